import { h, noFocusOnClick } from '../../ui/dom.js';
import { facts, section } from '../../ui/panel.js';
import { HEAT, SKIN_COLORS, WEIGHT } from './colors.js';
import type { PoseErrors, RigStatus } from './session.js';
import type { WeightKind } from './spec.js';

export type SkinTool = 'rig' | 'pose';
export type LayerName = 'target' | 'heat' | 'naive' | 'field';
export type LayerFlags = Record<LayerName, boolean>;

export interface SkinPanelActions {
  setTool(tool: SkinTool): void;
  setWeights(kind: WeightKind): void;
  setFlexible(on: boolean): void;
  setLayer(name: LayerName, on: boolean): void;
  resetPose(): void;
  removeHandle(): void;
  exportPosed(): void;
  exportAnimated(): void;
}

const WEIGHT_LABELS: Record<WeightKind, [string, string]> = {
  shepard: ['Shepard', 'Inverse distance weights |p − h|⁻²: immediate, reach through gaps'],
  harmonic: ['Harmonic', 'Harmonic weights on a triangulation of the outline: smooth, stay inside the shape (computed in the background)'],
  bbw: ['BBW', 'Bounded biharmonic weights (Jacobson et al. 2011): smooth and local (computed in the background)'],
};

const LAYERS: { name: LayerName; label: string; key: string; title: string }[] = [
  { name: 'target', label: 'Target', key: 'T', title: 'The deformation the curves try to follow (linear blend skinning of dense samples), dashed' },
  { name: 'heat', label: 'Error heat map', key: 'E', title: 'Color the target by each curve’s distance to it: red at the maximum, purple at the minimum' },
  { name: 'naive', label: 'Naive result', key: 'N', title: 'The control points moved by the deformation directly (the baseline the paper improves on)' },
  { name: 'field', label: 'Weight field', key: 'W', title: 'Color the curves by the selected handle’s weight: dark at 0 … yellow at 1' },
];

function fmt(v: number): string {
  if (!Number.isFinite(v)) return String(v);
  if (v === 0) return '0';
  return Math.abs(v) >= 100 ? v.toFixed(0) : Math.abs(v) >= 1 ? v.toFixed(2) : v.toPrecision(2);
}

/** The skin mode's side panel: tools, weights and their progress, layers, error numbers, export. */
export class SkinPanel {
  readonly sections: HTMLElement[];
  private readonly toolButtons = new Map<SkinTool, HTMLButtonElement>();
  private readonly weightButtons = new Map<WeightKind, HTMLButtonElement>();
  private readonly layerBoxes = new Map<LayerName, HTMLInputElement>();
  private readonly hint = h('p', { class: 'hint', 'data-testid': 'skin-hint' });
  private readonly rigFacts = facts(['Handles', 'Selected', 'Rig']);
  private readonly progress = h('div', { class: 'progress', 'data-testid': 'weights-progress', hidden: true, role: 'progressbar', 'aria-valuemin': '0', 'aria-valuemax': '100' });
  private readonly progressBar = h('div', { class: 'bar' });
  private readonly progressLabel = h('span', { class: 'label' });
  private readonly rigError = h('p', { class: 'rig-error', 'data-testid': 'rig-error', hidden: true });
  private readonly flexible: HTMLInputElement;
  private readonly errorFacts = facts(['Fit RMS', 'Naive RMS', 'Closer']);
  private readonly resetButton: HTMLButtonElement;
  private readonly removeButton: HTMLButtonElement;
  private readonly exportPosed: HTMLButtonElement;
  private readonly exportAnimated: HTMLButtonElement;

