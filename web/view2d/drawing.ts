import {
  BufferGeometry,
  Color,
  DoubleSide,
  Float32BufferAttribute,
  Mesh,
  MeshBasicMaterial,
  Path,
  ShapePath,
  ShapeUtils,
  SRGBColorSpace,
  Uint32BufferAttribute,
  type Vector2,
} from 'three';
import { SVGLoader } from 'three/examples/jsm/loaders/SVGLoader.js';
import type { SvgDocument, SvgShape } from '../../src/index.js';
import { cssColor } from './color.js';
import { flattenSpline } from './tessellate.js';
import { messageOf } from '../app/errors.js';

/** A shape the drawing left out because it could not be tessellated or stroked. */
export interface SkippedShape {
  /** The element as a user finds it in the file: `<path id="leg"> at line 12`. */
  element: string;
  /** What failed. */
  reason: string;
}

export interface DrawingStats {
  vertices: number;
  triangles: number;
  /** Time to tessellate and triangulate, in milliseconds. */
  ms: number;
  /** Shapes that failed to draw; everything else was drawn. */
  skipped: SkippedShape[];
}

/** Growable vertex/color/index buffers for one merged mesh. */
class MeshBuffers {
  positions: number[] = [];
  colors: number[] = [];
  indices: number[] = [];
  private color = new Color();

  get vertexCount(): number {
    return this.positions.length / 3;
  }

  /** Sets the color (linear RGB from an sRGB CSS color) and alpha for vertices added next. */
  setColor(rgba: readonly [number, number, number, number], alpha: number): [number, number, number, number] {
    this.color.setRGB(rgba[0], rgba[1], rgba[2], SRGBColorSpace);
    return [this.color.r, this.color.g, this.color.b, alpha];
  }

  /** Buffer lengths, to roll back a shape that fails half-way. */
  mark(): [number, number, number] {
    return [this.positions.length, this.colors.length, this.indices.length];
  }

  rollback([p, c, i]: [number, number, number]): void {
    this.positions.length = p;
    this.colors.length = c;
    this.indices.length = i;
  }

  addVertices(xyz: ArrayLike<number>, count: number, rgba: readonly number[]): void {
    for (let i = 0; i < 3 * count; i++) this.positions.push(xyz[i]);
    for (let i = 0; i < count; i++) this.colors.push(rgba[0], rgba[1], rgba[2], rgba[3]);
  }

  toGeometry(): BufferGeometry {
    const g = new BufferGeometry();
    g.setAttribute('position', new Float32BufferAttribute(this.positions, 3));
    g.setAttribute('color', new Float32BufferAttribute(this.colors, 4));
    g.setIndex(new Uint32BufferAttribute(this.indices, 1));
    return g;
  }
}

/**
 * The document painted from its spline model as one mesh: for every visible shape in document
 * order, its fill (fill-rule and holes through ShapePath.toShapes) then its stroke
 * (SVGLoader.pointsToStroke on the flattened splines, width scaled by the shape's transform).
 * Colors and alpha are per vertex, so a single draw call keeps the painter's order. A shape that
 * fails to tessellate or stroke is left out whole and listed in `stats.skipped`, naming its element;
 * the rest of the drawing is drawn.
 */
export function buildDrawing(doc: SvgDocument, tolerance: number): { mesh: Mesh; stats: DrawingStats } {
  const t0 = performance.now();
  const buffers = new MeshBuffers();
  const stroke: number[] = [];
  const xyz: number[] = [];
  // SVGLoader writes stroke UVs here; without a buffer its square caps read uvs[7] of undefined.
  const uvs: number[] = [];
  const skipped: SkippedShape[] = [];

  doc.shapes.forEach((shape, i) => {
    if (!shape.style.visible || shape.splineCount === 0) return;
    const before = buffers.mark();
    try {
      drawShape(shape, i);
    } catch (err) {
      buffers.rollback(before);
      const element = `<${shape.tag}${shape.id ? ` id="${shape.id}"` : ''}>${shape.line ? ` at line ${shape.line}` : ''}`;
      skipped.push({ element, reason: messageOf(err) });
    }
  });

  function drawShape(shape: SvgShape, i: number): void {
    const style = shape.style;
    const lines: Vector2[][] = doc.splinesOf(i).map((s) => flattenSpline(s, tolerance));

    const fill = cssColor(doc.paintColor(style.fill) ?? 'none');
    const fillAlpha = fill ? fill[3] * style.fillOpacity * style.opacity : 0;
    if (fill && fillAlpha > 0) {
      const rgba = buffers.setColor(fill, fillAlpha);
      const shapePath = new ShapePath();
      shapePath.userData = { style: { fillRule: style.fillRule } };
      for (const line of lines) if (line.length >= 3) shapePath.subPaths.push(new Path(line));
      for (const outline of shapePath.toShapes()) {
        const { shape: contour, holes } = outline.extractPoints(1);
        const outer = ShapeUtils.isClockWise(contour) ? contour : contour.reverse();
        const inner = holes.map((h) => (ShapeUtils.isClockWise(h) ? h.reverse() : h));
        const faces = ShapeUtils.triangulateShape(outer, inner); // drops duplicated end points first
        const base = buffers.vertexCount;
        xyz.length = 0;
        for (const ring of [outer, ...inner]) for (const v of ring) xyz.push(v.x, v.y, 0);
        buffers.addVertices(xyz, xyz.length / 3, rgba);
        for (const f of faces) buffers.indices.push(base + f[0], base + f[1], base + f[2]);
      }
    }

    const strokeColor = cssColor(doc.paintColor(style.stroke) ?? 'none');
    const strokeAlpha = strokeColor ? strokeColor[3] * style.strokeOpacity * style.opacity : 0;
    const t = shape.transform;
    const width = style.strokeWidth * Math.sqrt(Math.abs(t.a * t.d - t.b * t.c));
    if (strokeColor && strokeAlpha > 0 && width > 0) {
      const rgba = buffers.setColor(strokeColor, strokeAlpha);
      const join = style.strokeLinejoin === 'arcs' ? 'miter' : style.strokeLinejoin;
      const pen = SVGLoader.getStrokeStyle(width, '#000', join, style.strokeLinecap, style.strokeMiterlimit);
      for (const line of lines) {
        if (line.length < 2) continue;
        stroke.length = 0;
        uvs.length = 0;
        SVGLoader.pointsToStrokeWithBuffers(line, pen, 6, tolerance * 0.01, stroke, undefined, uvs, 0);
        // Count what was written: three r187 returns the number of coordinates, not vertices.
        const count = stroke.length / 3;
        const base = buffers.vertexCount;
        buffers.addVertices(stroke, count, rgba);
        for (let v = 0; v < count; v++) buffers.indices.push(base + v);
      }
    }
  }

  const geometry = buffers.toGeometry();
  const material = new MeshBasicMaterial({
    vertexColors: true,
    transparent: true,
    side: DoubleSide,
    depthTest: false,
    depthWrite: false,
  });
  const mesh = new Mesh(geometry, material);
  mesh.frustumCulled = false;
  mesh.name = 'drawing';
  return {
    mesh,
    stats: { vertices: buffers.vertexCount, triangles: buffers.indices.length / 3, ms: performance.now() - t0, skipped },
  };
}
