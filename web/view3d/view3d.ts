import {
  AlwaysDepth,
  Box3,
  BufferAttribute,
  BufferGeometry,
  Color,
  DepthTexture,
  DirectionalLight,
  DoubleSide,
  Group,
  HemisphereLight,
  Mesh,
  MeshStandardMaterial,
  PerspectiveCamera,
  Scene,
  ShaderMaterial,
  SRGBColorSpace,
  Sphere,
  Vector2,
  Vector3,
  WebGLRenderer,
  WebGLRenderTarget,
  MOUSE,
} from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { FullScreenQuad } from 'three/examples/jsm/postprocessing/Pass.js';
import { Emitter } from '../app/events.js';
import type { MeshBounds } from './bounds.js';
import { TriangleBVH, type BVHArrays, type RayHit } from './bvh.js';
import { softwareWebGL } from './gl-info.js';
import { FrameScheduler } from '../app/frames.js';

/** A pointer on the 3D view: canvas CSS pixels plus the modifier keys. */
export interface Pointer3D {
  sx: number;
  sy: number;
  button: number;
  shiftKey: boolean;
  altKey: boolean;
  /** Ctrl, or Cmd on macOS. */
  modKey: boolean;
  /** The time of the event (ms), for double-click detection. */
  time: number;
}

/**
 * Who gets pointer input on the 3D view (the surface mode). A left-button gesture the input does
 * not claim orbits the camera; a press and release without moving is a click.
 */
export interface View3DInput {
  /** Return true to own the drag (the camera stays put). */
  pointerDown(p: Pointer3D): boolean;
  /** A drag the input owns. */
  pointerDrag(p: Pointer3D): void;
  /** The claimed gesture ended (`moved`: it went past the click slop; button -1: cancelled). */
  pointerUp(p: Pointer3D, moved: boolean): void;
  /** The pointer moved with no button down. */
  hover(p: Pointer3D): void;
  pointerLeave(): void;
  /** A press and release without moving that no pointerDown claimed. */
  click(p: Pointer3D): void;
  doubleClick(p: Pointer3D): void;
}

export interface View3DEvents extends Record<string, unknown> {
  /** The camera moved or the canvas was resized. */
  view: null;
  /** A frame is about to be drawn: the moment to update what it shows (within it, asking for a render asks for the next frame). */
  prerender: number;
  /** A frame was drawn. */
  render: number;
}

/** Mesh material and background colors. */
const BACKGROUND = 0x1b1d21;
const MESH_COLOR = 0xc4bcaf;
/** Pixels the pointer may travel and still make a click. */
const CLICK_SLOP = 4;
/**
 * Triangles a software rasteriser draws in ~30 ms (SwiftShader: ~0.2 µs a triangle on these
 * machines, when nothing else runs). A mesh of more is drawn in pieces, one a frame (see render()); a GPU draws any
 * mesh in one.
 */
const SOFTWARE_TRIANGLES_PER_FRAME = 150_000;
/** The camera must have been still this long (ms) before the full mesh is drawn piece by piece. */
const SETTLE_MS = 120;

/** A coarse stand-in for a large mesh (web/view3d/proxy.ts) with its smooth normals. */
export interface MeshProxyArrays {
  positions: Float32Array;
  triangles: Uint32Array;
  normals: Float32Array;
}

/**
 * A mesh too large to draw in a frame: its proxy is drawn while the camera moves; once it is
 * still, the mesh is drawn into `target` (color and depth) a piece a frame, and when all of it is
 * there, frames copy the target to the screen and draw the mode's layers over it (depth tested
 * against the mesh's depth), so a curve edit does not draw the mesh again.
 */
