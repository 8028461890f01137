import { button, fileInput, segmented } from '../../ui/controls.js';
import { h } from '../../ui/dom.js';
import { facts, section } from '../../ui/panel.js';
import { rampGradient } from './colormap.js';
import type { Rig3DStatus } from './session.js';
import { MAX_LEVELS, MIN_LEVELS, type Skin3DWeights } from './spec.js';

export type GizmoMode = 'translate' | 'rotate' | 'scale';
export type Overlay3D = 'cage' | 'target' | 'naive' | 'errors';
export type Overlay3DFlags = Record<Overlay3D, boolean>;

/** A cage shipped in public/samples/cages. */
export interface CageSample {
  file: string;
  title: string;
}

export interface Skin3DPanelActions {
  openSample(file: string): void;
  openFile(file: File): void;
  setWeights(kind: Skin3DWeights): void;
  setLevels(levels: number): void;
  setGizmo(mode: GizmoMode): void;
  setOverlay(name: Overlay3D, on: boolean): void;
  resetPose(): void;
  removeHandle(): void;
  exportOBJ(): void;
  exportGLTF(): void;
}

const OVERLAYS: { name: Overlay3D; label: string; key: string; title: string }[] = [
  { name: 'cage', label: 'Cage wireframe', key: 'C', title: 'The control cage as a wireframe' },
  { name: 'target', label: 'Target', key: 'T', title: 'Linear blend skinning of the refined rest surface: what the posed cage tries to reproduce (translucent green)' },
  { name: 'naive', label: 'Naive result', key: 'N', title: 'The surface of the cage whose vertices are moved by the handles directly (translucent red)' },
  { name: 'errors', label: 'Error colours', key: 'E', title: 'Colour the surface (and the naive result) by each vertex’s distance to the target, as in Fig. 8 of the paper' },
];

/** A percentage with about two significant digits. */
export function percent(v: number): string {
  if (!Number.isFinite(v)) return '—';
  const p = v * 100;
  return `${p === 0 ? '0' : p >= 10 ? p.toFixed(1) : p >= 0.1 ? p.toFixed(2) : p.toPrecision(2)}%`;
}

/** 3D Skin mode's side panel: cage, rig and its progress, handles and gizmo, overlays, export. */
export class Skin3DPanel {
  readonly sections: HTMLElement[];
  readonly cageInput: HTMLInputElement;
  private readonly cageSelect = h('select', { class: 'wide-select', 'aria-label': 'Sample cage', 'data-testid': 'skin3d-sample' });
  private readonly cageFacts = facts(['File', 'Cage', 'Creases', 'Surface', 'Triangles']);
  private readonly weights: ReturnType<typeof segmented<Skin3DWeights>>;
  private readonly levels = h('input', { type: 'number', min: String(MIN_LEVELS), max: String(MAX_LEVELS), step: '1', class: 'num', 'data-testid': 'skin3d-levels', 'aria-label': 'Subdivision levels' });
  private readonly rigFacts = facts(['Handles', 'Selected', 'Rig', 'Update']);
  private readonly progress = h('div', { class: 'progress', 'data-testid': 'skin3d-progress', hidden: true, role: 'progressbar', 'aria-valuemin': '0', 'aria-valuemax': '100' });
  private readonly progressBar = h('div', { class: 'bar' });
  private readonly progressLabel = h('span', { class: 'label' });
  private readonly rigError = h('p', { class: 'rig-error', 'data-testid': 'skin3d-rig-error', hidden: true });
  private readonly gizmo: ReturnType<typeof segmented<GizmoMode>>;
  private readonly hint = h('p', { class: 'hint', 'data-testid': 'skin3d-hint' });
  private readonly overlayBoxes = new Map<Overlay3D, HTMLInputElement>();
  /** The colour scale of the error map: the mode shows it over the 3D view. */
  readonly legend = h('div', { class: 'skin3d-legend', 'data-testid': 'skin3d-legend', hidden: true });
  private readonly legendMax = h('span', {});
  private readonly errorFacts = facts(['Fit RMS', 'Naive RMS']);
  private readonly resetButton: HTMLButtonElement;
  private readonly removeButton: HTMLButtonElement;
  private readonly objButton: HTMLButtonElement;
  private readonly gltfButton: HTMLButtonElement;

