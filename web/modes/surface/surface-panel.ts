import type { MeshInfo } from '../../../src/index.js';
import { button, fileInput, segmented } from '../../ui/controls.js';
import { h } from '../../ui/dom.js';
import { facts, section } from '../../ui/panel.js';
import { MESH_ACCEPT } from './mesh-files.js';
import type { Scheme, Subdivision, SurfacePrefs } from './storage.js';

export type SurfaceTool = 'draw' | 'move' | 'rotate' | 'scale';

/** A file shipped in public/samples (a mesh, or an SVG to place). */
export interface SampleFile {
  file: string;
  title: string;
}

export interface SurfacePanelActions {
  openSample(file: string): void;
  openFile(file: File): void;
  setFlat(flat: boolean): void;
  setTool(tool: SurfaceTool): void;
  toggleSmooth(): void;
  insertPoint(): void;
  deletePoint(): void;
  deleteSpline(): void;
  setTrace(change: Partial<Pick<SurfacePrefs, 'scheme' | 'subdivision' | 'levels' | 'angle'>>): void;
  chooseSvg(file: string): void;
  chooseSvgFile(file: File): void;
  placeSvg(): void;
  setSvgPlacement(change: Partial<Pick<SurfacePrefs, 'svgSize' | 'svgRotation'>>): void;
  /** The slider was released: the resizing or turning of the last placement is one edit. */
  endSvgPlacement(): void;
  saveDrawing(): void;
  loadDrawing(file: File): void;
  clearDrawing(): void;
}

const TOOLS: [SurfaceTool, string, string][] = [
  ['draw', 'Draw', 'Click on the mesh to draw, drag points to edit them (Esc)'],
  ['move', 'Move', 'Drag on the mesh to move the selected spline along the surface (G)'],
  ['rotate', 'Rotate', 'Drag around the spline to turn it on the surface (R)'],
  ['scale', 'Scale', 'Drag away from (toward) the spline to grow (shrink) it (S)'],
];

function formatBytes(n: number): string {
  return n < 1024 ? `${n} B` : n < 2 ** 20 ? `${(n / 1024).toFixed(0)} KB` : `${(n / 2 ** 20).toFixed(1)} MB`;
}

/** Surface mode's side panel: mesh, tools and selection, tracing options, SVG placement, files. */
export class SurfacePanel {
  readonly sections: HTMLElement[];
  readonly meshInput: HTMLInputElement;
  private readonly meshSelect = h('select', { class: 'wide-select', 'aria-label': 'Sample mesh', 'data-testid': 'surface-mesh-sample' });
  private readonly meshFacts = facts(['File', 'Triangles', 'Vertices', 'Surface', 'Memory']);
  private readonly warnings = h('ul', { class: 'warnings', 'data-testid': 'surface-warnings' });
  private readonly flat: HTMLInputElement;
  private readonly tools: ReturnType<typeof segmented<SurfaceTool>>;
  private readonly hint = h('p', { class: 'hint', 'data-testid': 'surface-hint' });
  private readonly selFacts = facts(['Splines', 'Selected']);
  private readonly smoothButton: HTMLButtonElement;
  private readonly insertButton: HTMLButtonElement;
  private readonly deletePointButton: HTMLButtonElement;
  private readonly deleteSplineButton: HTMLButtonElement;
  private readonly scheme: ReturnType<typeof segmented<Scheme>>;
  private readonly subdivision: ReturnType<typeof segmented<Subdivision>>;
  private readonly levels = h('input', { type: 'number', min: '1', max: '8', step: '1', class: 'num', 'data-testid': 'surface-levels', 'aria-label': 'Subdivision levels' });
  private readonly angle = h('input', { type: 'number', min: '0.5', max: '45', step: '0.5', class: 'num', 'data-testid': 'surface-angle', 'aria-label': 'Angle threshold in degrees' });
  private readonly levelsRow: HTMLElement;
  private readonly angleRow: HTMLElement;
  private readonly traceFacts = facts(['Last trace', 'Points']);
  private readonly svgSelect = h('select', { class: 'wide-select', 'aria-label': 'SVG to place', 'data-testid': 'surface-svg-select' });
  private readonly svgSize = h('input', { type: 'range', min: '2', max: '150', step: '1', 'data-testid': 'surface-svg-size', 'aria-label': 'Width of the drawing on the mesh' });
  private readonly svgSizeLabel = h('span', { class: 'value' });
  private readonly svgRotation = h('input', { type: 'range', min: '-180', max: '180', step: '1', 'data-testid': 'surface-svg-rotation', 'aria-label': 'Rotation of the drawing' });
  private readonly svgRotationLabel = h('span', { class: 'value' });
  private readonly placeButton: HTMLButtonElement;
  private readonly saveButton: HTMLButtonElement;
  private readonly clearButton: HTMLButtonElement;
  private svgFiles: SampleFile[] = [];
  private chosenSvgFile: string | null = null;