interface Detail {
  proxy: Mesh;
  /**
   * The mesh in pieces of up to trianglesPerFrame consecutive triangles: their own index buffers,
   * the mesh's vertex buffers (so each piece's frame uploads only its indices).
   */
  pieces: Mesh[];
  /** The vertex buffers are on the GPU (uploaded in a frame of their own, before the first piece). */
  uploaded: boolean;
  target: WebGLRenderTarget;
  /** Pieces of the mesh drawn into the target for the current view. */
  drawn: number;
  /** When the view last changed (performance.now()). */
  changedAt: number;
  /** The screen must be drawn again (the layers or the view changed). */
  stale: boolean;
  /** The screen shows the mesh (else the proxy). */
  full: boolean;
  /**
   * Signalled when the GPU has drawn the last piece sent. The next piece waits for it: a WebGL
   * draw returns before it is done, and the frame that next draws on screen would wait for every
   * piece sent before it (a software rasteriser works through them only then).
   */
  fence: WebGLSync | null;
  timer: ReturnType<typeof setTimeout> | 0;
}

/** Copies a render target's color and depth to the screen (the depth, so layers are hidden by the mesh). */
function copyMaterial(): ShaderMaterial {
  return new ShaderMaterial({
    uniforms: { tColor: { value: null }, tDepth: { value: null } },
    vertexShader: 'varying vec2 vUv; void main() { vUv = uv; gl_Position = vec4(position.xy, 0.0, 1.0); }',
    // (only where the mesh is: the background is the screen's own clear color)
    fragmentShader: `uniform sampler2D tColor; uniform sampler2D tDepth; varying vec2 vUv;
      void main() {
        float depth = texture2D(tDepth, vUv).x;
        if (depth >= 1.0) discard;
        gl_FragColor = texture2D(tColor, vUv);
        gl_FragDepth = depth;
        #include <colorspace_fragment>
      }`,
    depthTest: true,
    depthFunc: AlwaysDepth,
    depthWrite: true,
  });
}

/** A mesh shown by the view: its geometry in file order, so face indices are the file's. */
export interface ShownMesh {
  positions: Float32Array;
  triangles: Uint32Array;
  /** Smooth vertex normals (three's, area weighted). */
  normals: Float32Array;
  center: Vector3;
  radius: number;
  /** Bounding box: min x y z, max x y z. */
  box: [number, number, number, number, number, number];
}

/**
 * A three.js 3D view: a perspective camera with orbit controls (orbit, zoom at the cursor, pan),
 * a hemisphere light and a headlight that follows the camera, one triangle mesh built from file
 * positions and triangles (face i of the geometry is face i of the file), and a layer for what a
 * mode draws on it. Renders on demand. Picking goes through a BVH and answers mesh points.
 */
export class View3D {
  readonly events = new Emitter<View3DEvents>();
  readonly renderer: WebGLRenderer;
  readonly scene = new Scene();
  readonly camera = new PerspectiveCamera(40, 1, 0.01, 100);
  readonly controls: OrbitControls;
  /** Where modes add their objects (curves, points). */
  readonly layer = new Group();
  readonly material: MeshStandardMaterial;
  input: View3DInput | null = null;
  /** Size of the canvas in CSS pixels. */
  readonly size = new Vector2(1, 1);

  private meshObject: Mesh | null = null;
  private shown: ShownMesh | null = null;
  private bvh: TriangleBVH | null = null;
  /** The picking hierarchy comes later (setPicking). */
  private pickingLater = false;
  /** Triangles drawn in one frame at most (larger meshes with a proxy are drawn over frames). */
  private readonly trianglesPerFrame: number;
  private detail: Detail | null = null;
  /** The orbit controls are being dragged. */
  private orbiting = false;
  private copy: FullScreenQuad | null = null;
  private readonly frames = new FrameScheduler((time) => {
    this.events.emit('prerender', time);
    this.render();
    this.events.emit('render', time);
  });
  private visible = true;
  private gesture: { id: number; sx: number; sy: number; claimed: boolean; moved: boolean } | null = null;

