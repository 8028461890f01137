// SkinRig through the TS API on real drawings: exactness, constraints, the baselines, relax,
// memory, and the DOM puppet.
import { DOMParser } from '@xmldom/xmldom';
import { beforeAll, describe, expect, test } from 'vitest';
import {
  SkinRig,
  SplinekitError,
  SvgPuppet,
  init,
  memory,
  parseSVG,
  type AffineMatrix,
  type SkinHandle,
  type SvgDocument,
} from '../../src/index.js';
import { maxDistance, readShared } from './helpers.js';

/** Handles at fractions of the drawing's bounds. */
function handlesFor(doc: SvgDocument, fractions: [number, number][]): SkinHandle[] {
  const [x0, y0, x1, y1] = doc.bounds!;
  return fractions.map(([fx, fy]) => ({ x: x0 + fx * (x1 - x0), y: y0 + fy * (y1 - y0) }));
}

/** Rotation by `deg` about (cx, cy), as an SVG matrix. */
function rotationAbout(deg: number, cx: number, cy: number): AffineMatrix {
  const a = (deg * Math.PI) / 180, c = Math.cos(a), s = Math.sin(a);
  return [c, s, -s, c, cx - (c * cx - s * cy), cy - (s * cx + c * cy)];
}

const ID: AffineMatrix = [1, 0, 0, 1, 0, 0];
const CORNERS: [number, number][] = [[0.2, 0.2], [0.8, 0.2], [0.2, 0.8], [0.8, 0.8]];

beforeAll(async () => {
  await init();
});

