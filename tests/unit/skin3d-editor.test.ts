// The browser-free parts of the editor's 3D Skin mode (web/modes/skin3d): the handle pose model
// (translation/rotation/scale about the handle → the rig's 3×4 transforms), pose interpolation
// between keyframes, adding and removing handles on a posed, keyframed spec, the shared keyframe
// edits, the error colour ramp, and the sample cages shipped in public/samples/cages.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { Matrix4, Quaternion, Vector3 } from 'three';
import { beforeAll, describe, expect, test } from 'vitest';
import { SubdivisionRig, cageToOBJ, init, parseCage } from '../../src/index.js';
import { deleteKeyframe, keyframeAt, retimeKeyframe, setKeyframe } from '../../web/app/keyframes.js';
import { KeyframeControl, type KeyedSession } from '../../web/modes/skin/keyframe-control.js';
import { niceCeil, rampColor, rampColors } from '../../web/modes/skin3d/colormap.js';
import { spec3DFromJSON, spec3DToJSON } from '../../web/modes/skin3d/storage.js';
import {
  EMPTY_SPEC3D,
  REST_POSE,
  addHandle3D,
  followPose,
  interpolatePose,
  isRest,
  poseAt3D,
  poseMatrix,
  poseTransforms,
  removeHandle3D,
  samePoses,
  setHandlePose,
  type HandlePose,
  type Handle3D,
  type Skin3DSpec,
} from '../../web/modes/skin3d/spec.js';

beforeAll(async () => {
  await init();
});

const root = join(import.meta.dirname, '..', '..');

/** x' = A x + b for a 3×4 row-major matrix at `offset`. */
function apply(m: Float64Array, x: number[], offset = 0): number[] {
  return [0, 1, 2].map((r) => m[offset + 4 * r] * x[0] + m[offset + 4 * r + 1] * x[1] + m[offset + 4 * r + 2] * x[2] + m[offset + 4 * r + 3]);
}

/** A pose from an axis, an angle, a translation and scales. */
function pose(axis: number[], angle: number, t: number[], s: number[]): HandlePose {
  const q = new Quaternion().setFromAxisAngle(new Vector3(...axis).normalize(), angle);
  return { t: t as [number, number, number], q: [q.x, q.y, q.z, q.w], s: s as [number, number, number] };
}

const handle = (id: number, x: number, y: number, z: number): Handle3D => ({ id, x, y, z });

describe('poseMatrix', () => {
  test('agrees with three.js: T(c + t) · compose(R, S) · T(−c), applied to points', () => {
    const h = handle(0, 0.3, -1.2, 2);
    const p = pose([1, 2, -0.5], 0.9, [0.5, -0.25, 1.5], [1.3, 0.7, 2]);
    const m = new Float64Array(12);
    poseMatrix(h, p, m);
    const three = new Matrix4()
      .makeTranslation(h.x + p.t[0], h.y + p.t[1], h.z + p.t[2])
      .multiply(new Matrix4().compose(new Vector3(), new Quaternion(...p.q), new Vector3(...p.s)))
      .multiply(new Matrix4().makeTranslation(-h.x, -h.y, -h.z));
    for (const x of [[0, 0, 0], [1, 2, 3], [-4, 0.5, 7], [h.x, h.y, h.z]]) {
      const ours = apply(m, x), theirs = new Vector3(...x).applyMatrix4(three);
      expect(ours[0]).toBeCloseTo(theirs.x, 12);
      expect(ours[1]).toBeCloseTo(theirs.y, 12);
      expect(ours[2]).toBeCloseTo(theirs.z, 12);
    }
    // The handle's own rest position goes to rest + t whatever the rotation and scale.
    const own = apply(m, [h.x, h.y, h.z]);
    [h.x + 0.5, h.y - 0.25, h.z + 1.5].forEach((v, k) => expect(own[k]).toBeCloseTo(v, 12));
  });

  test('the rest pose is the identity [I | 0] exactly; poseTransforms writes 12 numbers per handle', () => {
    const handles = [handle(0, 1, 2, 3), handle(1, -1, 0, 4)];
    const m = poseTransforms(handles, [REST_POSE, pose([0, 0, 1], Math.PI / 2, [1, 0, 0], [1, 1, 1])]);
    expect(m.length).toBe(24);
    expect([...m.subarray(0, 12)]).toEqual([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0]);
    // A quarter turn about z around (−1, 0, 4), then +x: (0, 0, 4) ↦ (−1, 1, 4) + (1, 0, 0).
    const moved = apply(m, [0, 0, 4], 12);
    expect(moved[0]).toBeCloseTo(0, 12);
    expect(moved[1]).toBeCloseTo(1, 12);
    expect(moved[2]).toBeCloseTo(4, 12);
    expect(isRest([REST_POSE, REST_POSE])).toBe(true);
    expect(isRest([pose([0, 0, 1], 0, [0, 0, 1e-12], [1, 1, 1])])).toBe(false);
  });
});

