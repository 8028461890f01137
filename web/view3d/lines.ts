import { Color, Group, type ColorRepresentation, type Vector2 } from 'three';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import { LineSegments2 } from 'three/examples/jsm/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/examples/jsm/lines/LineSegmentsGeometry.js';

/**
 * How far lines are drawn toward the camera, as a fraction of their depth (world units per unit
 * of distance): a pixel or two at any zoom, so a curve on the surface wins the depth test on
 * either side of the surface without floating visibly. Shared by every FatLine.
 */
export const TOWARD_CAMERA = { value: 0 };

/** Moves a line's camera-space ends toward the camera by TOWARD_CAMERA × their depth. */
function liftTowardCamera(material: LineMaterial): void {
  material.onBeforeCompile = (shader) => {
    shader.uniforms.towardCamera = TOWARD_CAMERA;
    shader.vertexShader = shader.vertexShader
      .replace('uniform float linewidth;', 'uniform float linewidth;\nuniform float towardCamera;')
      .replace(
        'vec4 end = modelViewMatrix * vec4( instanceEnd, 1.0 );',
        `vec4 end = modelViewMatrix * vec4( instanceEnd, 1.0 );
        start.xyz *= 1.0 - towardCamera;
        end.xyz *= 1.0 - towardCamera;`,
      );
  };
}

export interface FatLineOptions {
  color: ColorRepresentation;
  /** Width in CSS pixels. */
  width: number;
  /** Opacity of the parts hidden behind the mesh, drawn through it (0: not drawn). */
  xray?: number;
  /** Draw order (higher: later, on top among equals). */
  order?: number;
}

/**
 * Polylines with a width in screen pixels (three's Line2 family: instanced quads), depth-tested
 * against the mesh, optionally with an "x-ray" pass showing their hidden parts faintly.
 * Positions are Float32Array xyz; several polylines share one object (one draw call).
 */
export class FatLine {
  readonly object = new Group();
  private readonly front: LineMaterial;
  private readonly back: LineMaterial | null;
  private geometry: LineSegmentsGeometry | null = null;
  private lines: LineSegments2[] = [];

  constructor(options: FatLineOptions) {
    this.front = new LineMaterial({ color: new Color(options.color).getHex(), linewidth: options.width, worldUnits: false });
    this.back =
      options.xray && options.xray > 0
        ? new LineMaterial({ color: new Color(options.color).getHex(), linewidth: Math.max(1, options.width * 0.75), worldUnits: false, transparent: true, opacity: options.xray, depthTest: false, depthWrite: false })
        : null;
    liftTowardCamera(this.front);
    if (this.back) liftTowardCamera(this.back);
    this.object.renderOrder = options.order ?? 0;
  }

  /**
   * Sets the polylines: `xyz` holds all their points, `starts` the point index where each begins
   * (default: one polyline).
   */
  set(xyz: Float32Array | null, starts?: ArrayLike<number>): void {
    this.clear();
    if (!xyz || xyz.length < 6) return;
    const n = xyz.length / 3;
    const begins = starts && starts.length > 0 ? Array.from(starts) : [0];
    let count = 0;
    for (let k = 0; k < begins.length; k++) {
      const end = k + 1 < begins.length ? begins[k + 1] : n;
      count += Math.max(0, end - begins[k] - 1);
    }
    if (count === 0) return;
    const pairs = new Float32Array(6 * count);
    let o = 0;
    for (let k = 0; k < begins.length; k++) {
      const end = k + 1 < begins.length ? begins[k + 1] : n;
      for (let i = begins[k]; i + 1 < end; i++) {
        pairs.set(xyz.subarray(3 * i, 3 * i + 6), o);
        o += 6;
      }
    }
    this.geometry = new LineSegmentsGeometry();
    this.geometry.setPositions(pairs);
    const order = this.object.renderOrder;
    if (this.back) {
      const hidden = new LineSegments2(this.geometry, this.back);
      hidden.renderOrder = order;
      this.lines.push(hidden);
    }
    const shown = new LineSegments2(this.geometry, this.front);
    shown.renderOrder = order + 1;
    this.lines.push(shown);
    for (const l of this.lines) {
      l.frustumCulled = false;
      this.object.add(l);
    }
  }

  get empty(): boolean {
    return this.geometry === null;
  }

  setColor(color: ColorRepresentation): void {
    this.front.color.set(color);
    this.back?.color.set(color);
  }

  setWidth(width: number): void {
    this.front.linewidth = width;
    if (this.back) this.back.linewidth = Math.max(1, width * 0.75);
  }

  /** The canvas size in CSS pixels (the materials need it to size the lines). */
  setResolution(size: Vector2): void {
    this.front.resolution.copy(size);
    this.back?.resolution.copy(size);
  }

  clear(): void {
    for (const l of this.lines) this.object.remove(l);
    this.lines = [];
    this.geometry?.dispose();
    this.geometry = null;
  }

  dispose(): void {
    this.clear();
    this.front.dispose();
    this.back?.dispose();
  }
}
