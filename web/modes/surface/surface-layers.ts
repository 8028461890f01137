import { Group } from 'three';
import { FatLine, TOWARD_CAMERA } from '../../view3d/lines.js';
import { MarkerLayer, type Marker } from '../../view3d/points.js';
import type { View3D } from '../../view3d/view3d.js';

/** Colors of what surface mode draws on the (light grey) mesh. */
export const SURFACE_COLORS = {
  curve: '#e8590c',
  selected: '#1864ab',
  polygon: '#212529',
  preview: '#1c7ed6',
  anchor: '#ffffff',
  handle: '#74c0fc',
  hot: '#ffd43b',
  pending: '#ffffff',
  center: '#e64980',
};

export interface CurveShape {
  id: number;
  /** Lifted polyline (x y z), or null while it is being traced. */
  lifted: Float32Array | null;
  selected: boolean;
}

/**
 * The scene objects of surface mode: one fat polyline per spline, the selected spline's control
 * polygon, the rubber band while drawing, and the control points as screen-space markers.
 * Objects are rebuilt only when their arrays change (arrays are replaced, never mutated).
 */
export class SurfaceLayers {
  readonly root = new Group();
  private readonly curves = new Map<number, { line: FatLine; lifted: Float32Array | null; selected: boolean }>();
  private readonly polygon = new FatLine({ color: SURFACE_COLORS.polygon, width: 1.5, xray: 0.3, order: 12 });
  private readonly preview = new FatLine({ color: SURFACE_COLORS.preview, width: 2, xray: 0.3, order: 13 });
  private readonly markers = new MarkerLayer(20, 0.35);
  private polygonData: Float32Array | null = null;
  private previewData: Float32Array | null = null;

  constructor(private readonly view: View3D) {
    this.root.name = 'surface-layers';
    this.root.add(this.polygon.object, this.preview.object, this.markers.object);
    view.layer.add(this.root);
    this.resized();
  }

  setCurves(shapes: readonly CurveShape[]): void {
    const keep = new Set<number>();
    for (const s of shapes) {
      keep.add(s.id);
      let c = this.curves.get(s.id);
      if (!c) {
        c = { line: new FatLine({ color: SURFACE_COLORS.curve, width: 3, xray: 0.12, order: 10 }), lifted: null, selected: false };
        this.curves.set(s.id, c);
        this.root.add(c.line.object);
        c.line.setResolution(this.view.size);
      }
      if (c.lifted !== s.lifted) {
        c.lifted = s.lifted;
        c.line.set(s.lifted);
      }
      if (c.selected !== s.selected || !c.line.object.userData.styled) {
        c.selected = s.selected;
        c.line.object.userData.styled = true;
        c.line.setColor(s.selected ? SURFACE_COLORS.selected : SURFACE_COLORS.curve);
        c.line.setWidth(s.selected ? 3.5 : 3);
      }
    }
    for (const [id, c] of this.curves) {
      if (keep.has(id)) continue;
      this.root.remove(c.line.object);
      c.line.dispose();
      this.curves.delete(id);
    }
  }

  setPolygon(lifted: Float32Array | null, starts: Int32Array | null): void {
    if (lifted === this.polygonData) return;
    this.polygonData = lifted;
    this.polygon.set(lifted, starts ?? undefined);
  }

  setPreview(lifted: Float32Array | null): void {
    if (lifted === this.previewData) return;
    this.previewData = lifted;
    this.preview.set(lifted);
  }

  setMarkers(markers: readonly Marker[], lift: number): void {
    this.markers.set(markers);
    this.markers.setLift(lift);
  }

  /** The view changed: lines keep their pixel widths and their lift toward the camera. */
  resized(): void {
    // 1.5 pixels' worth at any depth (world units per pixel grow linearly with the depth).
    TOWARD_CAMERA.value = this.view.worldPerPixel(1) * 1.5;
    for (const c of this.curves.values()) c.line.setResolution(this.view.size);
    this.polygon.setResolution(this.view.size);
    this.preview.setResolution(this.view.size);
  }

  clear(): void {
    this.setCurves([]);
    this.setPolygon(null, null);
    this.setPreview(null);
    this.markers.clear();
  }

  dispose(): void {
    this.clear();
    this.polygon.dispose();
    this.preview.dispose();
    this.markers.dispose();
    this.view.layer.remove(this.root);
  }
}
