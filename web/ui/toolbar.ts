import type { History } from '../app/history.js';
import type { Mode } from '../app/modes.js';
import { ICONS, h, icon, noFocusOnClick } from './dom.js';

/** A drawing shipped in public/samples (listed in samples/index.json). */
export interface Sample {
  file: string;
  title: string;
}

export interface ToolbarActions {
  activateMode(id: string): void;
  openFile(file: File): void;
  openSample(sample: Sample): void;
  exportSVG(): void;
  undo(): void;
  redo(): void;
  fit(): void;
  zoom(factor: number): void;
  toggleOverlay(): void;
}

const isMac = /Mac|iPhone|iPad/.test(navigator.platform);
export const MOD = isMac ? '⌘' : 'Ctrl+';

/** The top bar: app name, mode switcher, file actions, history, view controls. */
export class Toolbar {
  readonly el: HTMLElement;
  /** The hidden file input behind "Open" (also used by tests and drag-and-drop fallbacks). */
  readonly fileInput: HTMLInputElement;
  private readonly modes: HTMLElement;
  private readonly samples: HTMLSelectElement;
  private readonly exportButton: HTMLButtonElement;
  private readonly undoButton: HTMLButtonElement;
  private readonly redoButton: HTMLButtonElement;
  private readonly overlayButton: HTMLButtonElement;
  private readonly zoomLabel: HTMLButtonElement;
  private sampleList: Sample[] = [];

  constructor(private readonly actions: ToolbarActions) {
    this.fileInput = h('input', { type: 'file', accept: '.svg,image/svg+xml', hidden: true, 'data-testid': 'file-input' });
    this.fileInput.addEventListener('change', () => {
      const file = this.fileInput.files?.[0];
      this.fileInput.value = ''; // choosing the same file again must fire 'change' again
      if (file) actions.openFile(file);
    });
    const button = (label: string, iconPath: string, title: string, onclick: () => void, extra: Record<string, string> = {}) => {
      const action = label.toLowerCase().replace(/\s+/g, '-');
      const b = h('button', { type: 'button', class: 'tool', title, 'aria-label': label, 'data-action': action, ...extra }, icon(iconPath), h('span', { class: 'label' }, label));
      b.addEventListener('click', onclick);
      return noFocusOnClick(b);
    };
    this.samples = h('select', { class: 'samples', title: 'Open a sample drawing', 'aria-label': 'Sample' });
    this.samples.addEventListener('change', () => {
      const sample = this.sampleList.find((s) => s.file === this.samples.value);
      if (sample) actions.openSample(sample);
      this.samples.blur(); // give the keys back to the canvas
    });
    this.exportButton = button('Export', ICONS.export, `Download the document as SVG (${MOD}S)`, () => actions.exportSVG());
    this.undoButton = button('Undo', ICONS.undo, `Undo (${MOD}Z)`, () => actions.undo());
    this.redoButton = button('Redo', ICONS.redo, `Redo (${MOD}Shift+Z)`, () => actions.redo());
    this.overlayButton = button('Points', ICONS.overlay, 'Show anchors and handles (H)', () => actions.toggleOverlay(), { 'aria-pressed': 'true' });
    this.zoomLabel = h('button', { type: 'button', class: 'zoom-label', title: 'Fit to the frame (F)' }, '100%');
    this.zoomLabel.addEventListener('click', () => actions.fit());
    noFocusOnClick(this.zoomLabel);
    this.modes = h('nav', { class: 'modes', 'aria-label': 'Modes' });

    this.el = h(
      'header',
      { class: 'toolbar' },
      h('div', { class: 'brand' }, h('span', { class: 'brand-mark' }), 'splinekit'),
      this.modes,
      h(
        'div',
        { class: 'group' },
        button('Open', ICONS.open, `Open an SVG file (${MOD}O), or drop one on the window`, () => this.fileInput.click()),
        this.samples,
        this.exportButton,
      ),
      h('div', { class: 'group' }, this.undoButton, this.redoButton),
      h('div', { class: 'spacer' }),
      h(
        'div',
        { class: 'group' },
        this.overlayButton,
        button('Fit', ICONS.fit, 'Fit to the frame (F)', () => actions.fit()),
        button('Zoom out', ICONS.zoomOut, 'Zoom out (−)', () => actions.zoom(1 / 1.5), { class: 'tool icon-only' }),
        this.zoomLabel,
        button('Zoom in', ICONS.zoomIn, 'Zoom in (+)', () => actions.zoom(1.5), { class: 'tool icon-only' }),
      ),
      this.fileInput,
    );
  }

  setModes(modes: readonly Mode[], active: Mode | null): void {
    this.modes.replaceChildren(
      ...modes.map((m) => {
        const tab = h('button', { type: 'button', class: 'mode', title: m.description, 'aria-pressed': String(m === active) }, m.title);
        tab.addEventListener('click', () => this.actions.activateMode(m.id));
        return noFocusOnClick(tab);
      }),
    );
  }

  setSamples(samples: Sample[]): void {
    this.sampleList = samples;
    this.samples.replaceChildren(
      h('option', { value: '', disabled: true }, 'Samples…'),
      ...samples.map((s) => h('option', { value: s.file }, s.title)),
    );
    this.samples.value = '';
  }

  /** Shows which sample is open ('' when the document is not a sample). */
  setSample(file: string): void {
    this.samples.value = this.sampleList.some((s) => s.file === file) ? file : '';
  }

  setHistory(history: History): void {
    this.undoButton.disabled = !history.canUndo;
    this.redoButton.disabled = !history.canRedo;
    this.undoButton.title = history.undoLabel ? `Undo ${history.undoLabel} (${MOD}Z)` : `Undo (${MOD}Z)`;
    this.redoButton.title = history.redoLabel ? `Redo ${history.redoLabel} (${MOD}Shift+Z)` : `Redo (${MOD}Shift+Z)`;
  }

  /** The Open button's tooltip (the active mode may open other files, e.g. meshes). */
  setOpenTitle(title: string): void {
    this.el.querySelector('[data-action="open"]')?.setAttribute('title', title);
  }

  setHasDocument(has: boolean): void {
    this.exportButton.disabled = !has;
  }

  setOverlay(on: boolean): void {
    this.overlayButton.setAttribute('aria-pressed', String(on));
  }

  setZoom(scale: number): void {
    const pct = scale * 100;
    this.zoomLabel.textContent = `${pct >= 10 ? Math.round(pct) : pct.toPrecision(2)}%`;
  }
}