  constructor(readonly container: HTMLElement) {
    // Multisampled on a GPU; not on a software rasteriser, where it would double a big mesh's frame.
    this.renderer = new WebGLRenderer({ antialias: !softwareWebGL(), preserveDrawingBuffer: true, powerPreference: 'high-performance' });
    this.trianglesPerFrame = softwareWebGL() ? SOFTWARE_TRIANGLES_PER_FRAME : Infinity;
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setClearColor(new Color(BACKGROUND), 1);
    const canvas = this.renderer.domElement;
    canvas.className = 'view3d-canvas';
    canvas.tabIndex = 0;
    canvas.setAttribute('aria-label', '3D view of the mesh');
    canvas.dataset.testid = 'view3d';
    container.appendChild(canvas);

    this.scene.add(new HemisphereLight(0xf4f6ff, 0x2e2a26, 1.1));
    // A headlight above-left of the camera: the side the user looks at is always lit.
    const key = new DirectionalLight(0xffffff, 2.6);
    key.position.set(-1, 1.1, 0.55);
    key.target.position.set(0, 0, -1);
    this.camera.add(key, key.target);
    this.scene.add(this.camera, this.layer);

    this.material = new MeshStandardMaterial({
      color: MESH_COLOR,
      roughness: 0.78,
      metalness: 0,
      side: DoubleSide,
      // Push the surface back in depth so curves drawn on it win the depth test.
      polygonOffset: true,
      polygonOffsetFactor: 1,
      polygonOffsetUnits: 1,
    });

    // Our listeners go first: a gesture the mode claims disables the controls before they see it.
    this.listen(canvas);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.enableDamping = false;
    this.controls.zoomToCursor = true;
    this.controls.screenSpacePanning = true;
    this.controls.mouseButtons = { LEFT: MOUSE.ROTATE, MIDDLE: MOUSE.ROTATE, RIGHT: MOUSE.PAN };
    this.controls.addEventListener('change', () => this.viewChanged());
    // A large mesh is not drawn in pieces while the user orbits (only once the camera is let go).
    this.controls.addEventListener('start', () => (this.orbiting = true));
    this.controls.addEventListener('end', () => {
      this.orbiting = false;
      this.redrawMesh();
      this.requestRender();
    });

    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  get canvas(): HTMLCanvasElement {
    return this.renderer.domElement;
  }

  /** The shown mesh's data, or null. */
  get mesh(): ShownMesh | null {
    return this.shown;
  }

  /** Shows or hides the canvas (three sets an inline display: the attribute `hidden` would not do). */
  setVisible(visible: boolean): void {
    this.visible = visible;
    this.canvas.style.display = visible ? 'block' : 'none';
    if (visible) {
      this.resize();
      this.requestRender();
    }
  }

  /**
   * Shows a mesh (positions xyz, triangles in file order). Smooth normals and the picking
   * hierarchy (and the bounds) are computed unless given (a worker can make them). `fit` frames the mesh. A
   * `proxy` is drawn instead while the camera moves if the mesh has more triangles than the
   * renderer draws in a frame (the still picture is the mesh, drawn over a few frames).
   */
  setMesh(
    positions: Float32Array,
    triangles: Uint32Array,
    options: { fit?: boolean; normals?: Float32Array; bvh?: BVHArrays | 'later'; proxy?: MeshProxyArrays | null; bounds?: MeshBounds } = {},
  ): ShownMesh {
    const fit = options.fit ?? true;
    this.clearMesh();
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(positions, 3));
    geometry.setIndex(new BufferAttribute(triangles, 1));
    if (options.normals && options.normals.length === positions.length) geometry.setAttribute('normal', new BufferAttribute(options.normals, 3));
    else geometry.computeVertexNormals();
    if (options.bounds) {
      const [x0, y0, z0, x1, y1, z1] = options.bounds.box;
      geometry.boundingBox = new Box3(new Vector3(x0, y0, z0), new Vector3(x1, y1, z1));
      geometry.boundingSphere = new Sphere(geometry.boundingBox.getCenter(new Vector3()), options.bounds.radius);
    } else {
      geometry.computeBoundingSphere();
      geometry.computeBoundingBox();
    }
    const bb = geometry.boundingBox!;
    const sphere = geometry.boundingSphere ?? new Sphere(new Vector3(), 1);
    this.meshObject = new Mesh(geometry, this.material);
    this.meshObject.name = 'surface-mesh';
    this.scene.add(this.meshObject);
    const proxy = options.proxy;
    if (proxy && triangles.length / 3 > this.trianglesPerFrame && proxy.triangles.length < triangles.length) {
      const g = new BufferGeometry();
      g.setAttribute('position', new BufferAttribute(proxy.positions, 3));
      g.setAttribute('normal', new BufferAttribute(proxy.normals, 3));
      g.setIndex(new BufferAttribute(proxy.triangles, 1));
      const object = new Mesh(g, this.material);
      object.name = 'surface-mesh-proxy';
      object.visible = false;
      this.scene.add(object);
      this.meshObject.visible = false; // (drawn as its pieces)
      const pieces: Mesh[] = [];
      for (let start = 0; start < triangles.length; start += 3 * this.trianglesPerFrame) {
        const piece = new BufferGeometry();
        piece.setAttribute('position', geometry.getAttribute('position'));
        piece.setAttribute('normal', geometry.getAttribute('normal'));
        piece.setIndex(new BufferAttribute(triangles.subarray(start, start + 3 * this.trianglesPerFrame), 1));
        piece.boundingSphere = sphere.clone(); // (not computed again from all the positions)
        const m = new Mesh(piece, this.material);
        m.visible = false;
        pieces.push(m);
        this.scene.add(m);
      }
      const target = new WebGLRenderTarget(1, 1, { depthTexture: new DepthTexture(1, 1) });
      target.texture.colorSpace = SRGBColorSpace;
      this.detail = { proxy: object, pieces, uploaded: false, target, drawn: 0, changedAt: performance.now(), stale: true, full: false, fence: null, timer: 0 };
    }
    // 'later': a worker sends it (setPicking); until then nothing is picked and everything is seen.
    this.pickingLater = options.bvh === 'later';
    this.bvh = this.pickingLater ? null : new TriangleBVH(positions, triangles, options.bvh === 'later' ? undefined : options.bvh);
    this.shown = {
      positions,
      triangles,
      normals: geometry.getAttribute('normal').array as Float32Array,
      center: bb.getCenter(new Vector3()),
      box: [bb.min.x, bb.min.y, bb.min.z, bb.max.x, bb.max.y, bb.max.z],
      radius: Math.max(sphere.radius, 1e-9),
    };
    // Zoom limits around the mesh's size: not lost in space, not through the surface at once.
    this.controls.minDistance = this.shown.radius * 0.02;
    this.controls.maxDistance = this.shown.radius * 20;
    if (fit) this.fit();
    this.requestRender();
    return this.shown;
  }

