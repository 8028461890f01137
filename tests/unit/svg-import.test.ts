// SVG → splines, element by element, against hand-computed geometry; and splines → SVG.
import { beforeAll, describe, expect, test } from 'vitest';
import { init, parseSVG, segmentCount, segmentOf, type SvgDocument } from '../../src/index.js';
import { cubicAt, maxDistance } from './helpers.js';

const svg = (body: string, attrs = 'viewBox="0 0 100 100"') =>
  `<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" ${attrs}>${body}</svg>`;

const pts = (doc: SvgDocument, i = 0) => Array.from(doc.splines[i].points);

/** Anchors (every third point) of spline i. */
const anchors = (doc: SvgDocument, i = 0) => {
  const p = doc.splines[i].points, out: number[][] = [];
  for (let k = 0; k < p.length / 2; k += 3) out.push([p[2 * k], p[2 * k + 1]]);
  return out;
};

beforeAll(async () => {
  await init();
});

describe('path data', () => {
  test('lines become cubics with handles at thirds; H, V, relative forms and Z', () => {
    const doc = parseSVG(svg('<path d="M10 20 H40 V50 h-30 z"/>'));
    expect(doc.splines).toHaveLength(1);
    const s = doc.splines[0];
    expect(s.closed).toBe(true);
    expect(segmentCount(s)).toBe(4);
    expect(anchors(doc)).toEqual([[10, 20], [40, 20], [40, 50], [10, 50]]);
    expect(pts(doc).slice(0, 8)).toEqual([10, 20, 20, 20, 30, 20, 40, 20]);
    expect(s.continuity.map((t) => t.kind)).toEqual(['C0', 'C0', 'C0', 'C0']);
  });

  test('absolute and relative spellings give the same splines', () => {
    const a = parseSVG(svg('<path d="M10 10 C20 0 30 0 40 10 S60 20 70 10 Q80 0 90 10 T95 30 L50 50"/>'));
    const r = parseSVG(svg('<path d="m10 10 c10 -10 20 -10 30 0 s20 10 30 0 q10 -10 20 0 t5 20 l-45 20"/>'));
    expect(maxDistance(pts(a), pts(r))).toBeLessThan(1e-12);
  });

  test('S reflects the previous second control point; Q and T are degree-elevated exactly', () => {
    const doc = parseSVG(svg('<path d="M0 0 C10 0 20 10 30 10 S50 0 60 0 M0 50 Q10 30 20 50 T40 50"/>'));
    // S: first handle = reflection of (20,10) about (30,10) = (40,10).
    expect(pts(doc, 0).slice(6, 14)).toEqual([30, 10, 40, 10, 50, 0, 60, 0]);
    // Q (0,50)-(10,30)-(20,50): cubic handles at P0 + 2/3 (Q - P0) and P3 + 2/3 (Q - P3).
    const q = pts(doc, 1);
    expect(q[2]).toBeCloseTo(20 / 3, 12);
    expect(q[3]).toBeCloseTo(50 - 40 / 3, 12);
    expect(q[4]).toBeCloseTo(40 / 3, 12);
    // The quadratic's own midpoint (t = 1/2) is (10, 40): the cubic passes through it.
    const mid = cubicAt(segmentOf(doc.splines[1], 0), 0.5);
    expect(mid[0]).toBeCloseTo(10, 12);
    expect(mid[1]).toBeCloseTo(40, 12);
    // T reflects the control point (10,30) about (20,50) → (30,70); its midpoint is (30,60).
    const mid2 = cubicAt(segmentOf(doc.splines[1], 1), 0.5);
    expect(mid2[0]).toBeCloseTo(30, 12);
    expect(mid2[1]).toBeCloseTo(60, 12);
    expect(doc.splines[1].continuity[0].kind).toBe('C1'); // T is smooth by construction
  });

  test('elliptical arcs become cubics of at most 90° that stay on the ellipse (within 1e-4 of the size)', () => {
    // Rotated ellipse rx=40 ry=20 rotated 30°, large arc: more than 180° of sweep.
    const doc = parseSVG(svg('<path d="M20 50 A40 20 30 1 1 70 60"/>', 'viewBox="0 0 200 200"'));
    const s = doc.splines[0];
    const n = segmentCount(s);
    expect(n).toBeGreaterThanOrEqual(3);
    // Endpoints exact.
    expect(Array.from(s.points.slice(0, 2))).toEqual([20, 50]);
    expect(s.points[s.points.length - 2]).toBeCloseTo(70, 9);
    expect(s.points[s.points.length - 1]).toBeCloseTo(60, 9);
    // Recover the centre from the first anchor and check every sample on the implicit ellipse.
    const phi = (30 * Math.PI) / 180, cos = Math.cos(phi), sin = Math.sin(phi);
    // Centre per SVG F.6.5, computed independently here.
    const x1 = 20, y1 = 50, x2 = 70, y2 = 60;
    const dx = (x1 - x2) / 2, dy = (y1 - y2) / 2;
    const x1p = cos * dx + sin * dy, y1p = -sin * dx + cos * dy;
    let rx = 40, ry = 20;
    const lambda = (x1p * x1p) / (rx * rx) + (y1p * y1p) / (ry * ry);
    if (lambda > 1) { rx *= Math.sqrt(lambda); ry *= Math.sqrt(lambda); }
    const num = rx * rx * ry * ry - rx * rx * y1p * y1p - ry * ry * x1p * x1p;
    const coef = -Math.sqrt(Math.max(0, num / (rx * rx * y1p * y1p + ry * ry * x1p * x1p))); // fa == fs → minus
    const cxp = (coef * rx * y1p) / ry, cyp = (-coef * ry * x1p) / rx;
    const cx = cos * cxp - sin * cyp + (x1 + x2) / 2, cy = sin * cxp + cos * cyp + (y1 + y2) / 2;
    let worst = 0;
    for (let k = 0; k < n; k++) {
      const seg = segmentOf(s, k);
      for (let i = 0; i <= 50; i++) {
        const [x, y] = cubicAt(seg, i / 50);
        const u = cos * (x - cx) + sin * (y - cy), v = -sin * (x - cx) + cos * (y - cy);
        // Distance to the ellipse ≈ |F| / |∇F| for F = (u/rx)² + (v/ry)² − 1.
        const F = (u * u) / (rx * rx) + (v * v) / (ry * ry) - 1;
        const grad = 2 * Math.hypot(u / (rx * rx), v / (ry * ry));
        worst = Math.max(worst, Math.abs(F) / grad);
      }
      // Each piece sweeps at most 90°: its chord is at most rx·√2 (the longer radius's quarter).
      expect(Math.hypot(seg[6] - seg[0], seg[7] - seg[1])).toBeLessThanOrEqual(rx * Math.SQRT2 + 1e-9);
    }
    expect(worst / doc.size).toBeLessThan(1e-4);
    expect(s.continuity.every((t) => t.kind === 'C1' || t.kind === 'G1')).toBe(true);
  });

  test('a lone moveto is a one-point spline; subpaths split into splines', () => {
    const doc = parseSVG(svg('<path d="M5 5 M10 10 L20 10 L20 20 Z L30 30"/>'));
    expect(doc.splines.map((s) => [s.closed, s.points.length / 2])).toEqual([[false, 1], [true, 9], [false, 4]]);
    // After Z the next subpath starts at the closed subpath's start.
    expect(Array.from(doc.splines[2].points.slice(0, 2))).toEqual([10, 10]);
    expect(doc.shapes[0].splineCount).toBe(3);
  });
});

