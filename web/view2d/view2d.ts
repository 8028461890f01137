import { Group, OrthographicCamera, Scene, WebGLRenderer } from 'three';
import type { SvgDocument } from '../../src/index.js';
import { Emitter } from '../app/events.js';
import { SvgLayer, type DrawingStats, type ShowOptions } from './svg-layer.js';
import { Viewport } from './viewport.js';
import { FrameScheduler } from '../app/frames.js';

/** A pointer on the view, in screen (canvas CSS pixels) and document coordinates. */
export interface ViewPointer {
  sx: number;
  sy: number;
  x: number;
  y: number;
  button: number;
  shiftKey: boolean;
  altKey: boolean;
  /** Ctrl, or Cmd on macOS. */
  modKey: boolean;
}

/** Who gets pointer input that is not a pan (the active mode, through the editor). */
export interface ViewInput {
  pointerDown(p: ViewPointer): boolean;
  pointerMove?(p: ViewPointer): void;
  pointerUp?(p: ViewPointer): void;
  pointerLeave?(): void;
  click(p: ViewPointer): void;
}

export interface ViewEvents extends Record<string, unknown> {
  /** The view transform changed (pan, zoom, fit, resize). */
  view: Viewport;
  /** A frame was drawn. */
  render: number;
  /** The drawing was mounted or updated from the model. */
  drawing: DrawingStats;
}

/** Pixels the pointer may travel and still make a click. */
const CLICK_SLOP = 4;

/**
 * The 2D view: the document drawn by the browser from its spline model (SvgLayer), under a
 * transparent three.js orthographic view of document space (y pointing down, as in SVG) that
 * draws the overlays, rendering on demand. Pan with a drag on empty space, the middle button or Space + drag; zoom
 * with the wheel around the cursor; `fit()` shows the document's frame.
 */
export class View2D {
  readonly events = new Emitter<ViewEvents>();
  readonly viewport = new Viewport();
  readonly renderer: WebGLRenderer;
  readonly scene = new Scene();
  readonly camera = new OrthographicCamera(-1, 1, -1, 1, -10, 10);
  /** Where overlays add their objects (drawn above the document). */
  readonly overlayLayer = new Group();
  input: ViewInput | null = null;

  /** The document as the browser draws it. */
  readonly drawing: SvgLayer;
  private doc: SvgDocument | null = null;
  private readonly frames = new FrameScheduler((time) => {
    this.render();
    this.events.emit('render', time);
  });
  private spaceDown = false;
  private drag: { id: number; sx: number; sy: number; lastX: number; lastY: number; pan: boolean; moved: boolean } | null = null;

  constructor(readonly container: HTMLElement) {
    this.drawing = new SvgLayer(container);
    // No multisampling (the overlays smooth their own edges) and no preserved buffer: both cost a
    // full-canvas pass per frame with software WebGL, which is what many machines have.
    this.renderer = new WebGLRenderer({ antialias: false, alpha: true, powerPreference: 'high-performance' });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setClearColor(0x000000, 0);
    const canvas = this.renderer.domElement;
    canvas.className = 'view2d-canvas';
    canvas.tabIndex = 0;
    canvas.setAttribute('aria-label', 'Drawing');
    container.appendChild(canvas);

    this.overlayLayer.renderOrder = 10;
    this.scene.add(this.overlayLayer);

    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
    this.listen(canvas);
  }

  get canvas(): HTMLCanvasElement {
    return this.renderer.domElement;
  }

  /** Shows or hides the view (its drawing and its canvas), e.g. while a 3D view takes the stage. */
  setVisible(visible: boolean): void {
    this.canvas.style.display = visible ? 'block' : 'none';
    this.drawing.host.hidden = !visible;
  }

  /** Shows a document (or nothing), fitted to its frame. */
  setDocument(doc: SvgDocument | null): void {
    this.doc = doc;
    if (doc) this.viewport.fit(doc.frame);
    this.rebuild();
    this.viewChanged();
  }

