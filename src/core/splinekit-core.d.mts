// Hand-written declarations of the Emscripten module built from wasm/bindings/ (emscripten 3.1.6
// has no --emit-tsd). Keep in step with the EMSCRIPTEN_BINDINGS blocks.

/** An embind object: its C++ memory is freed by delete(). */
export interface EmbindObject {
  delete(): void;
  isDeleted(): boolean;
}

/** wasm/bindings/spline_bindings.cpp — SplineSetHandle. Status 0 = ok, else see error(). */
export interface SplineSetHandle extends EmbindObject {
  resize(splines: number, points: number): void;
  points(): Float64Array;
  starts(): Int32Array;
  counts(): Int32Array;
  closed(): Int32Array;
  validate(): number;
  error(): string;
  segmentCount(): number;
  junctionCount(): number;
  bounds(): number;
  classify(lengthTolerance: number, angleTolerance: number, ratioTolerance: number): number;
  sample(perSegment: number): number;
  segmentLengths(tolerance: number): number;
  resultF64(): Float64Array;
  resultI32(): Int32Array;
}

/** wasm/bindings/spline_bindings.cpp — BezierScratch: 16 doubles, the segment in [0,8). */
export interface BezierScratch extends EmbindObject {
  data(): Float64Array;
  derivative(t: number, order: number): void;
  split(t: number): void;
  arcLength(t0: number, t1: number, tolerance: number): number;
  bounds(): void;
}

/** wasm/bindings/skin_bindings.cpp — SkinRigHandle (see the flow comment there). */
export interface SkinRigHandle extends EmbindObject {
  resizeKinds(n: number): void;
  kinds(): Int32Array;
  setup(splines: SplineSetHandle, handleCount: number, samples: number): number;
  handles(): Float64Array;
  samplePoints(): Float64Array;
  controlPoints(): Float64Array;
  sampleWeights(): Float64Array;
  pointWeights(): Float64Array;
  pointGradients(): Float64Array;
  useShepard(power: number): void;
  precompute(): number;
  transforms(): Float64Array;
  update(): void;
  points(): Float64Array;
  baseline(method: number): Float64Array;
  relax(): number;
  relaxEnergies(): Float64Array;
  error(method: number): number;
  perCurveError(): Float64Array;
  constraintResidual(): number;
  curveCount(): number;
  constrainedCount(): number;
  totalLength(): number;
  errorMessage(): string;
}

/** wasm/bindings/skin3d_bindings.cpp — Skin3dRigHandle (see the flow comment there). */
export interface Skin3dRigHandle extends EmbindObject {
  resize(vertices: number, faceIndices: number, faces: number, creases: number): void;
  positionsIn(): Float64Array;
  faceSizesIn(): Int32Array;
  faceIndicesIn(): Int32Array;
  creaseEdgesIn(): Int32Array;
  creaseSharpnessIn(): Float64Array;
  resizeCorners(corners: number): void;
  cornerVerticesIn(): Int32Array;
  cornerSharpnessIn(): Float64Array;
  setup(levels: number, handleCount: number): number;
  refineCage(levels: number): number;
  refinedCagePositions(): Float64Array;
  refinedCageQuads(): Int32Array;
  refinedCageCreaseEdges(): Int32Array;
  refinedCageCreaseSharpness(): Float64Array;
  refinedCageCornerVertices(): Int32Array;
  refinedCageCornerSharpness(): Float64Array;
  handles(): Float64Array;
  useShepard(power: number): void;
  /** onHandle(solved, total) after each handle's solve. */
  bbw(level: number, maxIterations: number, multiplierTolerance: number, onHandle: ((solved: number, total: number) => void) | undefined): number;
  bbwLevel(maxVertices: number): number;
  refinedWeights(): Float64Array;
  cageWeights(): Float64Array;
  prolongateWeights(): void;
  restrictWeights(): void;
  precompute(): number;
  transforms(): Float64Array;
  update(): void;
  cage(): Float64Array;
  naive(): Float64Array;
  cageIn(): Float64Array;
  /** source: 0 the fit, 1 the naive cage, 2 cageIn(). */
  refine(source: number): Float64Array;
  /** source as refine(). */
  limit(source: number): Float64Array;
  target(): Float64Array;
  error(source: number): number;
  perVertexError(): Float64Array;
  restRefined(): Float64Array;
  refinedTriangles(): Int32Array;
  cageVertexCount(): number;
  refinedVertexCount(): number;
  memoryM(): number;
  memoryO(): number;
  errorMessage(): string;
}