describe('followPose', () => {
  test('a handle elsewhere gets the same affine map of space', () => {
    const h = handle(0, 1, 1, 0);
    const p = pose([0, 1, 1], 1.1, [0.2, 0.3, -0.4], [1.5, 1, 0.5]);
    const c: [number, number, number] = [-2, 0.5, 3];
    const a = new Float64Array(12), b = new Float64Array(12);
    poseMatrix(h, p, a);
    poseMatrix(handle(1, ...c), followPose(h, p, c), b);
    for (let k = 0; k < 12; k++) expect(b[k]).toBeCloseTo(a[k], 12);
  });
});

describe('interpolatePose and poseAt3D', () => {
  const a = pose([0, 0, 1], 0, [0, 0, 0], [1, 1, 1]);
  const b = pose([0, 0, 1], Math.PI / 2, [2, -4, 6], [3, 1, 1]);

  test('halfway: translation and scale halfway, a quarter turn becomes an eighth (slerp, not a matrix blend)', () => {
    const m = interpolatePose(a, b, 0.5);
    expect(m.t).toEqual([1, -2, 3]);
    expect(m.s).toEqual([2, 1, 1]);
    const angle = 2 * Math.atan2(Math.hypot(m.q[0], m.q[1], m.q[2]), m.q[3]);
    expect(angle).toBeCloseTo(Math.PI / 4, 12);
    expect(Math.hypot(...m.q)).toBeCloseTo(1, 14);
    expect(samePoses([interpolatePose(a, b, 0)], [a])).toBe(true);
    expect(samePoses([interpolatePose(a, b, 1)], [b])).toBe(true);
  });

  test('takes the short way round (q and −q are the same rotation)', () => {
    const c = pose([0, 0, 1], 0.4, [0, 0, 0], [1, 1, 1]);
    const flipped: HandlePose = { ...c, q: [-c.q[0], -c.q[1], -c.q[2], -c.q[3]] };
    const m = interpolatePose(a, flipped, 0.5);
    const angle = 2 * Math.atan2(Math.hypot(m.q[0], m.q[1], m.q[2]), Math.abs(m.q[3]));
    expect(angle).toBeCloseTo(0.2, 12);
  });

  test('poseAt3D holds before the first and after the last keyframe, interpolates between', () => {
    const keys = [
      { time: 0.5, transforms: [a] },
      { time: 1.5, transforms: [b] },
    ];
    expect(poseAt3D(keys, 0)[0]).toBe(a);
    expect(poseAt3D(keys, 9)[0]).toBe(b);
    expect(poseAt3D(keys, 1)[0].t).toEqual([1, -2, 3]);
    expect(poseAt3D([], 1)).toEqual([]);
  });
});

