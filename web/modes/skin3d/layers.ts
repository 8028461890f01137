import { BufferAttribute, BufferGeometry, DoubleSide, LineBasicMaterial, LineSegments, Mesh, MeshStandardMaterial, Object3D, type Material } from 'three';
import { TransformControls } from 'three/examples/jsm/controls/TransformControls.js';
import type { Cage } from '../../../src/index.js';
import { MarkerLayer, type Marker } from '../../view3d/points.js';
import type { View3D } from '../../view3d/view3d.js';
import { rampColors } from './colormap.js';

export const SKIN3D_COLORS = {
  cage: 0x5aa0ff,
  handle: 0xffb347,
  selected: 0xff5a36,
  target: 0x3ecf8e,
  naive: 0xe0565b,
};

/** The unique edges of a cage's faces, as vertex index pairs. */
export function cageEdges(cage: Cage): Uint32Array {
  const seen = new Set<number>(), edges: number[] = [];
  const n = cage.positions.length / 3;
  let at = 0;
  for (const size of cage.faceSizes) {
    for (let k = 0; k < size; k++) {
      const a = cage.faceIndices[at + k], b = cage.faceIndices[at + ((k + 1) % size)];
      const key = Math.min(a, b) * n + Math.max(a, b);
      if (seen.has(key)) continue;
      seen.add(key);
      edges.push(a, b);
    }
    at += size;
  }
  return Uint32Array.from(edges);
}

/** Copies float64 xyz into a float32 attribute's array (same length) and flags it for upload. */
function upload(attribute: BufferAttribute, values: Float64Array): void {
  (attribute.array as Float32Array).set(values);
  attribute.needsUpdate = true;
}

/** A translucent copy of the refined surface (the target or the naive overlay). */
class OverlaySurface {
  readonly mesh: Mesh;
  private readonly material: MeshStandardMaterial;

  constructor(name: string, color: number, triangles: Uint32Array, count: number) {
    const g = new BufferGeometry();
    g.setAttribute('position', new BufferAttribute(new Float32Array(3 * count), 3));
    g.setAttribute('color', new BufferAttribute(new Float32Array(3 * count), 3));
    g.setIndex(new BufferAttribute(triangles, 1));
    this.material = new MeshStandardMaterial({ color, roughness: 0.8, metalness: 0, transparent: true, opacity: 0.4, depthWrite: false, side: DoubleSide });
    this.mesh = new Mesh(g, this.material);
    this.mesh.name = name;
    this.mesh.renderOrder = 5;
    this.mesh.visible = false;
    this.mesh.frustumCulled = false;
  }

  /** Shows `positions` (3 per vertex), coloured by `errors` on 0…`max` when given. */
  show(positions: Float64Array, errors: Float64Array | null, max: number): void {
    const g = this.mesh.geometry;
    upload(g.getAttribute('position') as BufferAttribute, positions);
    g.computeVertexNormals();
    if (errors) {
      const colors = g.getAttribute('color') as BufferAttribute;
      rampColors(errors, max, colors.array as Float32Array);
      colors.needsUpdate = true;
    }
    if (this.material.vertexColors !== (errors !== null)) {
      this.material.vertexColors = errors !== null;
      this.material.color.set(errors ? 0xffffff : this.baseColor);
      this.material.needsUpdate = true;
    }
    this.mesh.visible = true;
  }

  private get baseColor(): number {
    return this.mesh.name === 'skin3d-target' ? SKIN3D_COLORS.target : SKIN3D_COLORS.naive;
  }

  hide(): void {
    this.mesh.visible = false;
  }

  dispose(): void {
    this.mesh.geometry.dispose();
    this.material.dispose();
  }
}

/**
 * What 3D Skin mode draws in the view: the refined surface (the view's mesh, deformed in place),
 * the cage as a wireframe, the target and naive overlays, the handles as markers and the
 * translate/rotate/scale gizmo (three.js TransformControls) on the selected handle's proxy object.
 */
export class Skin3DLayers {
  readonly gizmo: TransformControls;
  /** What the gizmo moves: placed at the selected handle's pose, read back while dragging. */
  readonly proxy = new Object3D();
  private readonly group = new Object3D();
  private readonly cageMaterial = new LineBasicMaterial({ color: SKIN3D_COLORS.cage, transparent: true, opacity: 0.85, depthTest: false });
  private cageLines: LineSegments | null = null;
  private target: OverlaySurface | null = null;
  private naive: OverlaySurface | null = null;
  private readonly markers = new MarkerLayer(20, 0.45);
  private surfaceColors: Float32Array | null = null;
  private surfaceColor = 0xc4bcaf;

  constructor(readonly view: View3D) {
    this.group.name = 'skin3d';
    this.group.add(this.markers.object, this.proxy);
    view.layer.add(this.group);
    this.gizmo = new TransformControls(view.camera, view.canvas);
    this.gizmo.setSize(0.9);
    view.scene.add(this.gizmo.getHelper());
    this.gizmo.addEventListener('change', () => view.requestRender());
    this.gizmo.addEventListener('axis-changed', () => view.requestRender());
  }