  constructor(actions: SkinPanelActions) {
    const tools = h('div', { class: 'segmented', role: 'group', 'aria-label': 'Tool' });
    for (const [tool, label, title] of [
      ['rig', 'Rig', 'Edit the rig at rest: click to add a handle, drag one to move it (R)'],
      ['pose', 'Pose', 'Pose the drawing: drag a handle, turn or scale it with the ring (P)'],
    ] as const) {
      const b = noFocusOnClick(h('button', { type: 'button', 'data-tool': tool, title, 'aria-pressed': 'false' }, label));
      b.addEventListener('click', () => actions.setTool(tool));
      this.toolButtons.set(tool, b);
      tools.append(b);
    }
    this.resetButton = noFocusOnClick(h('button', { type: 'button', class: 'small', title: 'Back to the rest pose: the selected handle, or all (0)' }, 'Reset pose'));
    this.resetButton.addEventListener('click', () => actions.resetPose());
    this.removeButton = noFocusOnClick(h('button', { type: 'button', class: 'small', title: 'Remove the selected handle (Delete)' }, 'Remove handle'));
    this.removeButton.addEventListener('click', () => actions.removeHandle());

    const weights = h('div', { class: 'segmented', role: 'group', 'aria-label': 'Weights' });
    for (const kind of ['shepard', 'harmonic', 'bbw'] as const) {
      const [label, title] = WEIGHT_LABELS[kind];
      const b = noFocusOnClick(h('button', { type: 'button', 'data-weights': kind, title, 'aria-pressed': 'false' }, label));
      b.addEventListener('click', () => actions.setWeights(kind));
      this.weightButtons.set(kind, b);
      weights.append(b);
    }
    this.progress.append(this.progressBar, this.progressLabel);
    this.flexible = h('input', { type: 'checkbox', 'data-testid': 'flexible' });
    this.flexible.addEventListener('change', () => actions.setFlexible(this.flexible.checked));

    const layers = h('div', { class: 'toggles' });
    for (const l of LAYERS) {
      const box = h('input', { type: 'checkbox', 'data-layer': l.name });
      box.addEventListener('change', () => actions.setLayer(l.name, box.checked));
      this.layerBoxes.set(l.name, box);
      layers.append(h('label', { class: 'toggle', title: l.title }, box, h('span', {}, l.label), h('kbd', {}, l.key)));
    }
    const legends = h(
      'div',
      { class: 'legends' },
      h('div', { class: 'legend-bar' }, h('span', {}, 'min'), h('i', { style: `background:${HEAT.css()}` }), h('span', {}, 'max error')),
      h('div', { class: 'legend-bar' }, h('span', {}, '0'), h('i', { style: `background:${WEIGHT.css()}` }), h('span', {}, '1 weight')),
      h('div', { class: 'legend-line' }, h('i', { class: 'dashed', style: `border-color:${SKIN_COLORS.target}` }), 'target', h('i', { style: `border-color:${SKIN_COLORS.naive}` }), 'naive'),
    );

    this.exportPosed = noFocusOnClick(h('button', { type: 'button', class: 'wide', 'data-testid': 'export-posed', title: 'Download the deformed drawing as SVG' }, 'Deformed SVG'));
    this.exportPosed.addEventListener('click', () => actions.exportPosed());
    this.exportAnimated = noFocusOnClick(
      h('button', { type: 'button', class: 'wide', 'data-testid': 'export-animated', title: 'Download the keyframed animation as an SVG that plays by itself (SMIL, no script)' }, 'Animated SVG'),
    );
    this.exportAnimated.addEventListener('click', () => actions.exportAnimated());
    this.errorFacts.el.dataset.testid = 'skin-errors';
    this.rigFacts.el.dataset.testid = 'skin-rig';

    this.sections = [
      section('Handles', tools, this.hint, this.rigFacts.el, h('div', { class: 'row' }, this.resetButton, this.removeButton)),
      section('Weights', weights, this.progress, this.rigError, h('label', { class: 'toggle', title: 'Relax G1 tangent ratios and fixed angles when a gesture ends (§4 of the paper)' }, this.flexible, h('span', {}, 'Flexible G1 on release'))),
      section('Show', layers, legends),
      section('Error', this.errorFacts.el, h('p', { class: 'hint small' }, 'Root-mean-square distance to the target along the curves; the naive result moves the control points instead of fitting.')),
      section('Export', h('div', { class: 'row' }, this.exportPosed, this.exportAnimated)),
    ];
  }