  constructor(actions: Skin3DPanelActions) {
    this.cageInput = fileInput('.obj', 'skin3d-cage-input', (f) => actions.openFile(f));
    this.cageSelect.addEventListener('change', () => {
      if (this.cageSelect.value) actions.openSample(this.cageSelect.value);
      this.cageSelect.blur();
    });
    const open = button('Open cage…', 'Open a quad cage (OBJ, n-gons and OpenSubdiv crease tags) — or drop one on the window', () => this.cageInput.click(), 'small', 'skin3d-open');

    this.weights = segmented<Skin3DWeights>(
      'Weights',
      [
        ['shepard', 'Shepard', 'Inverse distance weights: immediate'],
        ['bbw', 'BBW', 'Bounded biharmonic weights (Jacobson et al. 2011): smooth and local, solved in the background'],
      ],
      (k) => actions.setWeights(k),
    );
    this.levels.addEventListener('change', () => {
      const v = Math.round(Number(this.levels.value));
      if (Number.isFinite(v)) actions.setLevels(Math.min(MAX_LEVELS, Math.max(MIN_LEVELS, v)));
      this.levels.blur();
    });
    this.progress.append(this.progressBar, this.progressLabel);

    this.gizmo = segmented<GizmoMode>(
      'Gizmo',
      [
        ['translate', 'Move', 'Drag the gizmo’s arrows or squares to move the selected handle (G)'],
        ['rotate', 'Turn', 'Drag the gizmo’s rings to turn the selected handle (R)'],
        ['scale', 'Scale', 'Drag the gizmo’s boxes to scale the selected handle (S)'],
      ],
      (m) => actions.setGizmo(m),
    );
    this.resetButton = button('Reset pose', 'Back to the rest pose: the selected handle, or all (0)', () => actions.resetPose(), 'small', 'skin3d-reset');
    this.removeButton = button('Remove handle', 'Remove the selected handle (Delete)', () => actions.removeHandle(), 'small', 'skin3d-remove');

    const overlays = h('div', { class: 'toggles' });
    for (const o of OVERLAYS) {
      const box = h('input', { type: 'checkbox', 'data-testid': `skin3d-overlay-${o.name}` });
      box.addEventListener('change', () => actions.setOverlay(o.name, box.checked));
      this.overlayBoxes.set(o.name, box);
      overlays.append(h('label', { class: 'toggle', title: o.title }, box, h('span', {}, o.label), h('kbd', {}, o.key)));
    }
    this.legend.append(
      h('div', { class: 'ramp', style: `background:${rampGradient()}` }),
      h('div', { class: 'ticks' }, h('span', {}, '0'), this.legendMax),
      h('div', { class: 'caption' }, 'distance to the target (% of the bounding-box diagonal)'),
    );

    this.objButton = button('Posed cage (OBJ)', 'Download the posed cage as OBJ (crease tags kept)', () => actions.exportOBJ(), 'small', 'skin3d-export-obj');
    this.gltfButton = button('Animation (glTF)', 'Download the refined surface as binary glTF (GLB): one morph target per keyframe and per tenth of a second between keyframes, played by a weights animation', () => actions.exportGLTF(), 'small', 'skin3d-export-gltf');

    this.sections = [
      section('Cage', h('div', { class: 'row' }, this.cageSelect, open), this.cageInput, this.cageFacts.el),
      section(
        'Rig',
        this.weights.el,
        h('div', { class: 'fields' }, h('label', { class: 'field', title: 'Catmull-Clark subdivision levels of the surface (1–4)' }, h('span', {}, 'Levels'), this.levels)),
        this.progress,
        this.rigError,
        this.rigFacts.el,
      ),
      section('Handles', this.hint, this.gizmo.el, h('div', { class: 'row' }, this.resetButton, this.removeButton)),
      section('Overlays', overlays, this.errorFacts.el),
      section('Export', h('div', { class: 'row' }, this.objButton, this.gltfButton)),
    ];
  }

  setSamples(samples: readonly CageSample[], current: string | null): void {
    this.cageSelect.replaceChildren(
      h('option', { value: '', disabled: true }, 'Sample cages…'),
      ...samples.map((s) => h('option', { value: s.file }, s.title)),
    );
    this.cageSelect.value = samples.some((s) => s.file === current) ? current! : '';
  }

