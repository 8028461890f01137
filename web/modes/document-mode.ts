import { CONTINUITY_KINDS, anchorJunction, segmentCount, type ContinuityKind } from '../../src/index.js';
import { SetContinuityCommand } from '../app/commands.js';
import type { Mode, ModeContext } from '../app/modes.js';
import type { AnchorSelection } from '../app/state.js';
import { CONTINUITY_COLORS, CONTINUITY_DESCRIPTIONS } from '../overlay/colors.js';
import { h, noFocusOnClick } from '../ui/dom.js';
import { facts, section } from '../ui/panel.js';
import type { SkippedShape } from '../view2d/svg-layer.js';
import type { ViewPointer } from '../view2d/view2d.js';

/** Kinds in the order the override buttons show them. */
const KINDS: ContinuityKind[] = ['C0', 'C1', 'G1', 'angle', 'none'];

function fmt(v: number, digits = 2): string {
  return Number.isFinite(v) ? (Math.abs(v) >= 1e5 ? v.toExponential(2) : String(+v.toFixed(digits))) : String(v);
}

/**
 * Document mode: inspect the drawing as the spline model sees it — counts, warnings, and the
 * continuity of each junction, which the user can override (undoably).
 */
export class DocumentMode implements Mode {
  readonly id = 'document';
  readonly title = 'Document';
  readonly description = 'Inspect the drawing: counts, warnings, and the continuity at every junction';
  private ctx: ModeContext | null = null;
  private off: (() => void)[] = [];
  private info = facts(['File', 'Frame', 'Elements', 'Splines', 'Segments', 'Import', 'Drawn']);
  private legend = h('ul', { class: 'legend' });
  private junction = h('div', { class: 'junction', 'data-testid': 'junction' });
  private warnings = h('ul', { class: 'warnings', 'data-testid': 'warnings' });
  /** Shapes the last drawing left out (they failed to tessellate or stroke). */
  private skipped: SkippedShape[] = [];

  activate(ctx: ModeContext): void {
    this.ctx = ctx;
    ctx.panel.append(
      section('Drawing', this.info.el),
      section('Continuity', this.legend, this.junction),
      section('Warnings', this.warnings),
    );
    const { state, view } = ctx;
    this.off.push(
      state.events.on('document', () => this.refresh()),
      state.events.on('continuity', () => {
        this.showCounts();
        this.showJunction();
      }),
      state.events.on('selection', () => this.showJunction()),
      state.events.on('overlay', () => this.showJunction()),
      view.events.on('drawing', (s) => {
        if (s.written > 0) this.info.set('Drawn', `${s.shapes.toLocaleString('en-US')} shapes in ${s.ms.toFixed(0)} ms`, 'Shapes drawn by the browser from their splines, and the time to write them');
        this.skipped = s.skipped;
        this.showWarnings();
      }),
    );
    this.refresh();
  }

  deactivate(): void {
    for (const off of this.off) off();
    this.off = [];
    this.ctx?.overlay.setHover(null);
    this.ctx = null;
  }

  pointerDown(p: ViewPointer): boolean {
    const hit = this.ctx?.overlay.pick(p.sx, p.sy);
    if (!hit) return false;
    this.ctx!.state.select(hit);
    return true;
  }

  pointerMove(p: ViewPointer): void {
    if (!this.ctx) return;
    const hit = this.ctx.overlay.pick(p.sx, p.sy);
    this.ctx.overlay.setHover(hit);
    this.ctx.view.canvas.classList.toggle('over-anchor', hit !== null);
  }

  pointerLeave(): void {
    this.ctx?.overlay.setHover(null);
    this.ctx?.view.canvas.classList.remove('over-anchor');
  }

  click(): void {
    this.ctx?.state.select(null);
  }

  keyDown(e: KeyboardEvent): boolean {
    if (e.key === 'Escape' && this.ctx?.state.selection) {
      this.ctx.state.select(null);
      return true;
    }
    return false;
  }

  private refresh(): void {
    const current = this.ctx?.state.current;
    if (!current) {
      for (const name of ['File', 'Frame', 'Elements', 'Splines', 'Segments', 'Import']) this.info.set(name, '—');
    } else {
      const { doc } = current;
      const stats = doc.stats();
      const [, , w, hgt] = doc.frame;
      this.info.set('File', current.file, current.file);
      this.info.set('Frame', `${fmt(w)} × ${fmt(hgt)}`, doc.viewBox ? `viewBox ${doc.viewBox.join(' ')}` : 'width × height');
      this.info.set('Elements', stats.elements.toLocaleString('en-US'));
      this.info.set('Splines', stats.splines.toLocaleString('en-US'));
      this.info.set('Segments', stats.segments.toLocaleString('en-US'));
      this.info.set('Import', `${current.importMs.toFixed(0)} ms`);
    }
    this.showCounts();
    this.showJunction();
    this.showWarnings();
  }

