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
        uHalfPx: { value: widthPx / 2 },
        uScale: { value: 1 },
        uDash: { value: dashed?.dash ?? 0 },
        uGap: { value: dashed?.gap ?? 0 },
      },
      vertexShader: /* glsl */ `
        attribute vec3 tint;
        attribute vec2 across;
        attribute float along;
        attribute float edge;
        uniform float uHalfWidth;
        uniform float uHalfPx;
        varying vec3 vTint;
        varying float vAlong;
        varying float vEdge;
        void main() {
          vTint = tint;
          vAlong = along;
          // Pixels from the middle line: ±(half width + 1) at the quad's sides, for the edge fade.
          vEdge = edge * (uHalfPx + 1.0);
          vec3 p = position + vec3(across * uHalfWidth, 0.0);
          gl_Position = projectionMatrix * modelViewMatrix * vec4(p, 1.0);
        }`,
      fragmentShader: /* glsl */ `
        uniform float uScale;
        uniform float uDash;
        uniform float uGap;
        uniform float uHalfPx;
        varying vec3 vTint;
        varying float vAlong;
        varying float vEdge;
        void main() {
          if (uGap > 0.0 && mod(vAlong * uScale, uDash + uGap) > uDash) discard;
          // Coverage of the pixel by the ribbon: smooth sides without multisampling.
          float coverage = clamp(uHalfPx + 0.5 - abs(vEdge), 0.0, 1.0);
          if (coverage <= 0.0) discard;
          gl_FragColor = vec4(vTint, coverage);
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
    // One pixel wider on each side than drawn, for the fragment shader's edge fade.
    u.uHalfWidth.value = (this.widthPx / 2 + 1) / scale;
    u.uScale.value = scale;
  }

  /**
   * Draws segments: `xy` holds x0 y0 x1 y1 per segment, `rgb` an sRGB color per end (6 numbers
   * per segment). Dashes run along consecutive segments that join.
   */
  set(xy: Float32Array, rgb: Float32Array): void {
    const n = xy.length / 4;
    // The same number of segments (a new pose of the same curves): rewrite the buffers in place.
    const reuse = this.mesh.visible && n === this.segments;
    const g = reuse ? this.mesh.geometry : new BufferGeometry();
    const old = (name: string) => (g.getAttribute(name) as Float32BufferAttribute).array as Float32Array;
    const position = reuse ? old('position') : new Float32Array(n * 12), tint = reuse ? old('tint') : new Float32Array(n * 12);
    const across = reuse ? old('across') : new Float32Array(n * 8), along = reuse ? old('along') : new Float32Array(n * 4);
    const edge = reuse ? null : new Float32Array(n * 4);
    const index = reuse ? null : new Uint32Array(n * 6);
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
        if (edge) edge[k] = side;
      }
      if (index) {
        const b = 4 * s;
        index[6 * s] = b;
        index[6 * s + 1] = index[6 * s + 3] = b + 1;
        index[6 * s + 2] = index[6 * s + 5] = b + 2;
        index[6 * s + 4] = b + 3;
      }
      dist += len;
      px = x1;
      py = y1;
    }
    if (reuse) {
      for (const name of ['position', 'tint', 'across', 'along']) g.getAttribute(name).needsUpdate = true;
      return;
    }
    g.setAttribute('position', new Float32BufferAttribute(position, 3));
    g.setAttribute('tint', new Float32BufferAttribute(tint, 3));
    g.setAttribute('across', new Float32BufferAttribute(across, 2));
    g.setAttribute('along', new Float32BufferAttribute(along, 1));
    g.setAttribute('edge', new Float32BufferAttribute(edge!, 1));
    g.setIndex(new Uint32BufferAttribute(index!, 1));
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
