// The number formatters path data is written with: fixedFormatter must write the same numbers as
// rounding through a float and String() (the live view's former formatter), only faster.
import fc from 'fast-check';
import { expect, test } from 'vitest';
import { fixedFormatter, formatNumber } from '../../src/index.js';

test('fixedFormatter writes the number String(round(v·10^d)/10^d) writes, in shortest form', () => {
  fc.assert(
    fc.property(fc.integer({ min: 0, max: 9 }), fc.double({ min: -1e6, max: 1e6, noNaN: true }), (decimals, v) => {
      const q = 10 ** decimals;
      const s = fixedFormatter(decimals)(v);
      expect(Number(s)).toBe(Math.round(v * q) / q + 0); // + 0: -0 reads back as 0
      expect(s).toMatch(/^-?\d+(\.\d*[1-9])?$/); // no trailing zeros, no exponent, no "-0"
    }),
    { numRuns: 5000, seed: 7 },
  );
});

test('fixedFormatter on hand-picked values', () => {
  const f4 = fixedFormatter(4);
  expect(['0', '-0.00004', '0.00005', '-12.5', '1e-7', '123.456789', '0.0001', '-0.1']
    .map((v) => f4(Number(v)))).toEqual(['0', '0', '0.0001', '-12.5', '0', '123.4568', '0.0001', '-0.1']);
  expect(fixedFormatter(0)(2.5)).toBe('3');
  expect(fixedFormatter(2)(-1.005)).toBe(String(Math.round(-1.005 * 100) / 100));
  // Too large to round as an integer: written as it is, never wrong.
  expect(Number(fixedFormatter(9)(1e12 + 0.5))).toBe(1e12 + 0.5);
  expect(fixedFormatter(3)(Infinity)).toBe('Infinity');
  expect(() => fixedFormatter(10)).toThrow(/0 to 9/);
});

test('formatNumber keeps 12 significant digits and never writes -0', () => {
  expect(formatNumber(-0)).toBe('0');
  expect(formatNumber(1 / 3)).toBe('0.333333333333');
  expect(formatNumber(123456.7890123456)).toBe('123456.789012');
});