describe('handles and keyframes on a spec', () => {
  test('adding a handle to a posed, keyframed spec follows the nearest handle in the pose and in every key; removing it gives the poses back', () => {
    let spec = addHandle3D(EMPTY_SPEC3D, 0, [0, 0, 0]);
    spec = addHandle3D(spec, 1, [10, 0, 0]);
    expect(spec.pose).toEqual([REST_POSE, REST_POSE]);
    const turned = pose([0, 1, 0], 0.7, [0, 2, 0], [1, 1, 1]);
    spec = setHandlePose(spec, 1, turned);
    spec = setKeyframe(spec, 1);
    spec = setHandlePose(spec, 1, pose([0, 1, 0], -0.3, [1, 0, 0], [2, 2, 2]));
    spec = setKeyframe(spec, 0.25);
    expect(spec.keyframes.map((k) => k.time)).toEqual([0.25, 1]);
    const before = spec;
    // Nearest to (9, 1, 0) at rest is handle 1.
    spec = addHandle3D(spec, 7, [9, 1, 0]);
    expect(spec.handles.map((h) => h.id)).toEqual([0, 1, 7]);
    const check = (poses: readonly HandlePose[]) => {
      const m1 = new Float64Array(12), m7 = new Float64Array(12);
      poseMatrix(spec.handles[1], poses[1], m1);
      poseMatrix(spec.handles[2], poses[2], m7);
      for (let k = 0; k < 12; k++) expect(m7[k]).toBeCloseTo(m1[k], 12);
    };
    check(spec.pose);
    for (const k of spec.keyframes) check(k.transforms);
    const removed = removeHandle3D(spec, 7);
    expect(removed.pose).toEqual(before.pose);
    expect(removed.keyframes).toEqual(before.keyframes);
    // The last handle gone: keyframes of no handles are dropped.
    expect(removeHandle3D(removeHandle3D(removed, 0), 1).keyframes).toEqual([]);
  });

  test('keyframe edits: replace at the same time, find, delete, retime between neighbours', () => {
    let spec = addHandle3D(EMPTY_SPEC3D, 0, [0, 0, 0]);
    spec = setKeyframe(spec, 0);
    spec = setKeyframe(spec, 1);
    spec = setKeyframe(spec, 3);
    expect(spec.duration).toBe(3);
    const moved = setHandlePose(spec, 0, pose([1, 0, 0], 1, [0, 0, 0], [1, 1, 1]));
    const replaced = setKeyframe(moved, 1.0005);
    expect(replaced.keyframes.length).toBe(3);
    expect(replaced.keyframes[1].transforms[0]).toBe(moved.pose[0]);
    expect(keyframeAt(spec, 2.9995)).toBe(2);
    expect(keyframeAt(spec, 2)).toBe(-1);
    // Kept strictly between its neighbours.
    expect(retimeKeyframe(spec, 1, 5).keyframes[1].time).toBeCloseTo(3 - 0.002, 12);
    expect(deleteKeyframe(spec, 0).keyframes.map((k) => k.time)).toEqual([1, 3]);
  });
});