  /** The picking hierarchy of the shown mesh, when setMesh was told it comes later. */
  setPicking(bvh: BVHArrays): void {
    if (!this.shown || !this.pickingLater) return;
    this.bvh = new TriangleBVH(this.shown.positions, this.shown.triangles, bvh);
    this.pickingLater = false;
  }

  /** The shown mesh's geometry (for a mode that deforms it or colours its vertices), or null. */
  get geometry(): BufferGeometry | null {
    return this.meshObject?.geometry ?? null;
  }

  /**
   * The shown mesh's positions changed in place (a deformation): normals, bounds and picking
   * follow (the picking hierarchy is built again on the next pick).
   */
  meshChanged(): void {
    const m = this.meshObject, shown = this.shown;
    if (!m || !shown) return;
    m.geometry.getAttribute('position').needsUpdate = true;
    m.geometry.computeVertexNormals();
    m.geometry.computeBoundingSphere();
    this.bvh = null;
    this.redrawMesh();
    this.requestRender();
  }

  clearMesh(): void {
    if (!this.meshObject) return;
    const d = this.detail;
    if (d) {
      clearTimeout(d.timer);
      if (d.fence) (this.renderer.getContext() as WebGL2RenderingContext).deleteSync(d.fence);
      this.scene.remove(d.proxy, ...d.pieces);
      d.proxy.geometry.dispose();
      for (const piece of d.pieces) piece.geometry.dispose();
      d.target.depthTexture?.dispose();
      d.target.dispose();
      this.detail = null;
    }
    this.scene.remove(this.meshObject);
    this.meshObject.geometry.dispose();
    this.meshObject = null;
    this.shown = null;
    this.bvh = null;
    this.pickingLater = false;
    this.requestRender();
  }