describe('SkinRig', () => {
  const doc = () => parseSVG(readShared('svg/characters/oc_ballerina.svg'));

  test('the identity pose returns the drawing unchanged', () => {
    const d = doc();
    const rig = SkinRig.create(d, { handles: handlesFor(d, CORNERS) });
    const all = Float64Array.from(d.splines.flatMap((s) => Array.from(s.points)));
    expect(maxDistance(rig.pose([ID, ID, ID, ID]), all)).toBeLessThan(1e-9 * d.size);
    expect(rig.error().total).toBeLessThan(1e-18 * d.size ** 2);
    expect(rig.toSVG()).toBe(d.toSVG()); // nothing moved, nothing rewritten
    rig.dispose();
  });

  test('one rotation for every handle rotates the drawing exactly', () => {
    const d = doc();
    const rig = SkinRig.create(d, { handles: handlesFor(d, CORNERS) });
    const R = rotationAbout(35, 50, 60);
    const X = rig.pose([R, R, R, R]);
    let k = 0, worst = 0;
    for (const s of d.splines) {
      for (let i = 0; i < s.points.length; i += 2, k += 2) {
        const x = s.points[i], y = s.points[i + 1];
        worst = Math.max(worst, Math.hypot(X[k] - (R[0] * x + R[2] * y + R[4]), X[k + 1] - (R[1] * x + R[3] * y + R[5])));
      }
    }
    expect(worst).toBeLessThan(1e-9 * d.size);
    rig.dispose();
  });

  test('a bent pose keeps every constraint and beats the naive baselines', () => {
    const d = doc();
    const handles = handlesFor(d, CORNERS);
    const rig = SkinRig.create(d, { handles });
    rig.pose([ID, ID, rotationAbout(40, handles[2].x, handles[2].y), rotationAbout(-30, handles[3].x, handles[3].y)]);
    expect(rig.constraintResidual()).toBeLessThan(1e-9 * d.size);
    const fit = rig.error('fit').rms;
    expect(fit).toBeGreaterThan(0);
    expect(fit).toBeLessThan(rig.error('naive').rms);
    expect(fit).toBeLessThan(rig.error('interpolated').rms);
    const per = rig.error('fit').perCurve;
    expect(per.length).toBe(rig.curveCount);
    expect(per.every((e) => e >= 0 && Number.isFinite(e))).toBe(true);
    // The naive baseline moves each control point by the deformation itself.
    const naive = rig.baseline('naive');
    expect(naive.length).toBe(2 * d.splines.reduce((n, s) => n + s.points.length / 2, 0));
    rig.dispose();
  });

  test('relax lowers the energy monotonically; unconstrained mode and overrides change the fit', () => {
    const d = doc();
    const handles = handlesFor(d, CORNERS);
    const pose = [ID, rotationAbout(25, handles[1].x, handles[1].y), ID, rotationAbout(-45, handles[3].x, handles[3].y)];
    const rig = SkinRig.create(d, { handles });
    rig.pose(pose);
    const rigid = rig.error().total;
    const r = rig.relax();
    for (let i = 1; i < r.energies.length; i++) expect(r.energies[i]).toBeLessThanOrEqual(r.energies[i - 1] * (1 + 1e-12));
    expect(rig.error().total).toBeLessThanOrEqual(rigid * (1 + 1e-12));
    expect(r.energies[0]).toBeCloseTo(rigid, 6);
    const free = SkinRig.create(d, { handles, unconstrained: true });
    free.pose(pose);
    expect(free.error().total).toBeLessThanOrEqual(rigid); // fewer constraints, lower optimum
    expect(free.constraintResidual()).toBe(0); // no constraint to measure
    rig.dispose();
    free.dispose();
  });

  test('bad input is refused with a clear error and leaves the rig as it was', () => {
    const d = doc();
    expect(() => SkinRig.create(d, { handles: [] })).toThrowError(/at least one handle/);
    expect(() => SkinRig.create(d, { handles: [{ x: NaN, y: 0 }] })).toThrowError(SplinekitError);
    expect(() => SkinRig.create(d, { handles: handlesFor(d, CORNERS), samples: 2 })).toThrowError(/samples/);
    const rig = SkinRig.create(d, { handles: handlesFor(d, CORNERS) });
    const before = rig.pose([ID, ID, ID, rotationAbout(10, 0, 0)]).slice();
    expect(() => rig.pose([ID, ID, ID, [1, 0, 0, NaN, 0, 0]])).toThrowError(/transform 3 has a non-finite/);
    expect(() => rig.pose([ID, ID])).toThrowError(/expected 4 transforms/);
    expect(rig.points()).toEqual(before);
    expect(rig.error().total).toBeGreaterThan(0); // the last good pose is still the current one
    rig.dispose();
    expect(() => rig.pose([ID, ID, ID, ID])).toThrowError(/after dispose/);
  });

  test('updates allocate nothing; create/dispose cycles leak nothing', () => {
    const d = parseSVG(readShared('svg/icons/fa_person_running.svg'));
    const handles = handlesFor(d, CORNERS);
    const rig = SkinRig.create(d, { handles });
    const flat = new Float64Array(24);
    const pose = (t: number) => {
      for (let i = 0; i < 4; i++) flat.set(rotationAbout(t * (i + 1), handles[i].x, handles[i].y), 6 * i);
      return rig.pose(flat);
    };
    pose(0);
    const before = memory();
    for (let i = 0; i < 1000; i++) pose(i * 0.05);
    expect(memory()).toEqual(before);
    rig.dispose();
    const used = memory().used;
    for (let i = 0; i < 50; i++) SkinRig.create(d, { handles, samples: 20 }).dispose();
    expect(memory().used).toBe(used);
  });
});

describe('SvgPuppet', () => {
  test('rewrites the paths of an inline svg on each pose', () => {
    const d = parseSVG(`<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
      <g transform="translate(10 0)"><rect id="body" x="10" y="10" width="30" height="60" fill="red"/></g>
      <circle cx="70" cy="30" r="10"/></svg>`);
    const handles = [{ x: 25, y: 10 }, { x: 25, y: 70 }, { x: 70, y: 30 }];
    const rig = SkinRig.create(d, { handles });
    const page = new DOMParser().parseFromString('<html xmlns="http://www.w3.org/1999/xhtml"><body><div id="stage"/></body></html>', 'text/xml');
    const stage = page.getElementsByTagName('div')[0] as unknown as Element;
    const puppet = SvgPuppet.mount(stage, d, rig);
    const paths = Array.from(stage.getElementsByTagName('path'));
    expect(paths.map((p) => p.getAttribute('data-splinekit-shape'))).toEqual(['0', '1']);
    expect(paths[0].getAttribute('fill')).toBe('red');
    const rest = paths[0].getAttribute('d');
    puppet.pose([ID, [1, 0, 0, 1, 15, 0], ID]);
    const moved = paths[0].getAttribute('d');
    expect(moved).not.toBe(rest);
    // The rect's path is in its group's space: parse it back and compare with the rig's points.
    const back = parseSVG(`<svg xmlns="http://www.w3.org/2000/svg"><g transform="translate(10 0)"><path d="${moved}"/></g></svg>`);
    expect(maxDistance(back.splines[0].points, rig.points().subarray(0, back.splines[0].points.length))).toBeLessThan(1e-6);
    rig.dispose();
  });
});