describe('KeyframeControl (the timeline edits both skin modes share)', () => {
  /** A session whose pose follows its keyframes when the playhead moves, and a host recording edits. */
  function setup() {
    let spec: Skin3DSpec = addHandle3D(EMPTY_SPEC3D, 0, [0, 0, 0]);
    const session: KeyedSession<Skin3DSpec> & { spec: Skin3DSpec; time: number } = {
      spec,
      time: 0,
      setTime(t) {
        this.time = Math.min(this.spec.duration, Math.max(0, t));
        if (this.spec.keyframes.length > 0) this.spec = { ...this.spec, pose: poseAt3D(this.spec.keyframes, this.time) };
      },
    };
    const labels: string[] = [];
    const control = new KeyframeControl<Skin3DSpec>({
      session: () => session,
      canKey: () => session.spec.handles.length > 0,
      busy: () => false,
      execute: (label, after) => {
        labels.push(label);
        session.spec = spec = after;
      },
      refresh: () => undefined,
      stopped: () => undefined,
    });
    return { session, control, labels };
  }

  test('keys the pose at the playhead, replaces it, jumps between keys, deletes, moves and lengthens', () => {
    const { session, control, labels } = setup();
    const up = pose([0, 0, 1], 0, [0, 1, 0], [1, 1, 1]);
    control.addKeyframe();
    control.seek(1.5, false);
    session.spec = setHandlePose(session.spec, 0, up);
    control.addKeyframe();
    control.addKeyframe();
    expect(labels).toEqual(['Add keyframe', 'Add keyframe', 'Replace keyframe']);
    expect(session.spec.keyframes.map((k) => k.time)).toEqual([0, 1.5]);
    control.runKey('previous-key');
    expect(session.time).toBe(0);
    expect(session.spec.pose[0].t).toEqual([0, 0, 0]);
    control.runKey('next-key');
    expect(session.time).toBe(1.5);
    expect(session.spec.pose[0].t).toEqual([0, 1, 0]);
    control.runKey('end');
    expect(session.time).toBe(2);
    control.moveKeyframe(1, 3); // past the end: the animation gets longer
    expect(session.spec.keyframes[1].time).toBe(3);
    expect(session.spec.duration).toBe(3);
    control.setDuration(1); // never shorter than the last keyframe
    expect(session.spec.duration).toBe(3);
    control.seek(3, false);
    control.deleteKeyframe();
    expect(session.spec.keyframes.map((k) => k.time)).toEqual([0]);
    expect(labels.at(-1)).toBe('Delete keyframe');
  });
});

describe('the autosaved spec (JSON)', () => {
  test('round-trips a posed, keyframed spec exactly, through JSON text', () => {
    let spec = addHandle3D(addHandle3D({ ...EMPTY_SPEC3D, weights: 'bbw', levels: 3 }, 4, [1, 2, 3]), 9, [-1, 0, 0.5]);
    spec = setHandlePose(spec, 1, pose([1, 1, 0], 0.4, [0.1, 0.2, 0.3], [1, 2, 1]));
    spec = setKeyframe(spec, 0.5);
    const back = spec3DFromJSON(JSON.parse(JSON.stringify(spec3DToJSON(spec))));
    expect(back).toEqual(spec);
  });

  test('names what is wrong in a bad one', () => {
    const good = spec3DToJSON(addHandle3D(EMPTY_SPEC3D, 0, [0, 0, 0]));
    expect(() => spec3DFromJSON({ ...good, version: 2 })).toThrow(/version 1/);
    expect(() => spec3DFromJSON({ ...good, handles: [{ id: 0, x: 0, y: Number.NaN, z: 0 }] })).toThrow(/finite/);
    expect(() => spec3DFromJSON({ ...good, handles: [good.handles[0], good.handles[0]], pose: [good.pose[0], good.pose[0]] })).toThrow(/unique/);
    expect(() => spec3DFromJSON({ ...good, pose: [] })).toThrow(/the pose needs 1 poses/);
    expect(() => spec3DFromJSON({ ...good, levels: 7 })).toThrow(/levels/);
    expect(() => spec3DFromJSON({ ...good, keyframes: [{ time: 1, transforms: good.pose }, { time: 0.5, transforms: good.pose }] })).toThrow(/increase/);
  });
});

describe('error colour ramp', () => {
  test('ends, clamping, and a readable scale top', () => {
    const out = new Float32Array(3);
    rampColor(0, out, 0);
    const low = [...out];
    rampColor(1, out, 0);
    const high = [...out];
    expect(low[2]).toBeGreaterThan(low[0]); // blue at zero
    expect(high[0]).toBeGreaterThan(high[2]); // red at the top
    rampColor(7, out, 0);
    expect([...out]).toEqual(high);
    rampColor(Number.NaN, out, 0);
    expect([...out]).toEqual(high);
    const many = rampColors([0, 2, 4], 4, new Float32Array(9));
    expect([...many.subarray(0, 3)]).toEqual(low);
    expect([...many.subarray(6, 9)]).toEqual(high);
    expect(niceCeil(0.0123)).toBeCloseTo(0.02, 15);
    expect(niceCeil(3)).toBe(5);
    expect(niceCeil(1)).toBe(1);
    expect(niceCeil(0.7)).toBeCloseTo(1, 15);
    expect(niceCeil(0)).toBe(0);
  });
});