describe('basic shapes', () => {
  test('rect, rounded rect, circle, ellipse, line, polyline, polygon', () => {
    const doc = parseSVG(svg(`
      <rect x="10" y="10" width="30" height="20"/>
      <rect x="0" y="0" width="40" height="20" rx="5"/>
      <circle cx="50" cy="50" r="10"/>
      <ellipse cx="50" cy="50" rx="20" ry="10"/>
      <line x1="0" y1="0" x2="30" y2="40"/>
      <polyline points="0,0 10,0 10,10"/>
      <polygon points="0 0 10 0 10 10"/>`));
    expect(doc.shapes.map((s) => s.tag)).toEqual(['rect', 'rect', 'circle', 'ellipse', 'line', 'polyline', 'polygon']);
    const [rect, rounded, circle, ellipse, line, polyline, polygon] = doc.splines;
    expect(anchors(doc, 0)).toEqual([[10, 10], [40, 10], [40, 30], [10, 30]]);
    expect(rect.closed).toBe(true);
    expect(segmentCount(rounded)).toBe(8);
    expect(rounded.continuity.filter((t) => t.kind === 'C0')).toHaveLength(0); // lines meet quarter arcs tangentially
    expect(doc.splines.indexOf(circle)).toBe(2);
    expect(segmentCount(circle)).toBe(4);
    expect(circle.continuity.map((t) => t.kind)).toEqual(['C1', 'C1', 'C1', 'C1']);
    for (let k = 0; k < 4; k++) {
      for (let i = 0; i <= 20; i++) {
        const [x, y] = cubicAt(segmentOf(circle, k), i / 20);
        expect(Math.abs(Math.hypot(x - 50, y - 50) - 10)).toBeLessThan(2.8e-3);
      }
    }
    const b = doc.bounds!;
    expect(b[0]).toBe(0);
    expect(b[2]).toBeCloseTo(70, 12); // ellipse reaches x = 70
    // A lone 2:1 ellipse: the classic four quarters would stray by 1.05e-4 of its size, so the
    // importer uses eight pieces; every sample lies on the ellipse within 1e-4 of its size.
    expect(segmentCount(ellipse)).toBe(8);
    for (let k = 0; k < 8; k++) {
      for (let i = 0; i <= 20; i++) {
        const [x, y] = cubicAt(segmentOf(ellipse, k), i / 20);
        const u = (x - 50) / 20, v = (y - 50) / 10;
        const F = u * u + v * v - 1, grad = 2 * Math.hypot(u / 20, v / 10);
        expect(Math.abs(F) / grad).toBeLessThan(1e-4 * Math.hypot(40, 20));
      }
    }
    expect(Array.from(line.points)).toEqual([0, 0, 10, 40 / 3, 20, 80 / 3, 30, 40]);
    expect(polyline.closed).toBe(false);
    expect(segmentCount(polyline)).toBe(2);
    expect(polygon.closed).toBe(true);
    expect(segmentCount(polygon)).toBe(3);
  });

  test('a rect with zero width draws nothing; percentages resolve against the viewport', () => {
    const doc = parseSVG(svg('<rect width="0" height="5"/><rect x="10%" y="0" width="50%" height="10"/>', 'viewBox="0 0 200 100"'));
    expect(doc.shapes[0].splineCount).toBe(0);
    expect(anchors(doc, 0)[0]).toEqual([20, 0]);
    expect(anchors(doc, 0)[1]).toEqual([120, 0]);
  });
});

