import type { SvgDocument } from '../../src/index.js';
import { DocumentMode } from '../modes/document-mode.js';
import { EditMode } from '../modes/edit/edit-mode.js';
import { MorphMode } from '../modes/morph/morph-mode.js';
import { SkinMode } from '../modes/skin/skin-mode.js';
import { Skin3DMode } from '../modes/skin3d/skin3d-mode.js';
import { isMeshFile } from '../modes/surface/mesh-files.js';
import { SurfaceMode } from '../modes/surface/surface-mode.js';
import { ControlOverlay } from '../overlay/overlay.js';
import { h } from '../ui/dom.js';
import { SidePanel } from '../ui/panel.js';
import { StatusBar } from '../ui/statusbar.js';
import { MOD, Toolbar, type Sample } from '../ui/toolbar.js';
import { View2D, type ViewPointer } from '../view2d/view2d.js';
import { loadSession, saveSession, type SavedSession } from './autosave.js';
import { OpenDocumentCommand } from './commands.js';
import { download } from './download.js';
import { History } from './history.js';
import { fetchBytes, openSVG, readFile } from './loader.js';
import { ModeRegistry, type ModeContext } from './modes.js';
import { EditorState, type LoadedDocument } from './state.js';
import { messageOf } from './errors.js';

/** Lets the browser paint (e.g. a "loading" message) before a long synchronous step. */
function nextPaint(): Promise<void> {
  return new Promise((resolve) => requestAnimationFrame(() => setTimeout(resolve, 0)));
}

/**
 * The editor: owns the state, the undo history, the view with its overlay, the modes and the
 * UI around them, and wires them together. Everything the user does ends up here.
 */
export class Editor {
  readonly state = new EditorState();
  readonly history = new History();
  readonly view: View2D;
  readonly overlay: ControlOverlay;
  readonly modes: ModeRegistry;
  readonly toolbar: Toolbar;
  readonly status: StatusBar;
  readonly panel = new SidePanel();
  readonly skin = new SkinMode();
  readonly morph = new MorphMode();
  readonly surface = new SurfaceMode();
  readonly skin3d = new Skin3DMode();
  readonly edit = new EditMode();
  samples: Sample[] = [];
  /** What the drop hint says (Surface mode opens meshes). */
  private readonly dropText = h('div', {}, 'Drop an SVG file to open it');
  /** The strip under the view that modes fill (the skin timeline). */
  private readonly dock: HTMLElement;

  constructor(root: HTMLElement) {
    this.toolbar = new Toolbar({
      activateMode: (id) => this.modes.activate(id),
      openFile: (file) => void this.openFile(file),
      openSample: (sample) => void this.openSample(sample),
      exportSVG: () => this.exportSVG(),
      undo: () => this.undo(),
      redo: () => this.redo(),
      fit: () => this.fit(),
      zoom: (f) => this.zoom(f),
      toggleOverlay: () => this.state.setOverlay(!this.state.overlay),
    });
    this.status = new StatusBar(() => this.state.setError(null));
    const stage = h('main', { class: 'stage' });
    this.dock = h('div', { class: 'dock' });
    const dropHint = h('div', { class: 'drop-hint', 'aria-hidden': 'true' }, this.dropText);
    root.append(this.toolbar.el, h('div', { class: 'workspace' }, h('div', { class: 'stage-column' }, stage, this.dock), this.panel.el), this.status.el, dropHint);

    this.view = new View2D(stage);
    this.overlay = new ControlOverlay(this.view);
    const context = (): ModeContext => ({ state: this.state, history: this.history, view: this.view, overlay: this.overlay, panel: this.panel.body, dock: this.dock });
    this.modes = new ModeRegistry(context);
    this.modes.register(new DocumentMode());
    this.modes.register(this.skin);
    this.modes.register(this.surface);
    this.modes.register(this.skin3d);
    this.modes.register(this.morph);
    this.modes.register(this.edit);
    this.status.el.prepend(this.surface.statusEl);

    this.wire();
    this.listenKeys();
    this.listenDrops(dropHint);
    this.modes.activate('document');
    this.status.setDocument(null);
  }

  get doc(): SvgDocument | null {
    return this.state.doc;
  }

  /**
   * Opens bytes as a document: undoable, or as the starting document (no history entry). `hash`
   * keeps the identity of a restored document (autosave keys); by default it is computed.
   */
  async openBytes(bytes: Uint8Array, name: string, options: { undoable: boolean; hash?: string }): Promise<boolean> {
    this.state.setBusy(`Opening ${name}…`);
    try {
      await nextPaint();
      const loaded = await openSVG(bytes, name, options.hash);
      this.show(loaded, options.undoable);
      return true;
    } catch (err) {
      this.state.setError(messageOf(err));
      return false;
    } finally {
      this.state.setBusy(null);
    }
  }