  setTool(tool: SkinTool, handles: number): void {
    for (const [t, b] of this.toolButtons) b.setAttribute('aria-pressed', String(t === tool));
    this.hint.textContent =
      tool === 'rig'
        ? handles === 0
          ? 'Click on the drawing to place handles: each one pulls the curves near it.'
          : 'Click to add a handle, drag one to move it at rest, Delete removes the selected one. Press P to pose.'
        : handles === 0
          ? 'No handles yet: press R (Rig) and click on the drawing to place some, or Shift+click here.'
          : 'Drag a handle to move it; Shift+drag turns it, Alt+drag scales it, or use the ring and its square knob.';
  }

  setSpec(spec: { handles: number; weights: WeightKind; flexible: boolean; selected: number | null; posed: boolean }): void {
    for (const [k, b] of this.weightButtons) b.setAttribute('aria-pressed', String(k === spec.weights));
    this.flexible.checked = spec.flexible;
    this.rigFacts.set('Handles', String(spec.handles));
    this.rigFacts.set('Selected', spec.selected === null ? '—' : `handle ${spec.selected}`);
    this.resetButton.disabled = !spec.posed;
    this.removeButton.disabled = spec.selected === null;
  }

  setStatus(status: RigStatus): void {
    const building = status.phase === 'building';
    this.progress.hidden = !building;
    if (building) {
      const pct = Math.round(100 * status.fraction);
      this.progressBar.style.width = `${pct}%`;
      const stage = status.stage ?? 'building';
      this.progressLabel.textContent = `${stage.charAt(0).toUpperCase()}${stage.slice(1)}… ${pct}%`;
      this.progress.setAttribute('aria-valuenow', String(pct));
    }
    this.rigError.hidden = status.phase !== 'error';
    this.rigError.textContent = status.phase === 'error' ? `${status.message ?? 'The rig failed'}${status.stale ? ' — posing with the previous rig.' : ''}` : '';
    const rig =
      status.phase === 'none'
        ? '—'
        : status.curves > 0
          ? `${status.curves.toLocaleString('en-US')} curves${status.ms !== null ? ` · ${status.ms.toFixed(0)} ms` : ''}`
          : 'building…';
    this.rigFacts.set('Rig', rig, 'Curves of the rig and the time its weights and precompute took');
  }

  setLayers(flags: LayerFlags): void {
    for (const [name, box] of this.layerBoxes) box.checked = flags[name];
  }

  setErrors(errors: PoseErrors | null, size: number): void {
    if (!errors) {
      for (const n of ['Fit RMS', 'Naive RMS', 'Closer']) this.errorFacts.set(n, '—');
      return;
    }
    const pct = (v: number) => `${fmt(v)} (${fmt((100 * v) / size)}%)`;
    this.errorFacts.set('Fit RMS', pct(errors.fit.rms), 'in document units (and % of the drawing’s diagonal)');
    this.errorFacts.set('Naive RMS', pct(errors.naive.rms));
    const ratio = errors.fit.rms > 0 ? errors.naive.rms / errors.fit.rms : Infinity;
    this.errorFacts.set('Closer', errors.naive.rms === 0 ? 'at rest: both exact' : Number.isFinite(ratio) ? `${fmt(ratio)}× closer than naive` : 'exact');
  }

  setExport(canPosed: boolean, canAnimated: boolean, animatedTitle: string): void {
    this.exportPosed.disabled = !canPosed;
    this.exportAnimated.disabled = !canAnimated;
    this.exportAnimated.title = animatedTitle;
  }
}