describe('structure', () => {
  test('nested group transforms map into document space', () => {
    const doc = parseSVG(svg('<g transform="translate(10 20)"><g transform="rotate(90) scale(2)"><path d="M1 0 L1 3"/></g></g>'));
    // rotate(90)·scale(2): (1,0) → (0,2), (1,3) → (-6,2); then +(10,20).
    expect(anchors(doc)[0][0]).toBeCloseTo(10, 12);
    expect(anchors(doc)[0][1]).toBeCloseTo(22, 12);
    expect(anchors(doc)[1][0]).toBeCloseTo(4, 12);
    expect(anchors(doc)[1][1]).toBeCloseTo(22, 12);
    const t = doc.shapes[0].transform;
    expect(t.a).toBeCloseTo(0, 12);
    expect(t.b).toBeCloseTo(2, 12);
  });

  test('transforms written with no separator between them (flag-icons, svgo) read as the spaced list', () => {
    const tight = parseSVG(svg('<g transform="translate(84.9)scale(.9375)rotate(30,1,2)"><path d="M1 0 L1 3"/></g>'));
    const spaced = parseSVG(svg('<g transform="translate(84.9) scale(.9375) rotate(30,1,2)"><path d="M1 0 L1 3"/></g>'));
    expect(tight.shapes[0].transform).toEqual(spaced.shapes[0].transform);
    expect(tight.shapes[0].transform.e).not.toBe(0);
  });

  test('use/defs instantiate referenced shapes at their offset, once per use', () => {
    const doc = parseSVG(svg(`<defs><path id="tri" d="M0 0 L10 0 L5 8 Z" fill="red"/></defs>
      <use xlink:href="#tri" x="20" y="30"/><use href="#tri" transform="translate(50 0)"/>`));
    expect(doc.shapes).toHaveLength(2);
    expect(anchors(doc, 0)[0]).toEqual([20, 30]);
    expect(anchors(doc, 1)[1]).toEqual([60, 0]);
    expect(doc.shapes[0].style.fill).toBe('red');
  });

  test('symbol with a viewBox is scaled to the use size', () => {
    const doc = parseSVG(svg(`<symbol id="s" viewBox="0 0 10 10"><rect width="10" height="10"/></symbol>
      <use href="#s" x="5" y="5" width="20" height="20"/>`));
    expect(anchors(doc)).toEqual([[5, 5], [25, 5], [25, 25], [5, 25]]);
  });

  test('switch draws its first child without required extensions; metadata is skipped silently', () => {
    const doc = parseSVG(svg(`<metadata><rdf:RDF xmlns:rdf="http://www.w3.org/1999/02/22-rdf-syntax-ns#"/></metadata>
      <switch><foreignObject requiredExtensions="http://example.com/ext" width="1" height="1"/>
      <g><path d="M0 0 L1 1"/></g><g><path d="M5 5 L6 6"/></g></switch>`));
    expect(doc.shapes).toHaveLength(1);
    expect(anchors(doc)[0]).toEqual([0, 0]);
    expect(doc.warnings).toEqual([]);
  });

  test('nested svg viewports apply x, y and viewBox', () => {
    const doc = parseSVG(svg('<svg x="10" y="10" width="20" height="20" viewBox="0 0 10 10"><path d="M0 0 L10 10"/></svg>'));
    expect(anchors(doc)).toEqual([[10, 10], [30, 30]]);
  });

  test('text and images are kept with a warning; width, height and viewBox are read', () => {
    const doc = parseSVG(svg('<text x="1" y="2">Hi</text><image href="a.png" width="5" height="5"/><text>again</text>', 'width="4in" height="300" viewBox="0 0 10 20"'));
    expect(doc.width).toBe(384);
    expect(doc.height).toBe(300);
    expect(doc.viewBox).toEqual([0, 0, 10, 20]);
    expect(doc.warnings.map((w) => [w.code, w.count])).toEqual([['kept:text', 2], ['kept:image', 1]]);
    expect(doc.warnings[0].message).toMatch(/2 <text> elements kept/);
    const out = doc.toSVG({ rewrite: 'all' });
    expect(out).toContain('>Hi</text>');
    expect(out).toContain('href="a.png"');
  });
});

