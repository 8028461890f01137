// `npm run bench` section "Morph": Sederberg & Greenwood shape blending against flubber (the
// polygon morphing library people use), on the glyph pairs of ../shared/data/svg/morph.
//
// Speed: the correspondence (Morph.create) and one frame (Morph.at) of the paper's Fig. 7 pair and
// of a pair cut to ≥ 100 + 100 segments, medians after warm-up, with flubber's set-up and frame on
// the same pairs and their ratios; bytes the wasm heap grew over 1,000 frames.
// Quality: over every ordered pair of glyphs of one letter, the in-betweens at t = 0.1 … 0.9 that
// cross themselves, cross another contour, or lose a hole (bench/morph-quality.mjs, the same
// checks as tests/unit/morph-glyphs.test.ts), for ours (linear and intrinsic) and for flubber.
import { readdirSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { Morph, memory, parseSVG } from '../dist/index.js';
import { bezierRings, frameFailures, parents, signedArea2 } from './morph-quality.mjs';
import { time } from './stats.mjs';

const flubber = createRequire(import.meta.url)('flubber');



/** Path data of one spline (document space), for flubber. */
function contourD(s) {
  const p = s.points, n = p.length / 2, f = (i) => `${p[2 * (i % n)]} ${p[2 * (i % n) + 1]}`;
  let d = `M${f(0)}`;
  const segs = s.closed ? n / 3 : (n - 1) / 3;
  for (let k = 0; k < segs; k++) d += `C${f(3 * k + 1)} ${f(3 * k + 2)} ${f(3 * k + 3)}`;
  return `${d}Z`;
}

function centroid(s) {
  let x = 0, y = 0;
  const n = s.points.length / 2;
  for (let i = 0; i < n; i++) {
    x += s.points[2 * i];
    y += s.points[2 * i + 1];
  }
  return [x / n, y / n];
}

/**
 * flubber as its users blend multi-contour shapes: contours paired in file order by
 * interpolateAll (default options), extra contours shrinking to / growing from a point at their
 * centroid (toCircle / fromCircle with radius 0). Returns t → rings (flat x,y arrays).
 */
function flubberBlend(a, b) {
  const da = a.splines.map(contourD), db = b.splines.map(contourD);
  const n = Math.min(da.length, db.length);
  const fns = flubber.interpolateAll(da.slice(0, n), db.slice(0, n), { string: false });
  for (let i = n; i < da.length; i++) fns.push(flubber.toCircle(da[i], ...centroid(a.splines[i]), 1e-6, { string: false }));
  for (let i = n; i < db.length; i++) fns.push(flubber.fromCircle(...centroid(b.splines[i]), 1e-6, db[i], { string: false }));
  return (t) => fns.map((fn) => fn(t).flat());
}

function failuresOf(ringsAt, exists) {
  const r0 = ringsAt(0), r1 = ringsAt(1);
  const p0 = parents(r0), p1 = parents(r1);
  const nesting = r0.map((_, i) => (exists(i) ? p0[i] : p1[i]));
  const winding = nesting.map((p, i) => (p < 0 ? 0 : Math.sign(signedArea2(exists(i) ? r0[i] : r1[i]))));
  let frames = 0;
  const kinds = { self: 0, cross: 0, holeOut: 0, holeFlip: 0 };
  for (let k = 1; k < 10; k++) {
    const f = frameFailures(ringsAt(k / 10), nesting, winding);
    if (f.any) frames++;
    for (const key of Object.keys(kinds)) kinds[key] += f[key];
  }
  return { frames, kinds };
}

export function morphBenchmarks(data) {
  const dir = join(data, 'svg/morph');
  const files = readdirSync(dir).filter((f) => f.endsWith('.svg')).sort();
  const docs = new Map(files.map((f) => [f, parseSVG(readFileSync(join(dir, f)), { name: f })]));

  // ---- speed ----
  const speed = [];
  const cases = [
    { name: 'Fig. 7: NimbusMonoPS-Bold_G → NimbusRoman-Bold_G', a: 'NimbusMonoPS-Bold_G.svg', b: 'NimbusRoman-Bold_G.svg', options: {} },
    { name: 'the same pair cut to ≥ 100 + 100 segments', a: 'NimbusMonoPS-Bold_G.svg', b: 'NimbusRoman-Bold_G.svg', options: { segmentLimit: 0.03 } },
    { name: 'LiberationSerif-Bold_ampersand → NimbusMonoPS-Bold_ampersand (3 → 2 contours)', a: 'LiberationSerif-Bold_ampersand.svg', b: 'NimbusMonoPS-Bold_ampersand.svg', options: {} },
  ];
  for (const c of cases) {
    const a = docs.get(c.a), b = docs.get(c.b);
    const probe = Morph.create(a, b, c.options);
    // Segments each key is cut into: matched anchors, a key's anchor counted once however many it meets.
    const keySegments = [0, 1].map((w) => {
      const pts = w === 0 ? probe.correspondence.a : probe.correspondence.b;
      let distinct = 0;
      for (let k = 0; k < pts.length; k += 2) if (k === 0 || pts[k] !== pts[k - 2] || pts[k + 1] !== pts[k - 1]) distinct++;
      return distinct;
    });
    probe.dispose();
    const correspondenceMs = time(() => Morph.create(a, b, c.options).dispose(), 15);
    const m = Morph.create(a, b, c.options);
    const frameMs = time(() => {
      for (let i = 0; i < 100; i++) m.at(i / 99);
    }, 30) / 100;
    m.at(0.5);
    const before = memory().used;
    for (let i = 0; i < 1000; i++) m.at(i / 999);
    const grew = memory().used - before;
    const cells = m.searchCells;
    m.dispose();
    const fb = () => flubberBlend(a, b);
    const flubberSetupMs = time(fb, 15);
    const blend = fb();
    const flubberFrameMs = time(() => {
      for (let i = 0; i < 100; i++) blend(i / 99);
    }, 30) / 100;
    speed.push({ pair: c.name, segments: keySegments, cells, correspondence_ms: correspondenceMs, frame_ms: frameMs, heap_bytes_grown_by_1000_frames: grew, flubber_setup_ms: flubberSetupMs, flubber_frame_ms: flubberFrameMs });
  }

  // ---- quality ----
  const letters = [...new Set(files.map((f) => f.replace(/\.svg$/, '').split('_').slice(1).join('_')))];
  const quality = { pairs: 0, ours: { pairs: 0, frames: 0 }, intrinsic: { pairs: 0, frames: 0 }, paper: { pairs: 0, frames: 0 }, paper_kinds: { self: 0, cross: 0, holeOut: 0, holeFlip: 0 }, flubber: { pairs: 0, frames: 0, kinds: { self: 0, cross: 0, holeOut: 0, holeFlip: 0 } }, ours_kinds: { self: 0, cross: 0, holeOut: 0, holeFlip: 0 }, intrinsic_kinds: { self: 0, cross: 0, holeOut: 0, holeFlip: 0 }, by_letter: {} };
  for (const letter of letters) {
    const fonts = files.filter((f) => f.endsWith(`_${letter}.svg`));
    const row = { pairs: 0, ours: 0, intrinsic: 0, paper: 0, flubber: 0 };
    for (const fa of fonts) {
      for (const fbn of fonts) {
        if (fa === fbn) continue;
        const a = docs.get(fa), b = docs.get(fbn);
        row.pairs++;
        for (const [key, options] of [['ours', {}], ['intrinsic', { interpolation: 'intrinsic' }], ['paper', { travel: 0 }]]) {
          const m = Morph.create(a, b, options);
          const r = failuresOf((t) => bezierRings(m.at(t).slice(), m.starts, m.counts), (i) => m.correspondence.contours[i].contourA >= 0);
          m.dispose();
          if (r.frames) {
            quality[key].pairs++;
            row[key]++;
          }
          quality[key].frames += r.frames;
          for (const k of Object.keys(r.kinds)) quality[`${key}_kinds`][k] += r.kinds[k];
        }
        const blend = flubberBlend(a, b);
        const rf = failuresOf(blend, (i) => i < a.splines.length);
        if (rf.frames) {
          quality.flubber.pairs++;
          row.flubber++;
        }
        quality.flubber.frames += rf.frames;
        for (const k of Object.keys(rf.kinds)) quality.flubber.kinds[k] += rf.kinds[k];
      }
    }
    quality.pairs += row.pairs;
    quality.by_letter[letter] = row;
  }
  return { speed, quality, flubber_version: createRequire(import.meta.url)('flubber/package.json').version };
}

const f = (x, d = 2) => (Number.isFinite(x) ? x.toFixed(d) : String(x));

export function morphSection(r, { date, machine, load }) {
  const speedRows = r.speed.map(
    (s) =>
      `| ${s.pair} | ${s.segments.join(' + ')} | ${f(s.correspondence_ms, 1)} | ${f(s.frame_ms, 4)} | ${s.heap_bytes_grown_by_1000_frames} | ${f(s.flubber_setup_ms, 1)} | ${f(s.flubber_frame_ms, 4)} | ${(s.correspondence_ms / s.flubber_setup_ms).toPrecision(2)} | ${(s.frame_ms / s.flubber_frame_ms).toPrecision(2)} |`,
  );
  const q = r.quality;
  const letterRows = Object.entries(q.by_letter).map(([l, row]) => `| ${l} | ${row.pairs} | ${row.ours} | ${row.intrinsic} | ${row.paper} | ${row.flubber} |`);
  const kinds = (k) => `${k.self} self-crossings, ${k.cross} contour crossings, ${k.holeOut} holes outside, ${k.holeFlip} flipped holes`;
  return `## Morph (Sederberg & Greenwood 1993) vs flubber ${r.flubber_version}

Measured ${date} by \`npm run bench\` (bench/morph.mjs; \`node bench/run.mjs --only=morph\` runs it alone). Machine: ${machine}${load ? ` (load average ${load}: a shared machine)` : ''}.
Medians after warm-up, wasm in Node. Ours: \`Morph.create\` (contours paired, every contour cut
into B-spline segments, the least-work correspondence over every start) and \`Morph.at\` (one
in-between: control points of every contour, cubic Bézier). flubber: \`interpolateAll\` on the
contours as path strings with its defaults (it flattens them to polygons), extra contours to/from
a point with \`toCircle\`/\`fromCircle\`; one frame = every contour's interpolator at t (points, no string).

| pair | segments (A + B) | correspondence ms | frame ms | heap growth, 1,000 frames (bytes) | flubber set-up ms | flubber frame ms | set-up / flubber | frame / flubber |
|---|---:|---:|---:|---:|---:|---:|---:|---:|
${speedRows.join('\n')}

Budgets (issue 15): correspondence of a 100 + 100-segment pair ≤ 10 ms (the paper: 3 s on an HP 730 for 84 + 45 curves),
one frame ≤ 0.1 ms with no allocation. The search covers every start of B (one direction per closed
contour, by winding) by divide and conquer over the starts, O(m n log n); the grid cells it relaxed
are in build/bench/results.json.

Validity of the in-betweens at t = 0.1, 0.2, …, 0.9 over every ordered pair of glyphs of one letter
(${q.pairs} pairs; the checks of tests/unit/morph-glyphs.test.ts: a contour crossing itself, two contours
crossing, a hole leaving its outer contour or flipping its winding). Pairs with at least one failing frame:

| letter | pairs | ours (linear) | ours (intrinsic) | the paper's work only (c_t = 0) | flubber |
|---|---:|---:|---:|---:|---:|
${letterRows.join('\n')}
| **all** | **${q.pairs}** | **${q.ours.pairs}** | **${q.intrinsic.pairs}** | **${q.paper.pairs}** | **${q.flubber.pairs}** |

Failing frames of ${9 * q.pairs}: ours ${q.ours.frames} (${kinds(q.ours_kinds)}); intrinsic ${q.intrinsic.frames}
(${kinds(q.intrinsic_kinds)}); the paper's work alone ${q.paper.frames} (${kinds(q.paper_kinds)}); flubber ${q.flubber.frames}
(${kinds(q.flubber.kinds)}). Without the travel term (eq. 3–5 only) the correspondence slides along
outlines cut into many similar segments; flubber's failures are contours that cross while its
contours, paired in file order and flattened, travel on straight lines.
`;
}
