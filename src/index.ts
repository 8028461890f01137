/**
 * splinekit — keeps vector curves vector.
 *
 *   import { init, parseSVG } from 'splinekit';
 *   await init();
 *   const doc = parseSVG(svgText);
 *
 * Everything numeric runs in the C++/WebAssembly core; this package wraps it in small typed
 * classes and handles files (SVG in and out).
 */
export { init, memory } from './core/module.js';
export { SplinekitError, type SplinekitErrorCode } from './core/errors.js';
export {
  CONTINUITY_KINDS,
  anchorJunction,
  cloneSpline,
  junctionAnchor,
  junctionCount,
  segmentCount,
  segmentOf,
  type ContinuityKind,
  type ContinuityTag,
  type Spline,
} from './spline/spline.js';
export { SplineSet, DEFAULT_CONTINUITY, type ContinuityOptions } from './spline/spline-set.js';
export { Bezier } from './spline/bezier.js';
export { parseSVG, DEFAULT_MAX_BYTES, DEFAULT_MAX_DEPTH, DEFAULT_MAX_ELEMENTS, type ParseOptions } from './svg/import.js';
export { expandEntities, ENTITY_EXPANSION_FACTOR, type ExpandedText } from './svg/entities.js';
export {
  SHAPE_ATTRIBUTE,
  SvgDocument,
  type ExportOptions,
  type SplinesJSON,
  type SvgShape,
  type SvgDocumentTransfer,
  type SvgStats,
  type SvgWarning,
} from './svg/document.js';
export { formatNumber, fixedFormatter } from './svg/path-data.js';
export type { ResolvedStyle } from './svg/style.js';
export type { Matrix } from './svg/matrix.js';
export { IDENTITY_MATRIX, type AffineMatrix } from './core/affine.js';
/** 2D affine matrix functions (compose, apply, rotate or scale about a point, conversions): see src/core/affine.ts. */
export * as affine from './core/affine.js';
export {
  SkinRig,
  type SkinError,
  type SkinHandle,
  type SkinMethod,
  type SkinRigOptions,
  type PrecomputedWeights,
  type WeightQueries,
  type WeightSource,
} from './skin/rig.js';
export { SvgPuppet } from './skin/puppet.js';
export { buildDomain, type Domain, type DomainOptions } from './skin/domain.js';
export { SkinWeights, type BbwOptions, type DomainWeightKind, type WeightMesh } from './skin/weights.js';
export { computeDomainWeights, domainWeights, outlineSamples, type DomainWeightsInput } from './skin/auto-weights.js';
export { animatedSVG, interpolateMatrix, keyframesAt, poseAt, type AnimationOptions, type Keyframe } from './skin/animation.js';
export { parseCage, cageToOBJ, type Cage, type CageCorner, type CageCrease } from './skin3d/cage.js';
export {
  SubdivisionRig,
  refineCage,
  type Skin3dError,
  type Skin3dMethod,
  type SubdivisionRigOptions,
  type WeightSpec,
} from './skin3d/rig.js';
export {
  DEFAULT_LANDMARKS,
  GUIDED_LANDMARKS,
  SurfaceMesh,
  type GeodesicPath,
  type MeshBuildTimes,
  type MeshInfo,
  type SurfaceMeshOptions,
  type MeshPoint,
  type MeshPointLike,
} from './surface/mesh.js';
export { GUIDE_MIN_FACES, GUIDE_RATIO } from './surface/coarse-guide.js';
export { meshPointNormal, meshPointPosition, vertexNormals } from './surface/mesh-point.js';
export {
  parseMesh,
  meshFormatOf,
  meshFormatList,
  DEFAULT_MAX_MESH_BYTES,
  MESH_FILE_ACCEPT,
  MESH_FORMATS,
  type MeshArrays,
  type MeshFormat,
  type MeshParseOptions,
} from './surface/mesh-io.js';
export {
  SurfaceSpline,
  evalBezier,
  traceBezier,
  type SurfaceSplineJSON,
  type TracedCurve,
  type TraceCounters,
} from './surface/spline.js';
export { DEFAULT_TRACE_LEVELS, DEFAULT_TRACE_SCHEME, SURFACE_SCHEMES, type SurfaceScheme, type TraceOptions } from './surface/trace-options.js';
export { mapSplines, type SvgMapOptions } from './surface/svg-map.js';
export { randomMeshPoints } from './surface/sampling.js';
export {
  CatmullRom,
  DEFAULT_PARAMETERIZATION,
  PARAMETERIZATIONS,
  type CatmullRomJSON,
  type CatmullRomOptions,
  type Parameterization,
  type StrokeOptions,
  type StrokeSample,
} from './edit/catmull-rom.js';
export { LocalEdit, DEFAULT_EDIT_OPTIONS, FALLOFFS, type ActiveWindowInfo, type Falloff, type LocalEditOptions } from './edit/local-edit.js';
export { Morph, type MorphContour, type MorphCorrespondence, type MorphKey } from './morph/morph.js';
export { MORPH_INTERPOLATIONS, type MorphDirection, type MorphInterpolation, type MorphOptions, type MorphPin } from './morph/options.js';
export type { MorphAnimationOptions, MorphStyle } from './morph/svg-out.js';