  constructor(actions: SurfacePanelActions) {
    this.meshInput = fileInput(MESH_ACCEPT, 'surface-mesh-input', (f) => actions.openFile(f));
    this.meshSelect.addEventListener('change', () => {
      if (this.meshSelect.value) actions.openSample(this.meshSelect.value);
      this.meshSelect.blur();
    });
    this.flat = h('input', { type: 'checkbox', 'data-testid': 'surface-flat' });
    this.flat.addEventListener('change', () => actions.setFlat(this.flat.checked));
    const openMesh = button('Open mesh…', 'Open an OBJ, OFF, PLY, STL, glTF or GLB file (or drop one on the window)', () => this.meshInput.click(), 'small', 'surface-open-mesh');

    this.tools = segmented('Tool', TOOLS, (t) => actions.setTool(t));
    this.smoothButton = button('Smooth', 'Make the selected anchor smooth (collinear handles) or a corner (C)', () => actions.toggleSmooth(), 'small', 'surface-smooth');
    this.insertButton = button('Insert point', 'Insert an anchor in the middle of the segment after the selected anchor (or Alt+click on a curve)', () => actions.insertPoint(), 'small', 'surface-insert');
    this.deletePointButton = button('Delete point', 'Delete the selected anchor (Delete)', () => actions.deletePoint(), 'small', 'surface-delete-point');
    this.deleteSplineButton = button('Delete spline', 'Delete the selected spline', () => actions.deleteSpline(), 'small', 'surface-delete-spline');

    this.scheme = segmented<Scheme>(
      'Scheme',
      [
        ['olr', 'OLR', 'Open Lane-Riesenfeld: subdivides the control polygon with geodesic averages (b/Surf §4.2)'],
        ['rdc', 'RDC', 'Recursive de Casteljau: splits each segment in half with geodesic de Casteljau (b/Surf §4.1)'],
      ],
      (s) => actions.setTrace({ scheme: s }),
    );
    this.subdivision = segmented<Subdivision>(
      'Subdivision',
      [
        ['uniform', 'Uniform', 'Subdivide every segment the same number of times'],
        ['adaptive', 'Adaptive', 'Subdivide until the control polygon turns less than the angle threshold'],
      ],
      (s) => actions.setTrace({ subdivision: s }),
    );
    this.levels.addEventListener('change', () => {
      const v = Math.round(Number(this.levels.value));
      if (Number.isFinite(v)) actions.setTrace({ levels: Math.min(8, Math.max(1, v)) });
    });
    this.angle.addEventListener('change', () => {
      const v = Number(this.angle.value);
      if (Number.isFinite(v) && v > 0) actions.setTrace({ angle: Math.min(45, Math.max(0.5, v)) });
    });
    this.levelsRow = h('label', { class: 'field' }, h('span', {}, 'Levels'), this.levels);
    this.angleRow = h('label', { class: 'field' }, h('span', {}, 'Angle (°)'), this.angle);

    const svgInput = fileInput('.svg,image/svg+xml', 'surface-svg-input', (f) => actions.chooseSvgFile(f));
    this.svgSelect.addEventListener('change', () => {
      const v = this.svgSelect.value;
      if (v === '__file__') {
        svgInput.click();
        this.svgSelect.value = this.chosenSvgFile ?? '';
      } else if (v) actions.chooseSvg(v);
      this.svgSelect.blur();
    });
    this.svgSize.addEventListener('input', () => actions.setSvgPlacement({ svgSize: Number(this.svgSize.value) / 100 }));
    this.svgRotation.addEventListener('input', () => actions.setSvgPlacement({ svgRotation: Number(this.svgRotation.value) }));
    for (const slider of [this.svgSize, this.svgRotation]) slider.addEventListener('change', () => actions.endSvgPlacement());
    this.placeButton = button('Place on the mesh…', 'Then click where its centre goes', () => actions.placeSvg(), 'wide', 'surface-place-svg');

    const loadInput = fileInput('.json,application/json', 'surface-drawing-input', (f) => actions.loadDrawing(f));
    this.saveButton = button('Save JSON', 'Download the drawing as JSON: its splines as mesh points on this mesh (Ctrl+S)', () => actions.saveDrawing(), 'small', 'surface-save');
    const loadButton = button('Load JSON…', 'Open a drawing saved as JSON (for this mesh)', () => loadInput.click(), 'small', 'surface-load');
    this.clearButton = button('Clear', 'Delete every spline', () => actions.clearDrawing(), 'small', 'surface-clear');
    this.meshFacts.el.dataset.testid = 'surface-mesh-facts';
    this.traceFacts.el.dataset.testid = 'surface-trace-facts';
    this.selFacts.el.dataset.testid = 'surface-selection';

    this.sections = [
      section(
        'Mesh',
        h('div', { class: 'row' }, this.meshSelect, openMesh),
        this.meshInput,
        this.meshFacts.el,
        this.warnings,
        h('label', { class: 'toggle', title: 'Shade each triangle flat (shows the tessellation)' }, this.flat, h('span', {}, 'Flat shading')),
      ),
      section(
        'Splines',
        this.tools.el,
        this.hint,
        this.selFacts.el,
        h('div', { class: 'row' }, this.smoothButton, this.insertButton),
        h('div', { class: 'row' }, this.deletePointButton, this.deleteSplineButton),
      ),
      section('Tracing', this.scheme.el, this.subdivision.el, h('div', { class: 'fields' }, this.levelsRow, this.angleRow), this.traceFacts.el),
      section(
        'Place an SVG',
        h('div', { class: 'row' }, this.svgSelect),
        svgInput,
        h('label', { class: 'field slider' }, h('span', {}, 'Size'), this.svgSize, this.svgSizeLabel),
        h('label', { class: 'field slider' }, h('span', {}, 'Rotation'), this.svgRotation, this.svgRotationLabel),
        h('div', { class: 'row' }, this.placeButton),
        h('p', { class: 'hint small' }, 'Control points are mapped from the drawing’s centre along geodesics (polar → normal coordinates) and traced; every spline stays editable.'),
      ),
      section('Drawing', h('div', { class: 'row' }, this.saveButton, loadButton, this.clearButton), loadInput),
    ];
  }

