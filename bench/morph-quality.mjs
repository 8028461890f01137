// Validity of morph in-betweens, shared by the tests (tests/unit/morph-glyphs.test.ts) and the
// benchmark (bench/morph.mjs, which counts the same failures for flubber): contours as polylines,
// and the three failures the issue names — a contour that crosses itself, two contours that cross,
// a hole that leaves its outer contour or flips its winding.

/** Proper crossings between edges of polylines (closed rings), adjacent edges of one ring excepted. */
function crossingPairs(rings) {
  const edges = [];
  rings.forEach((r, k) => {
    const n = r.length / 2;
    for (let i = 0; i < n; i++) {
      const j = (i + 1) % n;
      const x0 = r[2 * i], y0 = r[2 * i + 1], x1 = r[2 * j], y1 = r[2 * j + 1];
      if (x0 === x1 && y0 === y1) continue;
      edges.push({ k, i, n, x0, y0, x1, y1, lo: Math.min(x0, x1), hi: Math.max(x0, x1) });
    }
  });
  edges.sort((a, b) => a.lo - b.lo);
  const orient = (ax, ay, bx, by, cx, cy) => (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  const out = [];
  for (let a = 0; a < edges.length; a++) {
    const e = edges[a];
    for (let b = a + 1; b < edges.length && edges[b].lo <= e.hi; b++) {
      const f = edges[b];
      if (e.k === f.k && (Math.abs(e.i - f.i) <= 1 || Math.abs(e.i - f.i) === e.n - 1)) continue;
      if (Math.max(e.y0, e.y1) < Math.min(f.y0, f.y1) || Math.max(f.y0, f.y1) < Math.min(e.y0, e.y1)) continue;
      const d1 = orient(e.x0, e.y0, e.x1, e.y1, f.x0, f.y0), d2 = orient(e.x0, e.y0, e.x1, e.y1, f.x1, f.y1);
      const d3 = orient(f.x0, f.y0, f.x1, f.y1, e.x0, e.y0), d4 = orient(f.x0, f.y0, f.x1, f.y1, e.x1, e.y1);
      if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) out.push([e.k, f.k]);
    }
  }
  return out;
}

/** Twice the signed area of a ring. */
export function signedArea2(r) {
  let a = 0;
  const n = r.length / 2;
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    a += r[2 * i] * r[2 * j + 1] - r[2 * j] * r[2 * i + 1];
  }
  return a;
}

/** Whether (x, y) is inside ring r (even-odd). */
export function inside(r, x, y) {
  let c = false;
  const n = r.length / 2;
  for (let i = 0, j = n - 1; i < n; j = i++) {
    const yi = r[2 * i + 1], yj = r[2 * j + 1];
    if (yi > y !== yj > y && x < ((r[2 * j] - r[2 * i]) * (y - yi)) / (yj - yi) + r[2 * i]) c = !c;
  }
  return c;
}

/** Closed Bézier contours (flat control points, 3n per contour) as rings of `per` points per segment. */
export function bezierRings(points, starts, counts, per = 8) {
  const rings = [];
  for (let c = 0; c < starts.length; c++) {
    const s = starts[c], n = counts[c] / 3, ring = [];
    for (let k = 0; k < n; k++) {
      const p = (i) => {
        const q = s + ((3 * k + i) % counts[c]);
        return [points[2 * q], points[2 * q + 1]];
      };
      const [p0, p1, p2, p3] = [p(0), p(1), p(2), p(3)];
      for (let i = 0; i < per; i++) {
        const t = i / per, u = 1 - t;
        const b0 = u * u * u, b1 = 3 * u * u * t, b2 = 3 * u * t * t, b3 = t * t * t;
        ring.push(b0 * p0[0] + b1 * p1[0] + b2 * p2[0] + b3 * p3[0], b0 * p0[1] + b1 * p1[1] + b2 * p2[1] + b3 * p3[1]);
      }
    }
    rings.push(ring);
  }
  return rings;
}

/**
 * The nesting to keep: for each ring of a key, the ring it lies in (or -1), from its first point.
 * `rings` are the key's contours in output order.
 */
export function parents(rings) {
  return rings.map((r, i) => {
    let best = -1, area = Infinity;
    rings.forEach((o, j) => {
      if (j === i || o.length < 6) return;
      if (inside(o, r[0], r[1]) && Math.abs(signedArea2(o)) < area) {
        area = Math.abs(signedArea2(o));
        best = j;
      }
    });
    return best;
  });
}

/**
 * Failures of one in-between: rings that cross themselves, pairs of rings that cross each other,
 * holes (rings with a parent in `nesting`) whose first point left the parent or whose winding
 * differs from `winding[i]` (+1 / −1 for a hole, 0 for rings that are not holes).
 */
export function frameFailures(rings, nesting, winding) {
  const self = new Set(), cross = new Set();
  for (const [a, b] of crossingPairs(rings)) {
    if (a === b) self.add(a);
    else cross.add(`${Math.min(a, b)}-${Math.max(a, b)}`);
  }
  let holeOut = 0, holeFlip = 0;
  nesting.forEach((p, i) => {
    if (p < 0 || rings[i].length < 6 || rings[p].length < 6) return;
    if (!inside(rings[p], rings[i][0], rings[i][1])) holeOut++;
    if (Math.sign(signedArea2(rings[i])) !== winding[i]) holeFlip++;
  });
  return { self: self.size, cross: cross.size, holeOut, holeFlip, any: self.size + cross.size + holeOut + holeFlip > 0 };
}