  async openFile(file: File): Promise<boolean> {
    // In 3D Skin mode an OBJ is a cage.
    if (this.modes.active === this.skin3d && /\.obj$/i.test(file.name)) return this.skin3d.openFile(file);
    // Meshes go to Surface mode; there, an SVG is a drawing to place on the mesh.
    if (isMeshFile(file.name) || this.modes.active === this.surface) {
      if (this.modes.active !== this.surface) this.modes.activate(this.surface.id);
      return this.surface.openFile(file);
    }
    let bytes: Uint8Array;
    try {
      bytes = await readFile(file);
    } catch (err) {
      this.state.setError(messageOf(err));
      return false;
    }
    return this.openBytes(bytes, file.name, { undoable: true });
  }

  async openSample(sample: Sample, options = { undoable: true }): Promise<boolean> {
    try {
      const bytes = await fetchBytes(`samples/${sample.file}`, sample.file);
      return await this.openBytes(bytes, sample.file, options);
    } catch (err) {
      this.state.setError(messageOf(err));
      this.toolbar.setSample(this.state.current?.file ?? '');
      return false;
    }
  }

  /** Loads the sample list (public/samples/index.json). */
  async loadSamples(): Promise<Sample[]> {
    const bytes = await fetchBytes('samples/index.json', 'samples/index.json');
    const list = JSON.parse(new TextDecoder().decode(bytes)) as { samples: Sample[] };
    this.samples = list.samples;
    this.toolbar.setSamples(this.samples);
    return this.samples;
  }

  /** Fits the active view (the 3D view in Surface mode). */
  fit(): void {
    if (this.modes.active === this.surface) this.surface.fit();
    else if (this.modes.active === this.skin3d) this.skin3d.fit();
    else this.view.fit();
  }

  zoom(factor: number): void {
    if (this.modes.active === this.surface) this.surface.zoom(factor);
    else if (this.modes.active === this.skin3d) this.skin3d.zoom(factor);
    else this.view.zoom(factor);
  }

  undo(): void {
    this.history.undo();
  }

  redo(): void {
    this.history.redo();
  }

  /**
   * Reopens the document of the last visit (autosaved) in the mode it was in. Returns false when
   * there is none or it cannot be opened any more.
   */
  async restoreSession(saved: SavedSession | null = loadSession()): Promise<boolean> {
    if (!saved) return false;
    const ok = await this.openBytes(new TextEncoder().encode(saved.svg), saved.file, { undoable: false, hash: saved.hash });
    if (ok && this.modes.list.some((m) => m.id === saved.mode)) this.modes.activate(saved.mode);
    return ok;
  }

  /**
   * Downloads the document as SVG (shapes whose geometry changed are written back; the active
   * mode may add its data, e.g. the skin rig).
   */
  exportSVG(): void {
    const current = this.state.current;
    if (!current) return;
    let text: string;
    try {
      text = this.modes.active?.exportDocument?.(current) ?? current.doc.toSVG();
    } catch (err) {
      this.state.setError(`Export failed: ${messageOf(err)}`);
      return;
    }
    download(text, current.file.replace(/(\.svg)?$/i, '.svg'));
  }

  /** Remembers the open document and mode, so that a reload comes back to them. */
  private autosaveSession(): void {
    const current = this.state.current, mode = this.modes.active;
    if (!current || !mode) return;
    const problem = saveSession({ file: current.file, hash: current.hash, mode: mode.id, svg: new TextDecoder().decode(current.source) });
    if (problem) this.state.setMessage(`Not autosaved: ${problem}`);
  }

  private show(loaded: LoadedDocument, undoable: boolean): void {
    this.state.setError(null);
    if (undoable) this.history.execute(new OpenDocumentCommand(this.state, loaded));
    else this.state.setDocument(loaded);
  }