  setFlatShading(flat: boolean): void {
    if (this.material.flatShading === flat) return;
    this.material.flatShading = flat;
    this.material.needsUpdate = true;
    this.redrawMesh();
    this.requestRender();
  }

  /** Frames the mesh: its bounding box fills the view, seen from the front and a little above. */
  fit(): void {
    const m = this.shown;
    if (!m) return;
    const dir = new Vector3(0.3, 0.4, 1).normalize();
    const up = new Vector3(0, 1, 0);
    const right = new Vector3().crossVectors(up, dir).normalize();
    const camUp = new Vector3().crossVectors(dir, right);
    const tanY = Math.tan((this.camera.fov * Math.PI) / 360);
    const tanX = tanY * (this.size.x / Math.max(this.size.y, 1));
    // The camera sits at center + d·dir: every vertex (a sample of them on big meshes) must be
    // inside both half-angles of the view.
    let d = 0;
    const P = m.positions, stride = 3 * Math.max(1, Math.floor(P.length / 3 / 60000));
    const [cx, cy, cz] = [m.center.x, m.center.y, m.center.z];
    for (let i = 0; i + 2 < P.length; i += stride) {
      const x = P[i] - cx, y = P[i + 1] - cy, z = P[i + 2] - cz;
      const toward = x * dir.x + y * dir.y + z * dir.z;
      const across = Math.abs(x * right.x + y * right.y + z * right.z), above = Math.abs(x * camUp.x + y * camUp.y + z * camUp.z);
      d = Math.max(d, toward + across / tanX, toward + above / tanY);
    }
    d = Math.max(d * 1.12, m.radius * 0.1);
    this.controls.target.copy(m.center);
    this.camera.position.copy(m.center).addScaledVector(dir, d);
    this.camera.up.copy(up);
    this.controls.update();
    this.viewChanged();
  }

  /** Moves the camera towards the target by `factor` (> 1 zooms in). */
  zoom(factor: number): void {
    const offset = this.camera.position.clone().sub(this.controls.target).multiplyScalar(1 / factor);
    this.camera.position.copy(this.controls.target).add(offset);
    this.controls.update();
    this.viewChanged();
  }

  /** Canvas CSS pixels of a world point, with its depth in front of the camera (≤ 0: behind). */
  project(x: number, y: number, z: number): { sx: number; sy: number; depth: number } {
    const v = new Vector3(x, y, z);
    const depth = -v.clone().applyMatrix4(this.camera.matrixWorldInverse).z;
    v.project(this.camera);
    return { sx: ((v.x + 1) / 2) * this.size.x, sy: ((1 - v.y) / 2) * this.size.y, depth };
  }

  /** The ray under a canvas point (origin, unit direction). */
  ray(sx: number, sy: number): { origin: Vector3; dir: Vector3 } {
    this.camera.updateMatrixWorld();
    const ndc = new Vector3((sx / this.size.x) * 2 - 1, 1 - (sy / this.size.y) * 2, 0.5);
    const origin = this.camera.position.clone();
    const dir = ndc.unproject(this.camera).sub(origin).normalize();
    return { origin, dir };
  }

  /** The mesh point under a canvas point (nearest hit, either side), with the hit's position. */
  pick(sx: number, sy: number): (RayHit & { point: Vector3 }) | null {
    if (!this.shown || this.pickingLater) return null;
    this.bvh ??= new TriangleBVH(this.shown.positions, this.shown.triangles);
    const { origin, dir } = this.ray(sx, sy);
    const hit = this.bvh.raycast(origin.x, origin.y, origin.z, dir.x, dir.y, dir.z);
    return hit ? { ...hit, point: origin.addScaledVector(dir, hit.t) } : null;
  }

