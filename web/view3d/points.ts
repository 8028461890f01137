import { BufferAttribute, BufferGeometry, Color, Group, Points, ShaderMaterial, type ColorRepresentation } from 'three';

/** One marker: a disc or a square of `size` CSS pixels, with a dark outline. */
export interface Marker {
  x: number;
  y: number;
  z: number;
  color: ColorRepresentation;
  size: number;
  shape: 'disc' | 'square';
}

const VERTEX = /* glsl */ `
attribute vec3 color;
attribute float size;
attribute float shape;
uniform float pixelRatio;
/** Toward the camera by this fraction of the depth (about the marker's radius). */
uniform float lift;
varying vec3 vColor;
varying float vShape;
varying float vSize;
void main() {
  vColor = color;
  vShape = shape;
  vSize = size * pixelRatio;
  vec4 mv = modelViewMatrix * vec4(position, 1.0);
  // Toward the camera: the whole sprite clears the surface it sits on.
  mv.xyz *= 1.0 - lift;
  gl_Position = projectionMatrix * mv;
  gl_PointSize = vSize;
}`;

const FRAGMENT = /* glsl */ `
uniform float opacity;
varying vec3 vColor;
varying float vShape;
varying float vSize;
void main() {
  vec2 c = gl_PointCoord * 2.0 - 1.0;
  float d = vShape > 0.5 ? max(abs(c.x), abs(c.y)) : length(c);
  if (d > 1.0) discard;
  float ring = 1.0 - 3.0 / max(vSize, 1.0);
  vec3 col = d > ring ? vec3(0.07, 0.08, 0.09) : vColor;
  gl_FragColor = vec4(col, opacity);
}`;

/**
 * Control points as screen-space markers (GL points with a disc or square sprite): depth-tested
 * against the mesh, plus a faint pass that shows the hidden ones through it.
 */
export class MarkerLayer {
  readonly object = new Group();
  private readonly front: ShaderMaterial;
  private readonly back: ShaderMaterial;
  private geometry: BufferGeometry | null = null;
  private points: Points[] = [];

  constructor(order = 20, xray = 0.3) {
    const uniforms = () => ({ pixelRatio: { value: window.devicePixelRatio || 1 }, lift: { value: 0 }, opacity: { value: 1 } });
    this.front = new ShaderMaterial({ vertexShader: VERTEX, fragmentShader: FRAGMENT, uniforms: uniforms(), transparent: false });
    this.back = new ShaderMaterial({ vertexShader: VERTEX, fragmentShader: FRAGMENT, uniforms: uniforms(), transparent: true, depthTest: false, depthWrite: false });
    this.back.uniforms.opacity.value = xray;
    this.object.renderOrder = order;
  }

  set(markers: readonly Marker[]): void {
    this.clear();
    if (markers.length === 0) return;
    const n = markers.length;
    const pos = new Float32Array(3 * n), col = new Float32Array(3 * n), size = new Float32Array(n), shape = new Float32Array(n);
    const c = new Color();
    markers.forEach((m, i) => {
      pos.set([m.x, m.y, m.z], 3 * i);
      c.set(m.color);
      col.set([c.r, c.g, c.b], 3 * i);
      size[i] = m.size;
      shape[i] = m.shape === 'square' ? 1 : 0;
    });
    const g = new BufferGeometry();
    g.setAttribute('position', new BufferAttribute(pos, 3));
    g.setAttribute('color', new BufferAttribute(col, 3));
    g.setAttribute('size', new BufferAttribute(size, 1));
    g.setAttribute('shape', new BufferAttribute(shape, 1));
    this.geometry = g;
    const hidden = new Points(g, this.back), shown = new Points(g, this.front);
    hidden.renderOrder = this.object.renderOrder;
    shown.renderOrder = this.object.renderOrder + 1;
    for (const p of [hidden, shown]) {
      p.frustumCulled = false;
      this.object.add(p);
      this.points.push(p);
    }
  }

  /** Fraction of their depth the markers are drawn toward the camera (about their radius). */
  setLift(lift: number): void {
    this.front.uniforms.lift.value = lift;
    this.back.uniforms.lift.value = lift;
  }

  clear(): void {
    for (const p of this.points) this.object.remove(p);
    this.points = [];
    this.geometry?.dispose();
    this.geometry = null;
  }

  dispose(): void {
    this.clear();
    this.front.dispose();
    this.back.dispose();
  }
}