  /**
   * Shows a cage and its refined surface at rest: the surface becomes the view's mesh (framed
   * when `fit`), the overlays get its triangles.
   */
  setCage(cage: Cage, rest: Float64Array, triangles: Uint32Array, fit: boolean): void {
    this.clear();
    this.view.setMesh(Float32Array.from(rest), triangles, { fit });
    const g = new BufferGeometry();
    g.setAttribute('position', new BufferAttribute(Float32Array.from(cage.positions), 3));
    g.setIndex(new BufferAttribute(cageEdges(cage), 1));
    this.cageLines = new LineSegments(g, this.cageMaterial);
    this.cageLines.name = 'skin3d-cage';
    this.cageLines.renderOrder = 10;
    this.cageLines.frustumCulled = false;
    const count = rest.length / 3;
    this.target = new OverlaySurface('skin3d-target', SKIN3D_COLORS.target, triangles, count);
    this.naive = new OverlaySurface('skin3d-naive', SKIN3D_COLORS.naive, triangles, count);
    this.surfaceColors = new Float32Array(rest.length);
    this.view.geometry?.setAttribute('color', new BufferAttribute(this.surfaceColors, 3));
    this.group.add(this.cageLines, this.target.mesh, this.naive.mesh);
    this.view.requestRender();
  }

  /** The refined surface's vertex count shown (0: nothing shown). */
  get surfaceCount(): number {
    return (this.view.mesh?.positions.length ?? 0) / 3;
  }

  /** Deforms the shown cage and surface in place (no allocation). */
  update(cage: Float64Array, surface: Float64Array): void {
    const m = this.view.mesh;
    if (!m || !this.cageLines || surface.length !== m.positions.length) return;
    m.positions.set(surface);
    this.view.meshChanged();
    upload(this.cageLines.geometry.getAttribute('position') as BufferAttribute, cage);
  }

  setCageVisible(visible: boolean): void {
    if (this.cageLines) this.cageLines.visible = visible;
    this.view.requestRender();
  }

  /** Colours the surface by `errors` on 0…`max`, or takes the colours off (null). */
  setSurfaceErrors(errors: Float64Array | null, max: number): void {
    const g = this.view.geometry, colors = this.surfaceColors;
    const material = this.view.material;
    if (errors && g && colors && errors.length * 3 === colors.length) {
      rampColors(errors, max, colors);
      g.getAttribute('color').needsUpdate = true;
    }
    const on = errors !== null;
    if (material.vertexColors !== on) {
      // The colours as they are (not tinted by the surface's own colour), and back.
      if (on) this.surfaceColor = material.color.getHex();
      material.color.set(on ? 0xffffff : this.surfaceColor);
      material.vertexColors = on;
      material.needsUpdate = true;
    }
    this.view.requestRender();
  }

  /** Shows or hides the target and naive overlays (naive coloured by its errors when given). */
  setOverlays(target: Float64Array | null, naive: Float64Array | null, naiveErrors: Float64Array | null, max: number): void {
    if (target) this.target?.show(target, null, max);
    else this.target?.hide();
    if (naive) this.naive?.show(naive, naiveErrors, max);
    else this.naive?.hide();
    this.view.requestRender();
  }

  setHandles(markers: readonly Marker[]): void {
    this.markers.set(markers);
    this.view.requestRender();
  }

  /** Puts the gizmo on the proxy (placed by the caller), or takes it off. */
  attachGizmo(on: boolean): void {
    if (on && this.gizmo.object !== this.proxy) this.gizmo.attach(this.proxy);
    else if (!on && this.gizmo.object) this.gizmo.detach();
    this.view.requestRender();
  }

  /**
   * Whether a press at canvas pixel (sx, sy) is on the gizmo (one of its axes, planes or rings):
   * asks the controls' own picking, so what the user presses is what it drags.
   */
  gizmoHit(sx: number, sy: number): boolean {
    if (!this.gizmo.object || !this.gizmo.enabled) return false;
    const size = this.view.size;
    // The controls read only x, y (normalised device coordinates) and button of their pointer.
    this.gizmo.pointerHover({ x: (sx / size.x) * 2 - 1, y: -(sy / size.y) * 2 + 1, button: 0 } as unknown as PointerEvent);
    return this.gizmo.axis !== null;
  }

  clear(): void {
    this.attachGizmo(false);
    this.markers.clear();
    for (const o of [this.cageLines, this.target?.mesh, this.naive?.mesh]) if (o) this.group.remove(o);
    this.cageLines?.geometry.dispose();
    this.cageLines = null;
    this.target?.dispose();
    this.naive?.dispose();
    this.target = this.naive = null;
    this.surfaceColors = null;
    this.setSurfaceErrors(null, 1);
    this.view.clearMesh();
  }

  dispose(): void {
    this.clear();
    this.gizmo.dispose();
    this.markers.dispose();
    (this.cageMaterial as Material).dispose();
  }
}