  /**
   * Whether a point on (or just above) the surface is seen: nothing of the mesh between it and
   * the camera, up to `slack` (world units) in front of it.
   */
  isVisible(x: number, y: number, z: number, slack: number): boolean {
    if (!this.shown || this.pickingLater) return true;
    this.bvh ??= new TriangleBVH(this.shown.positions, this.shown.triangles);
    const origin = this.camera.position;
    const dir = new Vector3(x, y, z).sub(origin);
    const length = dir.length();
    if (length <= slack) return true;
    dir.divideScalar(length);
    const hit = this.bvh.raycast(origin.x, origin.y, origin.z, dir.x, dir.y, dir.z, length - slack);
    return hit === null;
  }

  /** World units per CSS pixel at a point's depth (for pick tolerances and offsets). */
  worldPerPixel(depth: number): number {
    const fov = (this.camera.fov * Math.PI) / 180;
    return (2 * Math.tan(fov / 2) * Math.max(depth, 1e-9)) / Math.max(this.size.y, 1);
  }

  requestRender(): void {
    if (this.detail) this.detail.stale = true;
    this.frames.request();
  }

  /**
   * How much of the shown mesh the picture on screen has: all its triangles, or (a large mesh
   * while the camera moves, or until it is drawn in full) its proxy's; 0 without a mesh.
   */
  get pictureTriangles(): number {
    const m = this.meshObject;
    if (!m) return 0;
    const d = this.detail;
    return (d && !d.full ? d.proxy : m).geometry.index!.count / 3;
  }

  /** What the mesh looks like changed (the camera, the canvas size, the shading): a large one is drawn again. */
  private redrawMesh(): void {
    const d = this.detail;
    if (!d) return;
    d.drawn = 0;
    d.changedAt = performance.now();
  }

  /** Resolves once the next frame has been drawn. */
  nextFrame(): Promise<void> {
    return this.frames.next();
  }

  render(): void {
    if (!this.visible) return;
    this.updateClipping();
    if (this.detail) this.renderInPieces(this.detail);
    else this.renderer.render(this.scene, this.camera);
  }

  /**
   * A frame of a mesh too large to draw in one (see Detail): the proxy on screen until the mesh
   * is in the target, then the target and the layers; meanwhile, once the camera has been still
   * for SETTLE_MS, one piece of the mesh into the target per frame, each once the GPU is done with
   * the one before.
   */
  private renderInPieces(d: Detail): void {
    const r = this.renderer, all = d.pieces.length, gl = r.getContext() as WebGL2RenderingContext;
    const size = r.getDrawingBufferSize(new Vector2());
    if (d.target.width !== size.x || d.target.height !== size.y) {
      d.target.setSize(size.x, size.y);
      d.drawn = 0;
    }
    // (a fence's status changes between tasks: it is asked again next frame)
    if (d.fence && gl.getSyncParameter(d.fence, gl.SYNC_STATUS) === gl.SIGNALED) {
      gl.deleteSync(d.fence);
      d.fence = null;
      if (d.drawn >= all) d.stale = true; // all of it is drawn: on screen now
    }
    if (d.stale) {
      d.stale = false;
      d.full = d.drawn >= all && !d.fence;
      if (d.full) {
        this.copy ??= new FullScreenQuad(copyMaterial());
        const material = this.copy.material as ShaderMaterial;
        material.uniforms.tColor.value = d.target.texture;
        material.uniforms.tDepth.value = d.target.depthTexture;
        this.copy.render(r);
        r.autoClear = false;
        r.render(this.scene, this.camera);
        r.autoClear = true;
      } else {
        d.proxy.visible = true;
        r.render(this.scene, this.camera);
        d.proxy.visible = false;
      }
    }
    if (d.fence) {
      this.frames.request();
      return;
    }
    if (d.drawn >= all || this.orbiting) return;
    const wait = d.changedAt + SETTLE_MS - performance.now();
    if (wait > 0) {
      clearTimeout(d.timer);
      d.timer = setTimeout(() => this.frames.request(), wait);
      return;
    }
    const piece = d.pieces[d.drawn];
    this.layer.visible = false;
    piece.visible = true;
    r.setRenderTarget(d.target);
    if (!d.uploaded) {
      // A frame that draws nothing but uploads the vertex buffers (with the first piece's indices).
      piece.geometry.setDrawRange(0, 0);
      r.render(this.scene, this.camera);
      piece.geometry.setDrawRange(0, Infinity);
      d.uploaded = true;
    } else {
      if (d.drawn === 0) r.clear();
      r.autoClear = false;
      r.render(this.scene, this.camera);
      r.autoClear = true;
      d.drawn++;
    }
    r.setRenderTarget(null);
    piece.visible = false;
    this.layer.visible = true;
    d.fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
    gl.flush();
    this.frames.request();
  }

