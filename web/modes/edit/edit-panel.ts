import { FALLOFFS, type Falloff } from '../../../src/index.js';
import { h, noFocusOnClick } from '../../ui/dom.js';
import { facts, section } from '../../ui/panel.js';

export type EditTool = 'draw' | 'edit' | 'tangent' | 'convert';

/** The drag settings (not part of the undo history: they shape the next drag). */
export interface EditSettings {
  left: number;
  right: number;
  falloff: Falloff;
  alpha: number;
  normals: boolean;
  /** Resample a drawn stroke evenly by arc length (§3.2). */
  evenStroke: boolean;
}

export const DEFAULT_SETTINGS: EditSettings = { left: 5, right: 5, falloff: 'cosine', alpha: 1, normals: false, evenStroke: true };

export interface EditPanelActions {
  setTool(tool: EditTool): void;
  setSettings(change: Partial<EditSettings>): void;
  resampleCurve(): void;
  /** Resample the window's inside at `factor` times its current number of points. */
  resampleWindow(factor: number): void;
  clearTangents(): void;
  /** Closes an open curve (the last point joins the first) or opens a closed one. */
  toggleClosed(): void;
  deleteCurve(): void;
}

const TOOLS: { tool: EditTool; label: string; key: string; title: string }[] = [
  { tool: 'draw', label: 'Draw', key: 'D', title: 'Draw a stroke with the mouse or a pen: it becomes a Catmull-Rom curve through its samples' },
  { tool: 'edit', label: 'Edit', key: 'E', title: 'Drag a control point: the move spreads over the active window; drag a window end (green, blue) to resize it' },
  { tool: 'tangent', label: 'Tangent', key: 'T', title: 'Drag the tangent knobs of the selected curve: direction and length at a control point' },
  { tool: 'convert', label: 'Convert path', key: 'C', title: 'Click a path of the drawing: it becomes an editable Catmull-Rom curve through its anchors' },
];

const FALLOFF_LABELS: Record<Falloff, string> = { linear: 'Linear', gaussian: 'Gaussian', cosine: 'Cosine^α' };

/** Edit mode's side panel: tools, the active window and drop-off with a preview, curve actions. */
export class EditPanel {
  readonly sections: HTMLElement[];
  private readonly toolButtons = new Map<EditTool, HTMLButtonElement>();
  private readonly left: HTMLInputElement;
  private readonly right: HTMLInputElement;
  private readonly falloff: HTMLSelectElement;
  private readonly alpha: HTMLInputElement;
  private readonly alphaValue = h('span', { class: 'value', 'data-testid': 'edit-alpha-value' });
  private readonly normals: HTMLInputElement;
  private readonly evenStroke: HTMLInputElement;
  private readonly preview: SVGSVGElement;
  private readonly info = facts(['Curves', 'Selected', 'Window', 'Pressure']);
  private readonly hint = h('p', { class: 'hint', 'data-testid': 'edit-hint' });
  private readonly curveButtons: HTMLButtonElement[] = [];