describe('animation', () => {
  test('matrix interpolation keeps rotations rotations and hits the ends', async () => {
    const { interpolateMatrix } = await import('../../src/index.js');
    const r90 = rotationAbout(90, 10, 0);
    const half = interpolateMatrix(ID, r90, 0.5);
    const c = Math.cos(Math.PI / 4), s = Math.sin(Math.PI / 4);
    expect(half[0]).toBeCloseTo(c, 12);
    expect(half[1]).toBeCloseTo(s, 12);
    expect(half[2]).toBeCloseTo(-s, 12);
    expect(half[3]).toBeCloseTo(c, 12); // a linear blend would give 0.5, 0.5: a shrunk matrix
    const end = interpolateMatrix([2, 0, 0, 3, 1, 1], r90, 1);
    end.forEach((v, k) => expect(v).toBeCloseTo(r90[k], 12));
    // The short way round: from +170° to −170° passes through 180°, not 0°.
    const mid = interpolateMatrix(rotationAbout(170, 0, 0), rotationAbout(-170, 0, 0), 0.5);
    expect(mid[0]).toBeCloseTo(-1, 12);
  });

  test('poseAt holds outside the keyframes and blends inside', async () => {
    const { poseAt } = await import('../../src/index.js');
    const keys = [{ time: 1, transforms: [ID] }, { time: 3, transforms: [[1, 0, 0, 1, 10, 0] as AffineMatrix] }];
    expect(poseAt(keys, 0)[0]).toEqual(ID);
    expect(poseAt(keys, 2)[0][4]).toBeCloseTo(5, 12);
    expect(poseAt(keys, 9)[0][4]).toBe(10);
  });

  test('an animated SVG animates every shape through frames that match the rig', async () => {
    const { animatedSVG, poseAt } = await import('../../src/index.js');
    const d = parseSVG(readShared('svg/characters/twemoji_1f419_octopus.svg'));
    const handles = handlesFor(d, CORNERS);
    const rig = SkinRig.create(d, { handles });
    const keys = [
      { time: 0, transforms: [ID, ID, ID, ID] },
      { time: 1, transforms: [ID, ID, rotationAbout(30, handles[2].x, handles[2].y), rotationAbout(-30, handles[3].x, handles[3].y)] },
      { time: 2, transforms: [ID, ID, ID, ID] },
    ];
    const svg = animatedSVG(rig, keys, { fps: 10 });
    const dom = new DOMParser().parseFromString(svg, 'image/svg+xml');
    const animates = Array.from(dom.getElementsByTagName('animate'));
    expect(animates).toHaveLength(d.shapes.length);
    const first = animates[0];
    expect(first.getAttribute('attributeName')).toBe('d');
    expect(first.getAttribute('dur')).toBe('2s');
    expect(first.getAttribute('repeatCount')).toBe('indefinite');
    const values = first.getAttribute('values')!.split(';');
    const keyTimes = first.getAttribute('keyTimes')!.split(';').map(Number);
    expect(values).toHaveLength(21);
    expect(keyTimes[0]).toBe(0);
    expect(keyTimes[20]).toBe(1);
    // Frame at t = 0.5 s is the rig's fit of the interpolated pose.
    const k = keyTimes.findIndex((t) => Math.abs(t - 0.25) < 1e-9);
    const X = rig.pose(poseAt(keys, 0.5)).slice();
    const shape = d.shapes[0];
    const back = parseSVG(`<svg xmlns="http://www.w3.org/2000/svg"><path d="${values[k]}"/></svg>`);
    const start = d.splines.slice(0, shape.firstSpline).reduce((n, s) => n + s.points.length, 0);
    expect(maxDistance(back.splines[0].points, X.subarray(start, start + back.splines[0].points.length))).toBeLessThan(1e-6 * d.size);
    // Every value has the same path structure (SMIL interpolates d only between alike paths).
    const structure = (v: string) => v.replace(/[^A-Za-z]/g, '');
    expect(new Set(values.map(structure)).size).toBe(1);
    rig.dispose();
  });
});