  setMeshSamples(samples: SampleFile[], current: string | null): void {
    this.meshSelect.replaceChildren(h('option', { value: '', disabled: true }, 'Sample meshes…'), ...samples.map((s) => h('option', { value: s.file }, s.title)));
    this.meshSelect.value = current && samples.some((s) => s.file === current) ? current : '';
  }

  setSvgSamples(samples: SampleFile[]): void {
    this.svgFiles = samples;
    this.renderSvgOptions();
  }

  /** The SVG chosen for placement (a sample's file name, or a user file's name). */
  setSvgChoice(name: string | null, fromFile: boolean): void {
    if (fromFile) this.chosenSvgFile = name;
    this.renderSvgOptions();
    this.svgSelect.value = name ?? '';
  }

  private renderSvgOptions(): void {
    const value = this.svgSelect.value;
    this.svgSelect.replaceChildren(
      h('option', { value: '', disabled: true }, 'Choose an SVG…'),
      ...this.svgFiles.map((s) => h('option', { value: s.file }, s.title)),
      ...(this.chosenSvgFile && !this.svgFiles.some((s) => s.file === this.chosenSvgFile) ? [h('option', { value: this.chosenSvgFile }, this.chosenSvgFile)] : []),
      h('option', { value: '__file__' }, 'SVG file…'),
    );
    this.svgSelect.value = value;
  }