/** What a shortest path or a traced curve cost: phase (i) searches and expanded graph nodes, phase (ii) strip faces, phase (iii) passes, kept flips and frozen vertices, chords traced and kept, faces their walks entered, faces the passes worked on, windows straightened on their own. */
export interface SurfaceWorkCounters {
  searches: number;
  visitedNodes: number;
  stripFaces: number;
  passes: number;
  flips: number;
  frozenVertices: number;
  chordsTried: number;
  chords: number;
  walkedFaces: number;
  passFaces: number;
  windows: number;
}

/** wasm/bindings/surface_bindings.cpp — SurfaceMeshHandle (see the flow comment there). */
export interface SurfaceMeshHandle extends EmbindObject {
  resizeMesh(vertices: number, faces: number): void;
  positionsIn(): Float64Array;
  trianglesIn(): Int32Array;
  /** Builds the mesh, and its solver unless deferSearch (then buildSearch() or the first call that needs it). */
  build(landmarks: number, deferSearch: boolean): number;
  buildSearch(): void;
  searchBuilt(): boolean;
  /** The landmarks the solver will get (before buildSearch; no effect after). */
  setLandmarks(landmarks: number): void;
  /** The coarse guide of long paths: resizeGuide(F), guideIn() gets 3 file vertex indices per face, buildGuide() (status; builds the solver first). */
  resizeGuide(faces: number): void;
  guideIn(): Int32Array;
  buildGuide(): number;
  /** Faces of the coarse guide's mesh (0 without one). */
  guideFaces(): number;
  /** The mesh report, {name: count} under the names of wasm/core/surface/mesh.h report_fields. */
  reportFields(): Record<string, number>;
  bytes(): number;
  scale(): number;
  /** Landmarks of the solver (0 below its minimum mesh size). */
  landmarkCount(): number;
  /** The file faces that repeat an earlier face (the core takes that face for them), ascending; a view valid until the next call. */
  duplicateFaces(): Int32Array;
  /** Milliseconds of the last build(): part 0 the mesh, 1 its solver (search graph, landmarks), 2 the coarse guide. */
  buildMilliseconds(part: number): number;
  resizePoints(n: number): void;
  pointsIn(): Float64Array;
  resizeXY(n: number): void;
  xyIn(): Float64Array;
  pointsOut(): Float64Array;
  xyzOut(): Float64Array;
  offsetsOut(): Int32Array;
  length(): number;
  milliseconds(): number;
  curveMilliseconds(curve: number): number;
  /** Work counters of curve `curve` of the last trace() (an empty object for another index). */
  curveCounters(curve: number): SurfaceWorkCounters & { searchedPaths?: number; seededPaths?: number };
  /** Work counters of the last shortestPath(). */
  pathCounters(): SurfaceWorkCounters;
  error(): string;
  shortestPath(): number;
  pathAt(t0: number, t1: number): number;
  straightest(dx: number, dy: number, dz: number, length: number): number;
  trace(curves: number, scheme: number, levels: number, adaptiveDegrees: number): number;
  evalCurve(t: number, scheme: number, levels: number, adaptiveDegrees: number): number;
  splitCurve(t: number, scheme: number, levels: number, adaptiveDegrees: number): number;
  moveAnchor(count: number, index: number, f: number, u: number, v: number): number;
  moveHandle(count: number, index: number, f: number, u: number, v: number, smooth: boolean): number;
  smoothAnchor(count: number, index: number): number;
  rotateScale(count: number, f: number, u: number, v: number, angle: number, scale: number): number;
  translateSpline(count: number, f0: number, u0: number, v0: number, f1: number, u1: number, v1: number): number;
  mapPoints(f: number, u: number, v: number, ux: number, uy: number, uz: number, rotation: number, scale: number): number;
}

/** wasm/bindings/morph_bindings.cpp — MorphHandle (see the flow comment there). Status 0 = ok, else see error(). */
export interface MorphHandle extends EmbindObject {
  resizePins(n: number): void;
  pins(): Float64Array;
  setup(a: SplineSetHandle, b: SplineSetHandle, stretching: number, bending: number, kinking: number, kinkExponent: number, segmentLimit: number, continuityTolerance: number, lengthUnit: number, travel: number, direction: number): number;
  evaluate(t: number, mode: number): number;
  points(): Float64Array;
  starts(): Int32Array;
  counts(): Int32Array;
  closed(): Int32Array;
  coupled(): Int32Array;
  contours(): Float64Array;
  contourCount(): number;
  pointCount(): number;
  work(): number;
  cells(): number;
  error(): string;
}