describe('styles', () => {
  test('inheritance, style attribute, class rules, currentColor and opacity', () => {
    const doc = parseSVG(svg(`<style>.hot { fill: #f00 } path.cold { stroke: blue; stroke-width: 3 } #me { fill-rule: evenodd }</style>
      <g fill="green" stroke-width="2" opacity="0.5" color="purple">
        <path d="M0 0 L1 1"/>
        <path class="hot cold" id="me" style="opacity: 0.5" d="M0 0 L1 1"/>
        <rect class="cold" stroke="currentColor" width="1" height="1"/>
        <g display="none"><path d="M0 0 L1 1"/></g>
      </g>`));
    const [a, b, c, d] = doc.shapes.map((s) => s.style);
    expect(a).toMatchObject({ fill: 'green', stroke: 'none', strokeWidth: 2, opacity: 0.5, visible: true, fillRule: 'nonzero' });
    expect(b).toMatchObject({ fill: '#f00', stroke: 'blue', strokeWidth: 3, opacity: 0.25, fillRule: 'evenodd' });
    expect(c).toMatchObject({ fill: 'green', stroke: 'purple', strokeWidth: 2 }); // path.cold does not match a rect
    expect(d.visible).toBe(false);
  });

  test('gradient paint is reported and has a stand-in color', () => {
    const doc = parseSVG(svg(`<defs><linearGradient id="g"><stop offset="0" stop-color="#111"/><stop offset="1" style="stop-color:#eee"/></linearGradient>
      <linearGradient id="h" xlink:href="#g"/></defs><rect fill="url(#h)" width="5" height="5"/>`));
    expect(doc.warnings.map((w) => w.code)).toEqual(['paint-server']);
    expect(doc.paintColor(doc.shapes[0].style.fill)).toBe('#111');
    expect(doc.paintColor('none')).toBeNull();
    expect(doc.paintColor('#abc')).toBe('#abc');
  });
});