  constructor(actions: EditPanelActions) {
    const tools = h('div', { class: 'segmented', role: 'group', 'aria-label': 'Edit tool' });
    for (const t of TOOLS) {
      const b = noFocusOnClick(h('button', { type: 'button', title: `${t.title} (${t.key})`, 'data-testid': `edit-tool-${t.tool}`, onclick: () => actions.setTool(t.tool) }, t.label));
      this.toolButtons.set(t.tool, b);
      tools.append(b);
    }
    const number = (testid: string, title: string, change: (v: number) => void) =>
      h('input', {
        type: 'number',
        min: 0,
        max: 100000,
        step: 1,
        'data-testid': testid,
        title,
        onchange: (e: Event) => {
          const v = Number((e.target as HTMLInputElement).value);
          if (Number.isInteger(v) && v >= 0) change(v);
        },
      });
    this.left = number('edit-left', 'mL: control points to the left of the dragged one', (v) => actions.setSettings({ left: v }));
    this.right = number('edit-right', 'nR: control points to the right of the dragged one', (v) => actions.setSettings({ right: v }));
    this.falloff = h('select', { 'data-testid': 'edit-falloff', onchange: (e: Event) => actions.setSettings({ falloff: (e.target as HTMLSelectElement).value as Falloff }) });
    for (const f of FALLOFFS) this.falloff.append(h('option', { value: f }, FALLOFF_LABELS[f]));
    this.alpha = h('input', {
      type: 'range',
      min: 0.1,
      max: 4,
      step: 0.05,
      'data-testid': 'edit-alpha',
      title: 'α, the exponent of the cosine: below 1 squares the bump off, above 1 sharpens it',
      oninput: (e: Event) => actions.setSettings({ alpha: Number((e.target as HTMLInputElement).value) }),
    });
    this.normals = h('input', { type: 'checkbox', 'data-testid': 'edit-normals', onchange: (e: Event) => actions.setSettings({ normals: (e.target as HTMLInputElement).checked }) });
    this.evenStroke = h('input', { type: 'checkbox', 'data-testid': 'edit-even', onchange: (e: Event) => actions.setSettings({ evenStroke: (e.target as HTMLInputElement).checked }) });
    this.preview = document.createElementNS('http://www.w3.org/2000/svg', 'svg');
    this.preview.setAttribute('class', 'edit-weights');
    this.preview.setAttribute('viewBox', '0 0 200 50');
    this.preview.setAttribute('data-testid', 'edit-weights');
    const button = (label: string, testid: string, title: string, run: () => void) => {
      const b = noFocusOnClick(h('button', { type: 'button', 'data-testid': testid, title, onclick: run }, label));
      this.curveButtons.push(b);
      return b;
    };
    this.sections = [
      section('Tool', tools, this.hint),
      section(
        'Active window',
        h('div', { class: 'row' }, h('label', {}, 'Left ', this.left), h('label', {}, ' Right ', this.right)),
        h('label', { class: 'row' }, 'Drop-off ', this.falloff),
        h('label', { class: 'row' }, 'α ', this.alpha, this.alphaValue),
        h('label', { class: 'row', title: '§3.4: turn each point’s direction from the drag towards the curve normal at its window end' }, this.normals, ' Interpolate normals'),
        h('div', { class: 'edit-weights-box', title: 'The drop-off weights across the window, left end to right end' }, this.preview),
      ),
      section(
        'Curve',
        this.info.el,
        h('label', { class: 'row', title: 'Place a drawn stroke’s control points evenly by arc length (same count)' }, this.evenStroke, ' Even spacing after drawing'),
        h(
          'div',
          { class: 'edit-buttons' },
          button('Resample curve', 'edit-resample', 'Control points evenly by arc length over the whole curve, same count (R)', () => actions.resampleCurve()),
          button('Finer window', 'edit-finer', 'Twice as many control points inside the active window', () => actions.resampleWindow(2)),
          button('Coarser window', 'edit-coarser', 'Half as many control points inside the active window', () => actions.resampleWindow(0.5)),
          button('Close / open', 'edit-close', 'Join the last control point to the first, or open a closed curve there', () => actions.toggleClosed()),
          button('Reset tangents', 'edit-clear-tangents', 'Back to the Catmull-Rom tangents on the selected curve', () => actions.clearTangents()),
          button('Delete curve', 'edit-delete', 'Remove the selected curve (Delete)', () => actions.deleteCurve()),
        ),
      ),
    ];
  }

  setTool(tool: EditTool): void {
    for (const [t, b] of this.toolButtons) {
      b.classList.toggle('active', t === tool);
      b.setAttribute('aria-pressed', String(t === tool));
    }
    const hints: Record<EditTool, string> = {
      draw: 'Drag on the drawing to sketch a curve.',
      edit: 'Drag a control point; drag the green or blue window end to widen or narrow that side.',
      tangent: 'Select a curve’s point with Edit, then drag its tangent knobs.',
      convert: 'Click a path of the drawing to make it an editable curve.',
    };
    this.hint.textContent = hints[tool];
  }

  setSettings(s: EditSettings): void {
    this.left.value = String(s.left);
    this.right.value = String(s.right);
    this.falloff.value = s.falloff;
    this.alpha.value = String(s.alpha);
    this.alpha.disabled = s.falloff !== 'cosine';
    this.alphaValue.textContent = s.alpha.toFixed(2);
    this.normals.checked = s.normals;
    this.evenStroke.checked = s.evenStroke;
  }

  /** The drop-off weights of the window (left end to right end) as a profile, or empty. */
  setWeights(weights: Float64Array | null): void {
    const ns = 'http://www.w3.org/2000/svg';
    const parts: SVGElement[] = [];
    const base = document.createElementNS(ns, 'line');
    for (const [k, v] of Object.entries({ x1: 0, y1: 46, x2: 200, y2: 46, class: 'axis' })) base.setAttribute(k, String(v));
    parts.push(base);
    if (weights && weights.length > 1) {
      const n = weights.length - 1;
      const line = document.createElementNS(ns, 'polyline');
      line.setAttribute('points', Array.from(weights, (w, k) => `${((200 * k) / n).toFixed(1)},${(46 - 42 * w).toFixed(1)}`).join(' '));
      parts.push(line);
    }
    this.preview.replaceChildren(...parts);
  }

  setInfo(curves: number, selected: string, window: string, pressure: string, hasCurve: boolean): void {
    this.info.set('Curves', String(curves));
    this.info.set('Selected', selected);
    this.info.set('Window', window);
    this.info.set('Pressure', pressure);
    for (const b of this.curveButtons) b.disabled = !hasCurve;
  }
}