  private wire(): void {
    const { state, view, overlay, toolbar, status } = this;
    state.events.on('document', (current) => {
      view.setDocument(current?.doc ?? null);
      overlay.setDocument(current?.doc ?? null);
      status.setDocument(current);
      toolbar.setHasDocument(current !== null);
      toolbar.setSample(current?.file ?? '');
      document.title = current ? `${current.file} — splinekit` : 'splinekit editor';
      this.autosaveSession();
    });
    state.events.on('continuity', () => {
      overlay.recolor();
      status.setDocument(state.current);
    });
    state.events.on('selection', (sel) => overlay.setSelection(sel));
    state.events.on('overlay', (on) => {
      overlay.visible = on;
      toolbar.setOverlay(on);
      if (!on) overlay.setHover(null);
    });
    state.events.on('error', (message) => status.setError(message));
    state.events.on('busy', (what) => {
      status.setMessage(what ?? state.message);
      document.body.classList.toggle('busy', what !== null);
    });
    state.events.on('message', (text) => status.setMessage(state.busy ?? text));
    this.history.events.on('change', (history) => toolbar.setHistory(history));
    toolbar.setHistory(this.history);
    toolbar.setHasDocument(false);
    overlay.visible = state.overlay;
    toolbar.setOverlay(state.overlay);
    view.events.on('view', () => toolbar.setZoom(view.zoomLevel));
    this.modes.events.on('change', (mode) => {
      toolbar.setModes(this.modes.list, mode);
      this.panel.setHeading(mode.title, mode.description);
      this.panel.setModeKeys(mode.keys ?? []);
      const surface = mode === this.surface, skin3d = mode === this.skin3d;
      toolbar.fileInput.accept = surface ? SurfaceMode.accept : skin3d ? Skin3DMode.accept : '.svg,image/svg+xml';
      this.dropText.textContent = surface ? 'Drop a mesh to open it, or an SVG to place on the mesh' : skin3d ? 'Drop an OBJ cage to open it' : 'Drop an SVG file to open it';
      toolbar.setOpenTitle(
        surface
          ? 'Open a mesh (OBJ, OFF, PLY, STL, glTF, GLB), or an SVG to place on it — or drop one on the window'
          : skin3d
            ? `Open a quad cage (OBJ with n-gons and crease tags; ${MOD}O), or drop one on the window`
            : `Open an SVG file (${MOD}O), or drop one on the window`,
      );
      this.autosaveSession();
    });

    // Pointer input goes to the active mode; whatever it does not claim pans the view.
    const mode = () => this.modes.active;
    view.input = {
      pointerDown: (p: ViewPointer) => mode()?.pointerDown?.(p) ?? false,
      pointerMove: (p: ViewPointer) => mode()?.pointerMove?.(p),
      pointerUp: (p: ViewPointer) => mode()?.pointerUp?.(p),
      pointerLeave: () => mode()?.pointerLeave?.(),
      click: (p: ViewPointer) => mode()?.click?.(p),
    };
  }

  private listenKeys(): void {
    window.addEventListener('keydown', (e) => {
      const target = e.target;
      if (target instanceof HTMLInputElement || target instanceof HTMLTextAreaElement) return;
      const mod = e.ctrlKey || e.metaKey;
      const key = e.key.toLowerCase();
      let handled = true;
      if (mod && key === 'z' && !e.shiftKey) this.undo();
      else if (mod && ((key === 'z' && e.shiftKey) || key === 'y')) this.redo();
      else if (mod && key === 'o') this.toolbar.fileInput.click();
      else if (mod && key === 's') {
        if (this.modes.active === this.surface) this.surface.saveDrawingFile();
        else if (this.modes.active === this.skin3d) this.skin3d.saveFile();
        else this.exportSVG();
      }
      else if (mod || e.altKey || target instanceof HTMLSelectElement) handled = false;
      else if (key === 'f') this.fit();
      else if (key === 'h') this.state.setOverlay(!this.state.overlay);
      else if (key === '+' || key === '=') this.zoom(1.5);
      else if (key === '-' || key === '_') this.zoom(1 / 1.5);
      else if (key === '1') this.view.actualSize();
      else handled = this.modes.active?.keyDown?.(e) ?? false;
      if (handled) e.preventDefault();
    });
  }

  private listenDrops(hint: HTMLElement): void {
    let depth = 0;
    const hasFiles = (e: DragEvent) => e.dataTransfer?.types.includes('Files') ?? false;
    window.addEventListener('dragenter', (e) => {
      if (!hasFiles(e)) return;
      depth++;
      hint.classList.add('visible');
    });
    window.addEventListener('dragleave', (e) => {
      if (!hasFiles(e)) return;
      depth = Math.max(0, depth - 1);
      if (depth === 0) hint.classList.remove('visible');
    });
    window.addEventListener('dragover', (e) => {
      if (!hasFiles(e)) return;
      e.preventDefault();
      if (e.dataTransfer) e.dataTransfer.dropEffect = 'copy';
    });
    window.addEventListener('drop', (e) => {
      depth = 0;
      hint.classList.remove('visible');
      if (!hasFiles(e)) return;
      e.preventDefault();
      const file = e.dataTransfer?.files[0];
      if (file) void this.openFile(file);
    });
  }
}