describe('export', () => {
  test('unchanged documents keep their markup; rewrite "all" turns shapes into equivalent paths', () => {
    const text = svg('<g transform="translate(5 5) rotate(20)"><rect id="r" class="k" x="1" y="2" width="10" height="4" rx="1" fill="#123"/><circle cx="3" cy="3" r="2"/></g>');
    const doc = parseSVG(text);
    const same = doc.toSVG();
    expect(same).toContain('<rect id="r" class="k" x="1" y="2" width="10" height="4" rx="1" fill="#123"/>');
    const all = doc.toSVG({ rewrite: 'all' });
    expect(all).not.toContain('<rect');
    expect(all).toMatch(/<path id="r" class="k" fill="#123" d="M/);
    expect(all).toContain('transform="translate(5 5) rotate(20)"'); // groups are untouched
    const again = parseSVG(all);
    expect(again.splines).toHaveLength(doc.splines.length);
    doc.splines.forEach((s, i) => expect(maxDistance(s.points, again.splines[i].points)).toBeLessThan(1e-9));
  });

  test('edited geometry is written back into the element space; other shapes stay as they were', () => {
    const doc = parseSVG(svg('<g transform="scale(2)"><path id="p" d="M0 0 L10 0"/><path id="q" d="M0 0 L0 10"/></g>'));
    const edited = doc.clone();
    edited.splines[0].points[6] = 30; // document-space end point x: 20 → 30
    expect(doc.splines[0].points[6]).toBe(20); // the clone is independent
    const out = edited.toSVG();
    expect(out).toContain('d="M0 0 L0 10"'); // untouched markup
    const back = parseSVG(out);
    expect(back.splines[0].points[6]).toBeCloseTo(30, 12);
    expect(out).toMatch(/id="p" d="M0 0C3\.33333333333 0 6\.66666666667 0 15 0"/);
  });

  test('an edited use instance is expanded in place; the other instance still uses the definition', () => {
    const doc = parseSVG(svg(`<defs><path id="tri" d="M0 0 L10 0 L5 8 Z"/></defs>
      <use id="u1" href="#tri" x="20" y="30" fill="blue"/><use id="u2" href="#tri" x="40"/>`));
    const edited = doc.clone();
    edited.splines[0].points[1] += 3; // move the first instance's first anchor down
    edited.splines[0].points[edited.splines[0].points.length - 1] += 0; // (closed: that anchor is shared)
    const out = edited.toSVG();
    expect(out).toContain('<use id="u2"');
    expect(out).not.toContain('<use id="u1"');
    expect(out).toMatch(/<g id="u1" fill="blue" transform="translate\(20 30\)"><path d="M0 3C/);
    const back = parseSVG(out);
    expect(back.shapes).toHaveLength(2);
    expect(maxDistance(back.splines[0].points, edited.splines[0].points)).toBeLessThan(1e-9);
    expect(maxDistance(back.splines[1].points, doc.splines[1].points)).toBe(0);
    expect(back.shapes[0].style.fill).toBe('blue');
  });
});

test('parsing releases everything it put in wasm memory', async () => {
  const { memory } = await import('../../src/index.js');
  const text = svg('<circle cx="5" cy="5" r="4"/><path d="M0 0 C1 2 3 4 5 6 S9 9 10 0"/>');
  parseSVG(text);
  const before = memory().used;
  for (let i = 0; i < 200; i++) parseSVG(text);
  expect(memory().used).toBe(before);
});
