// Declarations of bench/morph-quality.mjs for the TypeScript tests that use it.
export function signedArea2(r: ArrayLike<number>): number;
export function inside(r: ArrayLike<number>, x: number, y: number): boolean;
export function bezierRings(points: ArrayLike<number>, starts: ArrayLike<number>, counts: ArrayLike<number>, per?: number): number[][];
export function parents(rings: ArrayLike<number>[]): number[];
export function frameFailures(
  rings: ArrayLike<number>[],
  nesting: number[],
  winding: number[],
): { self: number; cross: number; holeOut: number; holeFlip: number; any: boolean };