export interface SplinekitCoreModule {
  CatmullRomHandle: { new (): CatmullRomHandle };
  LocalEditHandle: { new (): LocalEditHandle };
  MorphHandle: { new (): MorphHandle };
  SurfaceMeshHandle: { new (): SurfaceMeshHandle };
  SkinRigHandle: { new (): SkinRigHandle };
  Skin3dRigHandle: { new (): Skin3dRigHandle };
  SplineSetHandle: { new (): SplineSetHandle };
  BezierScratch: { new (): BezierScratch };
  gramMatrix(): number[];
  /** wasm/bindings/core_bindings.cpp: bytes in use by malloc. */
  heapUsed(): number;
  SkinWeightsHandle: { new (): SkinWeightsHandle };
  HEAP8: Int8Array;
}

export interface SplinekitCoreOptions {
  wasmBinary?: ArrayBuffer | Uint8Array;
  locateFile?(path: string, prefix: string): string;
}

declare function createSplinekitCore(options?: SplinekitCoreOptions): Promise<SplinekitCoreModule>;
export default createSplinekitCore;

/**
 * wasm/bindings/skin_weights_bindings.cpp — SkinWeightsHandle: harmonic and bounded biharmonic
 * weights on a 2D triangle mesh, evaluated at points. Status 0 = ok, else see error().
 */
export interface SkinWeightsHandle extends EmbindObject {
  resize(vertices: number, triangles: number, handles: number): void;
  vertices(): Float64Array;
  triangles(): Int32Array;
  handles(): Int32Array;
  harmonic(): number;
  /** mass: 0 barycentric, 1 Voronoi. */
  bbw(maxIterations: number, boundTolerance: number, multiplierTolerance: number, partitionOfUnity: boolean, mass: number): number;
  error(): string;
  handleCount(): number;
  weights(): Float64Array;
  triangleGradients(): Float64Array;
  iterations(): Int32Array;
  converged(): boolean;
  pinned(): number;
  resizeQueries(points: number): void;
  queries(): Float64Array;
  weightsAt(): number;
  gradientsAt(): number;
  result(): Float64Array;
}

/** wasm/bindings/edit_bindings.cpp — CatmullRomHandle (see the flow comment there). Status 0 = ok, else see error(). */
export interface CatmullRomHandle extends EmbindObject {
  resizeInput(doubles: number): void;
  input(): Float64Array;
  set(count: number, closed: boolean, parameterization: number): number;
  capture(samples: number, stride: number, minSpacing: number, resample: boolean, parameterization: number): number;
  pressure(): Float64Array;
  time(): Float64Array;
  count(): number;
  closed(): boolean;
  parameterization(): number;
  segmentCount(): number;
  points(): Float64Array;
  resample(count: number): number;
  resampleRange(first: number, last: number, inner: number): number;
  newFirst(): number;
  newLast(): number;
  bezier(): number;
  bezierPoints(): Float64Array;
  bezierKinds(): Int32Array;
  bezierRatios(): Float64Array;
  out(): Float64Array;
  point(segment: number, u: number): number;
  normal(segment: number, u: number): number;
  segmentLength(segment: number): number;
  tangent(i: number): number;
  setTangent(i: number, x: number, y: number): number;
  clearTangent(i: number): number;
  tangentOverridden(i: number): boolean;
  applyEdit(edit: LocalEditHandle): number;
  error(): string;
}

/** wasm/bindings/edit_bindings.cpp — LocalEditHandle: one localized drag. Status 0 = ok, else see error(). */
export interface LocalEditHandle extends EmbindObject {
  /** falloff: 0 linear, 1 gaussian, 2 cosine. */
  begin(curve: CatmullRomHandle, center: number, left: number, right: number, falloff: number, alpha: number, sigma: number, normals: boolean): number;
  move(dx: number, dy: number): void;
  end(): void;
  active(): boolean;
  points(): Float64Array;
  indices(): Int32Array;
  weights(): Float64Array;
  distances(): Float64Array;
  left(): number;
  right(): number;
  error(): string;
}
