/**
 * Options of {@link Morph.create}. Every field is optional; an omitted work coefficient or
 * tolerance takes the core's default (wasm/core/morph/morph.h), which are the paper's.
 */
export interface MorphOptions {
  /** c_s of the stretching work (eq. 3). Default 1; the paper finds 0.01–16 gives the same blends. */
  stretching?: number;
  /** c_b of the bending work (eq. 4). Default 1. */
  bending?: number;
  /** c_k of the kinking work (eq. 5). Default 4. */
  kinking?: number;
  /** e_k, the exponent of the kinking work (eq. 5). Default 1 (the paper: 0.00001–10 work alike). */
  kinkExponent?: number;
  /**
   * c_t of the travel work (beyond the paper): the squared distance between corresponding points,
   * each in its drawing's normalized frame (centroid 0, RMS radius 1), times the length they span.
   * It keeps the correspondence from sliding along outlines made of many similar segments.
   * Default 1; 0 gives the paper's model, in which a rotated copy costs no work.
   */
  travel?: number;
  /**
   * Longest segment before knots are inserted (§6), as a fraction of each contour's width
   * (its length / π, which a rotation does not change). Default 0.05; 0 turns the limit off.
   */
  segmentLimit?: number;
  /**
   * How far an anchor may sit off the line of its handles and still count as a C1 join (the paper's
   * TOL), as a fraction of the drawing's size. Default 1e-3.
   */
  continuityTolerance?: number;
  /**
   * The unit of length of the work terms, as a fraction of the mean total length of both keys'
   * contours: it balances stretching (grows with length) against bending (shrinks with it).
   * Default 0.01 (an outline 100 units long, the scale of the paper's 64-point glyphs).
   */
  lengthUnit?: number;
  /**
   * Which ways round the second key's contours are searched: 'winding' (default) traverses each
   * closed contour the way that gives it its partner's winding (open paths: both ways); 'both'
   * takes the least work over both directions (the work does not see orientation, so a reversed
   * match can win and turn the blend inside out); 'forward' as given.
   */
  direction?: MorphDirection;
  /** Pinned correspondences (the paper's anchor points): each holds its two points together. Default none. */
  pins?: readonly MorphPin[];
  /** How control points travel: 'linear' (§2) or 'intrinsic' (lengths and angles). Default 'linear'. */
  interpolation?: MorphInterpolation;
}

/** How in-betweens interpolate control points: straight lines, or edge lengths and turning angles. */
export type MorphInterpolation = 'linear' | 'intrinsic';

/** Every {@link MorphInterpolation}. */
export const MORPH_INTERPOLATIONS: readonly MorphInterpolation[] = ['linear', 'intrinsic'];

/** A pinned correspondence in document space: the point of key A nearest `a` meets the point of key B nearest `b`. */
export interface MorphPin {
  /** A point on (or near) the first key, [x, y]. */
  a: readonly [number, number];
  /** A point on (or near) the second key, [x, y]. */
  b: readonly [number, number];
}

/** Which directions of the second key's contours the correspondence search tries. */
export type MorphDirection = 'winding' | 'both' | 'forward';
