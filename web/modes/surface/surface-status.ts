import { h } from '../../ui/dom.js';
import type { ShownMeshInfo } from './context.js';
import type { TraceReport } from './trace-cache.js';

/**
 * Surface mode's part of the status bar: the mesh (file, triangles), what loading it repaired
 * (warnings), and the time of the last trace.
 */
export class SurfaceStatus {
  /** The element the editor places in the status bar. */
  readonly el: HTMLElement;
  private readonly mesh = h('span', { class: 'status-file', 'data-testid': 'surface-status-mesh' });
  private readonly warnings = h('span', { class: 'status-warnings', 'data-testid': 'surface-status-warnings' });
  private readonly trace = h('span', { class: 'status-timing', 'data-testid': 'surface-status-trace' });

  constructor() {
    this.el = h('span', { class: 'surface-status' }, this.mesh, this.warnings, this.trace);
  }

  /** Shows the mesh of file `file` (null: none) and the last trace. */
  show(file: string | null, m: ShownMeshInfo | null, t: TraceReport | null): void {
    this.mesh.textContent = file && m ? `${file} · ${m.info.faces.toLocaleString('en-US')} triangles` : 'No mesh';
    this.mesh.title = file && m ? `${file}: ${m.info.faces} triangles, ${m.info.usedVertices} vertices, ${m.ready ? `loaded and precomputed in ${m.loadMs.toFixed(0)} ms` : `shown after ${m.loadMs.toFixed(0)} ms, preparing its search structures`}` : '';
    const w = m?.info.warnings ?? [];
    this.warnings.textContent = w.length === 0 ? (m ? 'no warnings' : '') : w.length === 1 ? w[0] : `${w.length} warnings: ${w[0]}…`;
    this.warnings.title = w.join('\n');
    this.warnings.classList.toggle('has-warnings', w.length > 0);
    this.trace.textContent = t
      ? t.count > 1
        ? `traced ${t.count} splines in ${t.sum.toFixed(1)} ms (${t.points.toLocaleString('en-US')} points)`
        : `traced in ${t.ms.toFixed(2)} ms (${t.points.toLocaleString('en-US')} points)`
      : '';
    this.trace.title = 'Time the core took to trace (geodesic subdivision), per the last edit or retrace';
  }
}