  dispose(): void {
    this.frames.cancel();
    this.controls.dispose();
    this.clearMesh();
    (this.copy?.material as ShaderMaterial | undefined)?.dispose();
    this.material.dispose();
    this.renderer.dispose();
    this.canvas.remove();
  }

  /** Near and far planes around what is in view, for depth precision at any zoom. */
  private updateClipping(): void {
    const m = this.shown;
    const distance = this.camera.position.distanceTo(m?.center ?? this.controls.target);
    const radius = m?.radius ?? 1;
    const near = Math.max(distance - radius * 1.5, distance * 0.002, radius * 1e-4);
    const far = distance + radius * 3;
    if (Math.abs(this.camera.near - near) > 1e-12 || Math.abs(this.camera.far - far) > 1e-12) {
      this.camera.near = near;
      this.camera.far = far;
      this.camera.updateProjectionMatrix();
    }
  }

  private viewChanged(): void {
    this.redrawMesh();
    this.events.emit('view', null);
    this.requestRender();
  }

  private resize(): void {
    const w = this.container.clientWidth, h = this.container.clientHeight;
    if (w === 0 || h === 0 || !this.visible) return;
    if (w === this.size.x && h === this.size.y) return;
    this.size.set(w, h);
    this.renderer.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.viewChanged();
  }

  private pointer(e: PointerEvent | MouseEvent): Pointer3D {
    const r = this.canvas.getBoundingClientRect();
    return { sx: e.clientX - r.left, sy: e.clientY - r.top, button: e.button, shiftKey: e.shiftKey, altKey: e.altKey, modKey: e.ctrlKey || e.metaKey, time: e.timeStamp };
  }

  private listen(canvas: HTMLCanvasElement): void {
    canvas.addEventListener('pointerdown', (e) => {
      canvas.focus({ preventScroll: true });
      if (this.gesture) return;
      const p = this.pointer(e);
      const claimed = e.button === 0 && !e.ctrlKey && !e.metaKey && (this.input?.pointerDown(p) ?? false);
      if (claimed) {
        this.controls.enabled = false; // until the gesture ends
        canvas.setPointerCapture(e.pointerId);
      }
      this.gesture = { id: e.pointerId, sx: p.sx, sy: p.sy, claimed, moved: false };
    });
    canvas.addEventListener('pointermove', (e) => {
      const g = this.gesture, p = this.pointer(e);
      if (!g || g.id !== e.pointerId) {
        if (!g) this.input?.hover(p);
        return;
      }
      if (!g.moved && Math.hypot(p.sx - g.sx, p.sy - g.sy) > CLICK_SLOP) g.moved = true;
      if (g.claimed && g.moved) this.input?.pointerDrag(p);
    });
    const end = (e: PointerEvent, cancelled: boolean) => {
      const g = this.gesture;
      if (!g || g.id !== e.pointerId) return;
      this.gesture = null;
      const p = this.pointer(e);
      if (g.claimed) {
        this.controls.enabled = true;
        if (canvas.hasPointerCapture(e.pointerId)) canvas.releasePointerCapture(e.pointerId);
        this.input?.pointerUp({ ...p, button: cancelled ? -1 : p.button }, g.moved);
      } else if (!g.moved && !cancelled && e.button === 0) this.input?.click(p);
    };
    canvas.addEventListener('pointerup', (e) => end(e, false));
    canvas.addEventListener('pointercancel', (e) => end(e, true));
    canvas.addEventListener('pointerleave', () => {
      if (!this.gesture) this.input?.pointerLeave();
    });
    canvas.addEventListener('dblclick', (e) => this.input?.doubleClick(this.pointer(e)));
    canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  }
}
