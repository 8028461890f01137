import type { LoadedDocument } from '../app/state.js';
import { CONTINUITY_COLORS } from '../overlay/colors.js';
import { h } from './dom.js';

const KINDS = ['C0', 'C1', 'G1', 'angle', 'none'] as const;

function formatBytes(n: number): string {
  return n < 1024 ? `${n} B` : n < 2 ** 20 ? `${(n / 1024).toFixed(1)} KB` : `${(n / 2 ** 20).toFixed(1)} MB`;
}

/** The bottom bar: what is open, its counts, the import time, and errors (in red) or progress. */
export class StatusBar {
  readonly el: HTMLElement;
  private readonly file = h('span', { class: 'status-file', 'data-testid': 'status-file' });
  private readonly counts = h('span', { class: 'status-counts', 'data-testid': 'status-counts' });
  private readonly continuity = h('span', { class: 'status-continuity', 'data-testid': 'status-continuity' });
  private readonly warnings = h('span', { class: 'status-warnings', 'data-testid': 'status-warnings' });
  private readonly timing = h('span', { class: 'status-timing', 'data-testid': 'status-timing' });
  private readonly message = h('span', { class: 'status-message', 'data-testid': 'status-message', role: 'status' });
  private readonly error = h('span', { class: 'status-error', 'data-testid': 'status-error', role: 'alert', hidden: true });

  constructor(onDismissError: () => void) {
    const dismiss = h('button', { type: 'button', class: 'dismiss', title: 'Dismiss', 'aria-label': 'Dismiss the error' }, '×');
    dismiss.addEventListener('click', onDismissError);
    this.error.append(h('span', { class: 'text' }), dismiss);
    this.el = h('footer', { class: 'statusbar' }, this.file, this.counts, this.continuity, this.warnings, this.timing, h('span', { class: 'spacer' }), this.message, this.error);
  }

  setDocument(current: LoadedDocument | null): void {
    if (!current) {
      for (const el of [this.file, this.counts, this.continuity, this.warnings, this.timing]) el.textContent = '';
      this.file.textContent = 'No document';
      return;
    }
    const stats = current.doc.stats();
    this.file.textContent = current.file;
    this.file.title = `${current.file} — ${formatBytes(current.bytes)}`;
    this.counts.textContent = `${stats.elements} elements · ${stats.splines} splines · ${stats.segments} segments`;
    this.continuity.replaceChildren(
      ...KINDS.map((k) =>
        h('span', { class: 'kind', title: `${stats.continuity[k]} ${k} junctions` }, h('i', { class: 'swatch', style: `background:${CONTINUITY_COLORS[k]}` }), `${k} ${stats.continuity[k]}`),
      ),
    );
    this.warnings.textContent = stats.warnings === 1 ? '1 warning' : `${stats.warnings} warnings`;
    this.warnings.classList.toggle('has-warnings', stats.warnings > 0);
    this.timing.textContent = `imported in ${current.importMs.toFixed(0)} ms`;
  }

  setError(message: string | null): void {
    this.error.hidden = message === null;
    (this.error.querySelector('.text') as HTMLElement).textContent = message ?? '';
    this.error.title = message ?? '';
  }

  setMessage(message: string | null): void {
    this.message.textContent = message ?? '';
  }
}