  private showCounts(): void {
    const stats = this.ctx?.state.doc?.stats();
    this.legend.replaceChildren(
      ...KINDS.map((k) =>
        h(
          'li',
          { title: CONTINUITY_DESCRIPTIONS[k] },
          h('i', { class: 'swatch', style: `background:${CONTINUITY_COLORS[k]}` }),
          h('span', { class: 'name' }, k),
          h('span', { class: 'desc' }, CONTINUITY_DESCRIPTIONS[k]),
          h('span', { class: 'count' }, String(stats?.continuity[k] ?? 0)),
        ),
      ),
    );
  }

  private showJunction(): void {
    const ctx = this.ctx;
    const doc = ctx?.state.doc;
    const sel = ctx?.state.selection;
    if (!ctx || !doc) {
      this.junction.replaceChildren();
      return;
    }
    if (!sel) {
      this.junction.replaceChildren(
        h('p', { class: 'hint' }, ctx.state.overlay ? 'Click an anchor on the canvas to inspect its junction and override its tag.' : 'Show the control points (H) to pick anchors.'),
      );
      return;
    }
    const spline = doc.splines[sel.spline];
    const shapeIndex = doc.shapes.findIndex((s) => sel.spline >= s.firstSpline && sel.spline < s.firstSpline + s.splineCount);
    const shape = doc.shapes[shapeIndex];
    const x = spline.points[2 * sel.anchor], y = spline.points[2 * sel.anchor + 1];
    const j = anchorJunction(spline, sel.anchor);
    const rows = facts(['Element', 'Spline', 'Anchor']);
    if (shape) {
      rows.set('Element', `<${shape.tag}${shape.id ? ` id="${shape.id}"` : ''}>${shape.line ? ` · line ${shape.line}` : ''}`, shape.via.length ? `drawn through ${shape.via.join(' › ')}` : undefined);
    }
    rows.set('Spline', `#${sel.spline} · ${spline.closed ? 'closed' : 'open'} · ${segmentCount(spline)} segments`);
    rows.set('Anchor', `point ${sel.anchor} at (${fmt(x)}, ${fmt(y)})`);
    const content: HTMLElement[] = [h('h4', {}, j < 0 ? 'End point' : `Junction ${j}`), rows.el];
    if (j < 0) {
      content.push(h('p', { class: 'hint' }, 'An end of an open spline: no junction, nothing to keep.'));
    } else {
      const tag = spline.continuity[j];
      const buttons = h('div', { class: 'segmented', role: 'group', 'aria-label': 'Continuity tag' });
      for (const k of KINDS) {
        const b = h('button', { type: 'button', 'data-kind': k, 'aria-pressed': String(tag.kind === k), title: CONTINUITY_DESCRIPTIONS[k] }, h('i', { class: 'swatch', style: `background:${CONTINUITY_COLORS[k]}` }), k);
        b.addEventListener('click', () => this.override(sel, j, k));
        buttons.append(noFocusOnClick(b));
      }
      const measured = facts(['Tag', 'Ratio', 'Angle']);
      measured.set('Tag', tag.kind);
      measured.set('Ratio', fmt(tag.ratio, 3), '|H_out − P| / |P − H_in| at import');
      measured.set('Angle', `${fmt((tag.angle * 180) / Math.PI, 1)}°`, 'signed turn from the incoming to the outgoing tangent');
      measured.el.dataset.testid = 'junction-tag';
      content.push(buttons, measured.el);
    }
    this.junction.replaceChildren(...content);
  }

  private override(sel: AnchorSelection, junction: number, kind: ContinuityKind): void {
    const ctx = this.ctx;
    const doc = ctx?.state.doc;
    if (!ctx || !doc || !CONTINUITY_KINDS.includes(kind)) return;
    if (doc.splines[sel.spline].continuity[junction].kind === kind) return;
    ctx.history.execute(new SetContinuityCommand(ctx.state, doc, sel.spline, junction, kind));
  }

  private showWarnings(): void {
    const doc = this.ctx?.state.doc;
    if (!doc || doc.warnings.length + this.skipped.length === 0) {
      this.warnings.replaceChildren(h('li', { class: 'none' }, doc ? 'None: everything drawn is in the model.' : '—'));
      return;
    }
    this.warnings.replaceChildren(
      ...this.skipped.map((s) => h('li', { title: 'not drawn', class: 'skipped' }, `${s.element}: not drawn (${s.reason})`)),
      ...doc.warnings.map((w) => h('li', { title: w.code }, w.message)),
    );
  }
}