  setCage(info: { file: string; vertices: number; faces: number; creases: number; refinedVertices: number; triangles: number } | null): void {
    this.cageFacts.set('File', info?.file ?? '—');
    this.cageFacts.set('Cage', info ? `${info.vertices} vertices, ${info.faces} faces` : '—');
    this.cageFacts.set('Creases', info ? `${info.creases} edges` : '—', 'Edges tagged with an OpenSubdiv crease (t crease … in the OBJ)');
    this.cageFacts.set('Surface', info && info.refinedVertices > 0 ? `${info.refinedVertices} vertices` : '—', 'The refined (subdivided) surface the rig fits');
    this.cageFacts.set('Triangles', info && info.triangles > 0 ? String(info.triangles) : '—');
    this.objButton.disabled = this.gltfButton.disabled = info === null;
  }

  setRig(o: { weights: Skin3DWeights; levels: number; handles: number; selected: number | null; status: Rig3DStatus; memory: number | null }): void {
    this.rigFacts.el.dataset.testid = 'skin3d-rig';
    this.weights.set(o.weights);
    if (document.activeElement !== this.levels) this.levels.value = String(o.levels);
    const s = o.status;
    this.rigFacts.set('Handles', String(o.handles));
    this.rigFacts.set('Selected', o.selected === null ? '—' : `handle ${o.selected + 1}`);
    const memory = o.memory === null ? '' : `, ${(o.memory / 2 ** 20).toFixed(1)} MB`;
    this.rigFacts.set('Rig', s.phase === 'building' ? 'solving weights…' : s.phase === 'error' ? 'failed' : s.ms === null ? '—' : `built in ${s.ms.toFixed(0)} ms${memory}`);
    const building = s.phase === 'building';
    this.progress.hidden = !building;
    if (building) {
      const pct = Math.round(100 * s.fraction);
      this.progressBar.style.width = `${pct}%`;
      this.progressLabel.textContent = pct > 0 ? `Solving BBW weights… ${pct}%` : 'Solving BBW weights…';
      this.progress.setAttribute('aria-valuenow', String(pct));
    }
    this.rigError.hidden = s.phase !== 'error';
    this.rigError.textContent = s.message ? `The rig could not be built: ${s.message}` : '';
    this.resetButton.disabled = o.handles === 0;
    this.removeButton.disabled = o.selected === null;
    this.hint.textContent =
      o.handles === 0
        ? 'Click on the surface to place a handle.'
        : o.selected === null
          ? 'Click a handle to pose it with the gizmo; click elsewhere on the surface to add one.'
          : 'Drag the gizmo to pose the handle (G move, R turn, S scale); click the surface to add another, Esc to deselect.';
  }

  /** Times of the last update: the pose (fit and subdivision) and the draw (geometry, normals, overlays). */
  setUpdate(poseMs: number | null, drawMs: number | null): void {
    const ms = (v: number) => `${v < 10 ? v.toFixed(1) : v.toFixed(0)} ms`;
    this.rigFacts.set('Update', poseMs === null ? '— (at rest)' : `pose ${ms(poseMs)}${drawMs === null ? '' : `, draw ${ms(drawMs)}`}`, 'Fitting the cage and subdividing it (pose), then updating the shown surface and overlays (draw)');
  }

  setGizmo(mode: GizmoMode): void {
    this.gizmo.set(mode);
  }

  setOverlays(flags: Overlay3DFlags): void {
    for (const [name, box] of this.overlayBoxes) box.checked = flags[name];
    this.legend.hidden = !flags.errors;
  }

  /** The error numbers of the current pose (null: no posed rig) and the colour scale's top. */
  setErrors(e: { fitRms: number; naiveRms: number; max: number } | null): void {
    this.errorFacts.set('Fit RMS', e ? percent(e.fitRms) : '—', 'RMS distance of the fitted surface to the target, over the bounding-box diagonal');
    this.errorFacts.set('Naive RMS', e ? percent(e.naiveRms) : '—', 'RMS distance of the naive surface to the target, over the bounding-box diagonal');
    this.legendMax.textContent = e ? percent(e.max) : '—';
  }
}