  setMesh(file: string | null, info: MeshInfo | null, sample: boolean): void {
    if (!file || !info) {
      for (const n of ['File', 'Triangles', 'Vertices', 'Surface', 'Memory']) this.meshFacts.set(n, '—');
      this.warnings.replaceChildren();
      return;
    }
    if (!sample) this.meshSelect.value = '';
    else this.meshSelect.value = file;
    this.meshFacts.set('File', file, file);
    this.meshFacts.set('Triangles', info.faces.toLocaleString('en-US'));
    this.meshFacts.set('Vertices', `${info.usedVertices.toLocaleString('en-US')}${info.vertices !== info.usedVertices ? ` of ${info.vertices.toLocaleString('en-US')}` : ''}`);
    const surface = [
      info.components === 1 ? '1 piece' : `${info.components} pieces`,
      info.boundaryLoops === 0 ? 'closed' : `${info.boundaryLoops} boundar${info.boundaryLoops === 1 ? 'y' : 'ies'}`,
    ];
    if (info.nonManifoldEdges + info.nonManifoldVertices > 0) surface.push('non-manifold');
    this.meshFacts.set('Surface', surface.join(', '));
    const guide = info.guideFaces > 0 ? `, including a coarse guide of ${info.guideFaces.toLocaleString('en-US')} triangles that finds long paths' way` : '';
    this.meshFacts.set('Memory', formatBytes(info.bytes), `Bytes the mesh structures take in the WebAssembly core${guide}`);
    this.warnings.replaceChildren(...(info.warnings.length > 0 ? info.warnings.map((w) => h('li', {}, w)) : [h('li', { class: 'none' }, 'No warnings')]));
  }

  setPrefs(p: SurfacePrefs, scale: number | null): void {
    this.flat.checked = p.flat;
    this.scheme.set(p.scheme);
    this.subdivision.set(p.subdivision);
    this.levels.value = String(p.levels);
    this.angle.value = String(p.angle);
    this.levelsRow.hidden = p.subdivision !== 'uniform';
    this.angleRow.hidden = p.subdivision !== 'adaptive';
    this.svgSize.value = String(Math.round(p.svgSize * 100));
    this.svgSizeLabel.textContent = `${Math.round(p.svgSize * 100)}%${scale ? ` · ${(p.svgSize * scale).toPrecision(3)}` : ''}`;
    this.svgSize.title = 'Width of the drawing, as a fraction of the mesh’s bounding-box diagonal';
    this.svgRotation.value = String(Math.round(p.svgRotation));
    this.svgRotationLabel.textContent = `${Math.round(p.svgRotation)}°`;
  }

  setTool(tool: SurfaceTool, hint: string): void {
    this.tools.set(tool);
    this.hint.textContent = hint;
  }

  setSelection(s: { splines: number; selected: string; smooth: boolean | null; canInsert: boolean; canDeletePoint: boolean; canDeleteSpline: boolean }): void {
    this.selFacts.set('Splines', String(s.splines));
    this.selFacts.set('Selected', s.selected);
    this.smoothButton.disabled = s.smooth === null;
    this.smoothButton.textContent = s.smooth ? 'Make corner' : 'Make smooth';
    this.insertButton.disabled = !s.canInsert;
    this.deletePointButton.disabled = !s.canDeletePoint;
    this.deleteSplineButton.disabled = !s.canDeleteSpline;
    this.saveButton.disabled = s.splines === 0;
    this.clearButton.disabled = s.splines === 0;
  }

  setTrace(last: string, points: string): void {
    this.traceFacts.set('Last trace', last);
    this.traceFacts.set('Points', points);
  }

  setPlacing(placing: boolean, canPlace: boolean): void {
    this.placeButton.disabled = !canPlace;
    this.placeButton.setAttribute('aria-pressed', String(placing));
    this.placeButton.textContent = placing ? 'Click on the mesh… (Esc cancels)' : 'Place on the mesh…';
  }
}
