// The package's affine module (src/core/affine.ts) against the transformation-matrix library
// (which SVG import uses for transform lists) as an independent implementation, and against
// closed forms: a rotation about c keeps c and turns by θ, a scaling about c keeps c.
import { applyToPoint, compose, inverse, rotate, scale, translate } from 'transformation-matrix';
import { describe, expect, test } from 'vitest';
import { affine, IDENTITY_MATRIX, type AffineMatrix } from '../../src/index.js';
import { IDENTITY } from '../../src/svg/matrix.js';
import { mulberry32 as random } from '../../src/core/random.js';

const rnd = random(7);
const randomMatrix = (): AffineMatrix => [0, 0, 0, 0, 0, 0].map(() => 4 * rnd() - 2) as unknown as AffineMatrix;
const near = (m: AffineMatrix, n: AffineMatrix, eps = 1e-12) => m.forEach((v, i) => expect(v).toBeCloseTo(n[i], -Math.log10(eps)));

describe('affine', () => {
  test('one identity: the tuple, its object form and every test of it agree', () => {
    expect([...IDENTITY_MATRIX]).toEqual([1, 0, 0, 1, 0, 0]);
    expect(IDENTITY).toEqual({ a: 1, b: 0, c: 0, d: 1, e: 0, f: 0 });
    expect(affine.fromMatrix(IDENTITY)).toEqual([...IDENTITY_MATRIX]);
    expect(affine.isIdentity(IDENTITY_MATRIX)).toBe(true);
    expect(affine.isIdentity([1, 0, 0, 1, 0, 1e-9])).toBe(false);
    expect(Object.isFrozen(IDENTITY_MATRIX)).toBe(true);
  });

  test('multiply and apply agree with transformation-matrix on random matrices', () => {
    for (let k = 0; k < 20; k++) {
      const m = randomMatrix(), n = randomMatrix();
      const theirs = compose(affine.toMatrix(m), affine.toMatrix(n));
      near(affine.multiply(m, n), affine.fromMatrix(theirs));
      const [x, y] = [10 * rnd() - 5, 10 * rnd() - 5];
      const p = applyToPoint(affine.toMatrix(m), { x, y });
      const q = affine.apply(m, x, y);
      expect(q[0]).toBeCloseTo(p.x, 12);
      expect(q[1]).toBeCloseTo(p.y, 12);
      // (m·n)(p) = m(n(p)): first n, then m.
      const mn = affine.apply(affine.multiply(m, n), x, y);
      const seq = affine.apply(m, ...affine.apply(n, x, y));
      expect(mn[0]).toBeCloseTo(seq[0], 12);
      expect(mn[1]).toBeCloseTo(seq[1], 12);
      expect(affine.fromMatrix(affine.toMatrix(m))).toEqual([...m]);
    }
  });

  test('rotation and scaling about a point keep the point and match the library', () => {
    const [cx, cy, theta, k] = [3, -2, 0.7, 1.8];
    const r = affine.rotationAbout(theta, cx, cy);
    expect(affine.apply(r, cx, cy)[0]).toBeCloseTo(cx, 12);
    expect(affine.apply(r, cx, cy)[1]).toBeCloseTo(cy, 12);
    near(r, affine.fromMatrix(rotate(theta, cx, cy)));
    expect(affine.angleOf(r)).toBeCloseTo(theta, 12);
    expect(affine.scaleOf(r)).toBeCloseTo(1, 12);
    const s = affine.scalingAbout(k, cx, cy);
    near(s, affine.fromMatrix(scale(k, k, cx, cy)));
    expect(affine.scaleOf(s)).toBeCloseTo(k, 12);
    expect(affine.angleOf(s)).toBe(0);
    near(affine.translation(4, 5), affine.fromMatrix(translate(4, 5)));
    // The polar angle of a rotation composed with a scaling is the rotation's.
    expect(affine.angleOf(affine.multiply(r, s))).toBeCloseTo(theta, 12);
  });

  test('invert: m·m⁻¹ = identity, and the library agrees; null for a singular matrix', () => {
    for (let k = 0; k < 20; k++) {
      const m = randomMatrix();
      const inv = affine.invert(m)!;
      near(affine.multiply(m, inv), IDENTITY_MATRIX, 1e-9);
      near(affine.multiply(inv, m), IDENTITY_MATRIX, 1e-9);
      near(inv, affine.fromMatrix(inverse(affine.toMatrix(m))), 1e-9);
    }
    expect(affine.invert([1, 2, 2, 4, 5, 6])).toBeNull();
    expect(affine.invert([0, 0, 0, 0, 1, 1])).toBeNull();
  });

  test('sameMatrix and isFiniteMatrix', () => {
    expect(affine.sameMatrix([1, 2, 3, 4, 5, 6], [1, 2, 3, 4, 5, 6 + 1e-9])).toBe(false);
    expect(affine.sameMatrix([1, 2, 3, 4, 5, 6], [1, 2, 3, 4, 5, 6 + 1e-9], 1e-8)).toBe(true);
    expect(affine.isFiniteMatrix([1, 0, 0, 1, 0, 0])).toBe(true);
    expect(affine.isFiniteMatrix([1, 0, 0, 1, 0])).toBe(false);
    expect(affine.isFiniteMatrix([1, 0, 0, 1, 0, NaN])).toBe(false);
    expect(affine.isFiniteMatrix('1 0 0 1 0 0')).toBe(false);
  });
});