  /**
   * Draws another version of the shown document (e.g. a deformed copy with the same frame),
   * keeping the view where it is: only the shapes that changed are rewritten. `live` during a
   * drag or playback (see SvgLayer.show): a show that is not live follows when it ends.
   */
  showDrawing(doc: SvgDocument, options: ShowOptions = {}): void {
    this.doc = doc;
    this.rebuild(options);
  }

  /** The document being drawn. */
  get drawn(): SvgDocument | null {
    return this.doc;
  }

  /** Draws the shown document's current splines (after geometry changed). */
  rebuild(options: ShowOptions = {}): void {
    // The WebGL canvas holds only overlays, which ask for their own frames when they change: a
    // frame of it here would redraw and read back an unchanged canvas (software GL) per pose.
    this.events.emit('drawing', this.drawing.show(this.doc, this.viewport, options));
  }

  fit(): void {
    if (!this.doc) return;
    this.viewport.fit(this.doc.frame);
    this.viewChanged();
  }

  /** Shows the document's frame with its top-left corner at canvas pixel (sx, sy), `width` pixels wide. */
  placeFrame(sx: number, sy: number, width: number): void {
    if (!this.doc) return;
    this.viewport.place(this.doc.frame, sx, sy, width);
    this.viewChanged();
  }

  /** Zooms by `factor` around a screen point (default: the middle of the view). */
  zoom(factor: number, sx = this.viewport.width / 2, sy = this.viewport.height / 2): void {
    this.viewport.zoomAt(factor, sx, sy);
    this.viewChanged();
  }

  /** Screen pixels per document unit at 100% (the document's width over its frame's width). */
  get naturalScale(): number {
    return this.doc ? this.doc.width / this.doc.frame[2] : 1;
  }

  /** Zoom relative to the document's natural size (1 = 100%). */
  get zoomLevel(): number {
    return this.viewport.scale / this.naturalScale;
  }

  /** Shows the document at its natural size (100%), around the middle of the view. */
  actualSize(): void {
    this.zoom(this.naturalScale / this.viewport.scale);
  }

  /** Screen position (canvas CSS pixels) of a document point. */
  toScreen(x: number, y: number): [number, number] {
    return this.viewport.toScreen(x, y);
  }

  requestRender(): void {
    this.frames.request();
  }

  /** Resolves once the next frame has been drawn. */
  nextFrame(): Promise<void> {
    return this.frames.next();
  }

  /** Draws now (normally use requestRender). */
  render(): void {
    const [left, right, top, bottom] = this.viewport.planes();
    // top < bottom: the camera maps document y downwards, as on screen.
    Object.assign(this.camera, { left, right, top, bottom });
    this.camera.updateProjectionMatrix();
    this.renderer.render(this.scene, this.camera);
  }

  private viewChanged(): void {
    this.drawing.setView(this.viewport);
    this.events.emit('view', this.viewport);
    this.requestRender();
  }

  private resize(): void {
    this.canvasRect = null;
    const w = this.container.clientWidth, h = this.container.clientHeight;
    if (w === 0 || h === 0) return;
    const first = this.viewport.width <= 1;
    this.viewport.resize(w, h);
    this.renderer.setSize(w, h);
    if (first && this.doc) this.viewport.fit(this.doc.frame);
    this.viewChanged();
  }

  /**
   * The canvas's place on the page, read when a gesture starts and after a resize: reading it on
   * every move would lay out the drawing the last frame changed before the move is handled.
   */
  private canvasRect: DOMRect | null = null;

  private pointer(e: PointerEvent | MouseEvent): ViewPointer {
    const r = (this.canvasRect ??= this.canvas.getBoundingClientRect());
    const sx = e.clientX - r.left, sy = e.clientY - r.top;
    const [x, y] = this.viewport.toDoc(sx, sy);
    return { sx, sy, x, y, button: e.button, shiftKey: e.shiftKey, altKey: e.altKey, modKey: e.ctrlKey || e.metaKey };
  }

