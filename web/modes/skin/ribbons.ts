import { BufferGeometry, DoubleSide, Float32BufferAttribute, Mesh, ShaderMaterial, Uint32BufferAttribute } from 'three';

/**
 * Polylines drawn as ribbons of constant screen width, optionally dashed, colored per vertex: one
 * quad per segment, widened in the vertex shader, so zooming only changes uniforms. A plain
 * shader keeps this cheap for tens of thousands of segments, also with software WebGL.
 * Colors are sRGB (written as they are, like the control overlay's).
 */
export class Ribbons {
  readonly mesh: Mesh<BufferGeometry, ShaderMaterial>;
  private segments = 0;

  constructor(
    private readonly widthPx: number,
    dashed: { dash: number; gap: number } | null,
    renderOrder: number,
  ) {
    const material = new ShaderMaterial({
      uniforms: {
        uHalfWidth: { value: 1 },
        uScale: { value: 1 },
        uDash: { value: dashed?.dash ?? 0 },
        uGap: { value: dashed?.gap ?? 0 },
      },
      vertexShader: /* glsl */ `
        attribute vec3 tint;
        attribute vec2 across;
        attribute float along;
        uniform float uHalfWidth;
        varying vec3 vTint;
        varying float vAlong;
        void main() {
          vTint = tint;
          vAlong = along;
          vec3 p = position + vec3(across * uHalfWidth, 0.0);
          gl_Position = projectionMatrix * modelViewMatrix * vec4(p, 1.0);
        }`,
      fragmentShader: /* glsl */ `
        uniform float uScale;
        uniform float uDash;
        uniform float uGap;
        varying vec3 vTint;
        varying float vAlong;
        void main() {
          if (uGap > 0.0 && mod(vAlong * uScale, uDash + uGap) > uDash) discard;
          gl_FragColor = vec4(vTint, 1.0);
        }`,
      // The view's y points down, which turns the quads' winding around.
      side: DoubleSide,
      transparent: true,
      depthTest: false,
      depthWrite: false,
    });
    this.mesh = new Mesh(new BufferGeometry(), material);
    this.mesh.frustumCulled = false;
    this.mesh.renderOrder = renderOrder;
    this.mesh.visible = false;
  }

  /** Segments drawn. */
  get count(): number {
    return this.mesh.visible ? this.segments : 0;
  }

  /** Keeps the width in pixels and the dashes a constant length on screen (scale: pixels per unit). */
  setScale(scale: number): void {
    const u = this.mesh.material.uniforms;
    u.uHalfWidth.value = this.widthPx / 2 / scale;
    u.uScale.value = scale;
  }

  /**
   * Draws segments: `xy` holds x0 y0 x1 y1 per segment, `rgb` an sRGB color per end (6 numbers
   * per segment). Dashes run along consecutive segments that join.
   */
  set(xy: Float32Array, rgb: Float32Array): void {
    const n = xy.length / 4;
    const position = new Float32Array(n * 12), tint = new Float32Array(n * 12), across = new Float32Array(n * 8), along = new Float32Array(n * 4);
    const index = new Uint32Array(n * 6);
    let dist = 0, px = NaN, py = NaN;
    for (let s = 0; s < n; s++) {
      const x0 = xy[4 * s], y0 = xy[4 * s + 1], x1 = xy[4 * s + 2], y1 = xy[4 * s + 3];
      const len = Math.hypot(x1 - x0, y1 - y0);
      const nx = len > 0 ? -(y1 - y0) / len : 0, ny = len > 0 ? (x1 - x0) / len : 0;
      if (x0 !== px || y0 !== py) dist = 0; // a new polyline: restart the dash pattern
      for (let v = 0; v < 4; v++) {
        const k = 4 * s + v, side = v % 2 === 0 ? 1 : -1, end = v < 2 ? 0 : 1;
        position[3 * k] = end ? x1 : x0;
        position[3 * k + 1] = end ? y1 : y0;
        const c = 6 * s + 3 * end;
        tint[3 * k] = rgb[c];
        tint[3 * k + 1] = rgb[c + 1];
        tint[3 * k + 2] = rgb[c + 2];
        across[2 * k] = nx * side;
        across[2 * k + 1] = ny * side;
        along[k] = end ? dist + len : dist;
      }
      const b = 4 * s;
      index[6 * s] = b;
      index[6 * s + 1] = b + 1;
      index[6 * s + 2] = b + 2;
      index[6 * s + 3] = b + 1;
      index[6 * s + 4] = b + 3;
      index[6 * s + 5] = b + 2;
      dist += len;
      px = x1;
      py = y1;
    }
    const g = new BufferGeometry();
    g.setAttribute('position', new Float32BufferAttribute(position, 3));
    g.setAttribute('tint', new Float32BufferAttribute(tint, 3));
    g.setAttribute('across', new Float32BufferAttribute(across, 2));
    g.setAttribute('along', new Float32BufferAttribute(along, 1));
    g.setIndex(new Uint32BufferAttribute(index, 1));
    this.mesh.geometry.dispose();
    this.mesh.geometry = g;
    this.segments = n;
    this.mesh.visible = n > 0;
  }

  hide(): void {
    if (!this.mesh.visible) return;
    this.mesh.visible = false;
    this.segments = 0;
    this.mesh.geometry.dispose();
    this.mesh.geometry = new BufferGeometry();
  }

  dispose(): void {
    this.mesh.geometry.dispose();
    this.mesh.material.dispose();
  }
}