describe('sample cages (public/samples/cages)', () => {
  test.each(['gingerbread.obj', 'bar.obj'])('%s: parseCage reads it, a rig subdivides and poses it, cageToOBJ writes it back', (file) => {
    const text = readFileSync(join(root, 'public/samples/cages', file), 'utf8');
    const cage = parseCage(text, file);
    const vertices = text.split('\n').filter((l) => l.startsWith('v ')).length;
    expect(cage.positions.length).toBe(3 * vertices);
    expect(cage.creases.length).toBe(text.split('\n').filter((l) => l.startsWith('t crease')).length);
    const rig = SubdivisionRig.create(cage, { handles: [0, 0, 0], levels: 2 });
    try {
      // One handle moved by t: every cage vertex (and the surface) moves by t.
      const posed = rig.pose([1, 0, 0, 0.5, 0, 1, 0, -1, 0, 0, 1, 2], 'fit').slice();
      for (let i = 0; i < posed.length; i++) expect(posed[i] - cage.positions[i]).toBeCloseTo([0.5, -1, 2][i % 3], 9);
      expect(rig.refinedTriangles.length % 3).toBe(0);
    } finally {
      rig.dispose();
    }
    const again = parseCage(cageToOBJ(cage), file);
    expect([...again.faceSizes]).toEqual([...cage.faceSizes]);
    expect(again.creases).toEqual(cage.creases);
  });

  const index = JSON.parse(readFileSync(join(root, 'public/samples/cages/index.json'), 'utf8')) as { cages: { file: string }[] };

  test.each(index.cages.map((c) => c.file))('%s is closed, manifold, outward-facing, with crease tags on its own edges', (file) => {
    const text = readFileSync(join(root, 'public/samples/cages', file), 'utf8');
    const v = text.split('\n').filter((l) => l.startsWith('v ')).map((l) => l.slice(2).split(' ').map(Number));
    const f = text.split('\n').filter((l) => l.startsWith('f ')).map((l) => l.slice(2).split(' ').map((i) => Number(i) - 1));
    const creases = text.split('\n').filter((l) => l.startsWith('t crease 2/1/0 ')).map((l) => l.split(' ').slice(3).map(Number));
    expect(text.startsWith('# ')).toBe(true);
    expect(text).toContain('our own work, CC0');
    // Every directed edge once, its reverse once: closed and consistently oriented.
    const directed = new Set<string>();
    for (const face of f) for (let k = 0; k < face.length; k++) directed.add(`${face[k]},${face[(k + 1) % face.length]}`);
    const count = f.reduce((n, face) => n + face.length, 0);
    expect(directed.size).toBe(count);
    for (const e of directed) expect(directed.has(e.split(',').reverse().join(','))).toBe(true);
    // Euler characteristic 2 (a sphere).
    expect(v.length - count / 2 + f.length).toBe(2);
    // Outward: positive signed volume.
    let volume = 0;
    for (const face of f) {
      for (let k = 1; k + 1 < face.length; k++) {
        const [a, b, c] = [v[face[0]], v[face[k]], v[face[k + 1]]];
        volume += new Vector3(...a).dot(new Vector3(...b).cross(new Vector3(...c))) / 6;
      }
    }
    expect(volume).toBeGreaterThan(0);
    expect(creases.length).toBeGreaterThan(0);
    for (const [a, b, s] of creases) {
      expect(directed.has(`${a},${b}`) || directed.has(`${b},${a}`)).toBe(true);
      expect(s).toBeGreaterThan(0);
    }
  });
});