  private listen(canvas: HTMLCanvasElement): void {
    canvas.addEventListener('pointerdown', (e) => {
      if (this.drag) return;
      this.canvasRect = null;
      canvas.focus({ preventScroll: true });
      if (e.button > 1) return; // the right button's context menu stays the browser's
      const p = this.pointer(e);
      // Middle button and Space + drag always pan; a left drag pans unless the mode claims it.
      const pan = e.button === 1 || this.spaceDown || !this.input?.pointerDown(p);
      this.drag = { id: e.pointerId, sx: p.sx, sy: p.sy, lastX: e.clientX, lastY: e.clientY, pan, moved: false };
      canvas.setPointerCapture(e.pointerId);
      if (e.button === 1) e.preventDefault();
      this.updateCursor();
    });
    canvas.addEventListener('pointermove', (e) => {
      const d = this.drag;
      if (!d || d.id !== e.pointerId) {
        if (!d) this.input?.pointerMove?.(this.pointer(e));
        return;
      }
      const p = this.pointer(e);
      if (!d.moved && Math.hypot(p.sx - d.sx, p.sy - d.sy) > CLICK_SLOP) {
        d.moved = true;
        this.updateCursor();
      }
      if (d.pan && d.moved) {
        this.viewport.panBy(e.clientX - d.lastX, e.clientY - d.lastY);
        this.viewChanged();
      } else if (!d.pan) {
        this.input?.pointerMove?.(p);
      }
      d.lastX = e.clientX;
      d.lastY = e.clientY;
    });
    const end = (e: PointerEvent, cancelled: boolean) => {
      const d = this.drag;
      if (!d || d.id !== e.pointerId) return;
      this.drag = null;
      const p = this.pointer(e);
      if (!d.pan) this.input?.pointerUp?.(p);
      else if (!d.moved && !cancelled && e.button === 0) this.input?.click(p);
      this.updateCursor();
    };
    canvas.addEventListener('pointerleave', () => {
      if (!this.drag) this.input?.pointerLeave?.();
    });
    canvas.addEventListener('pointerup', (e) => end(e, false));
    canvas.addEventListener('pointercancel', (e) => end(e, true));
    canvas.addEventListener('auxclick', (e) => e.preventDefault());
    canvas.addEventListener(
      'wheel',
      (e) => {
        e.preventDefault();
        const p = this.pointer(e);
        const pixels = e.deltaMode === 1 ? e.deltaY * 16 : e.deltaMode === 2 ? e.deltaY * this.viewport.height : e.deltaY;
        // Pinch gestures arrive as ctrl+wheel with small deltas: make them a little faster.
        this.zoom(Math.exp(-pixels * (e.ctrlKey ? 0.01 : 0.0015)), p.sx, p.sy);
      },
      { passive: false },
    );
    const typing = (e: KeyboardEvent) => e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement || e.target instanceof HTMLTextAreaElement;
    window.addEventListener('keydown', (e) => {
      if (e.code === 'Space' && !typing(e) && !e.repeat) {
        this.spaceDown = true;
        this.updateCursor();
        if (e.target === document.body || e.target === canvas) e.preventDefault();
      }
    });
    window.addEventListener('keyup', (e) => {
      if (e.code === 'Space') {
        this.spaceDown = false;
        this.updateCursor();
      }
    });
    window.addEventListener('scroll', () => (this.canvasRect = null), { capture: true, passive: true });
    window.addEventListener('blur', () => {
      this.spaceDown = false;
      this.updateCursor();
    });
  }

  private updateCursor(): void {
    const panning = this.drag?.pan && this.drag.moved;
    this.canvas.style.cursor = panning ? 'grabbing' : this.spaceDown ? 'grab' : '';
  }
}
