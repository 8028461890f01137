import { Vector3 } from 'three';
import type { MeshPoint, SurfaceSplineJSON } from '../../../src/index.js';
import { fetchBytes, readFile } from '../../app/loader.js';
import { DrawingCommand } from './commands.js';
import { messageOf, type SurfaceContext } from './context.js';
import { addSplines, findSpline, replaceSpline, type SurfaceDrawing } from './drawing.js';
import type { SurfaceEdits } from './edits.js';
import type { SurfacePrefs } from './storage.js';

/** What the last placement of an SVG made (resized or turned again while untouched). */
interface Placement {
  ids: number[];
  jsons: SurfaceSplineJSON[];
  center: MeshPoint;
  svg: { name: string; text: string };
  /** The view's up when it was placed (where the drawing's up went). */
  up: [number, number, number];
}

/**
 * Placing an SVG drawing on the mesh (b/Surf's SVG mapping): the drawing chosen, the click that
 * places it (one undoable edit), and resizing or turning the last placement while it is untouched
 * (re-mapped as the slider moves, one request at a time, recorded as one edit when it settles).
 */
export class SvgPlacement {
  private svg: { name: string; text: string } | null = null;
  private _placing = false;
  private placement: Placement | null = null;
  /** Re-mapping the last placement while a slider moves: one at a time, then once more if asked. */
  private remap: { busy: boolean; again: boolean; commit: boolean; before: SurfaceDrawing | null } = { busy: false, again: false, commit: false, before: null };

  constructor(
    private readonly mode: SurfaceContext,
    private readonly edits: SurfaceEdits,
  ) {}

  /** Whether the next click on the mesh places the drawing. */
  get placing(): boolean {
    return this._placing;
  }

  /** The chosen drawing's name, or null. */
  get svgName(): string | null {
    return this.svg?.name ?? null;
  }

  /** Whether there is a drawing to place. */
  get hasSvg(): boolean {
    return this.svg !== null;
  }

  /** Forgets the placement (another mesh is shown, the mode is left). */
  reset(): void {
    this._placing = false;
    this.placement = null;
    this.remap.before = null;
  }

  /** Leaves placing without a word (the mode is left). */
  quit(): void {
    this._placing = false;
  }

  /** Chooses the drawing to place. */
  use(name: string, text: string, fromFile: boolean): void {
    this.svg = { name, text };
    this.mode.panel?.setSvgChoice(name, fromFile);
    this.mode.refreshPanel();
  }

  async chooseSample(file: string): Promise<void> {
    try {
      const bytes = await fetchBytes(`samples/${file}`, file);
      this.use(file, new TextDecoder().decode(bytes), false);
      this.start();
    } catch (err) {
      this.mode.setError(messageOf(err));
    }
  }

  async chooseFile(file: File): Promise<void> {
    try {
      const bytes = await readFile(file);
      this.use(file.name, new TextDecoder().decode(bytes), true);
      this.start();
    } catch (err) {
      this.mode.setError(messageOf(err));
    }
  }

  /** The next click places the drawing. */
  start(): void {
    if (!this.svg || !this.mode.session) return;
    this.edits.finish();
    this._placing = true;
    this.mode.ctx?.state.setMessage(`Click on the mesh where the centre of ${this.svg.name} goes`);
    this.mode.refreshPanel();
  }

  stop(): void {
    if (!this._placing) return;
    this._placing = false;
    this.mode.ctx?.state.setMessage(null);
    this.mode.refreshPanel();
  }

  /** Places the drawing centred at `center` (queued after other edits). */
  place(center: MeshPoint): void {
    const svg = this.svg;
    if (!svg) return;
    this.stop();
    this.edits.enqueue(async () => {
      const mode = this.mode, s = mode.session, gen = mode.generation, mesh = mode.mesh, ctx = mode.ctx;
      if (!s || !mesh || !ctx) return;
      ctx.state.setBusy(`Placing ${svg.name}…`);
      try {
        const up = this.screenUp();
        const r = await mode.client.map(svg.text, svg.name, center, mode.prefs.svgSize * mesh.scale, (mode.prefs.svgRotation * Math.PI) / 180, up);
        if (s !== mode.session || gen !== mode.generation) return;
        const added = r.splines.map((json) => ({ id: s.newId(), json }));
        this.edits.replaceDrawing(`Place ${svg.name}`, addSplines(s.drawing, added), added.length > 0 ? { spline: added[0].id, point: null } : null);
        this.placement = { ids: added.map((a) => a.id), jsons: added.map((a) => a.json), center, svg, up };
        ctx.state.setMessage(`${svg.name}: ${added.length} splines placed in ${r.ms.toFixed(0)} ms`);
      } finally {
        mode.ctx?.state.setBusy(null);
      }
    });
  }

  /** The screen's up direction in the world (a placed drawing reads upright in the view). */
  private screenUp(): [number, number, number] {
    const q = this.mode.view?.camera.quaternion;
    const up = new Vector3(0, 1, 0);
    if (q) up.applyQuaternion(q);
    return [up.x, up.y, up.z];
  }

  /** The last placement, if its splines are still as it made them. */
  private untouched(): Placement | null {
    const p = this.placement;
    if (!p) return null;
    const d = this.mode.drawing;
    return p.ids.every((id, i) => findSpline(d, id)?.json === p.jsons[i]) ? p : null;
  }

  /** Size or rotation changed: the next placement uses it, and the last one (untouched) follows. */
  setSizeOrRotation(change: Partial<Pick<SurfacePrefs, 'svgSize' | 'svgRotation'>>): void {
    const mode = this.mode;
    mode.setPrefs(change);
    const p = this.untouched();
    if (!p) return;
    if (this.remap.busy) {
      this.remap.again = true;
      return;
    }
    this.remap.busy = true;
    this.remap.before ??= mode.drawing;
    const s = mode.session!, gen = mode.generation, mesh = mode.mesh!;
    mode.client
      .map(p.svg.text, p.svg.name, p.center, mode.prefs.svgSize * mesh.scale, (mode.prefs.svgRotation * Math.PI) / 180, p.up)
      .then((r) => {
        if (s !== mode.session || gen !== mode.generation || r.splines.length !== p.ids.length || this.untouched() !== p) return;
        let d = s.drawing;
        r.splines.forEach((json, i) => (d = replaceSpline(d, p.ids[i], json)));
        p.jsons = r.splines;
        s.setDrawing(d);
      })
      .catch((err: unknown) => mode.setError(messageOf(err)))
      .finally(() => {
        this.remap.busy = false;
        if (this.remap.again) {
          this.remap.again = false;
          this.setSizeOrRotation({});
        } else if (this.remap.commit) this.commit();
      });
  }

  /** The slider was let go: record the resizing/turning once the re-mapping settles. */
  end(): void {
    if (this.remap.busy || this.remap.again) this.remap.commit = true;
    else this.commit();
  }

  /** Records the resizing/turning of the last placement as one undoable edit. */
  private commit(): void {
    const before = this.remap.before, mode = this.mode, s = mode.session, ctx = mode.ctx;
    this.remap.before = null;
    this.remap.commit = false;
    if (!before || !s || !ctx || before === s.drawing) return;
    const after = s.drawing;
    // The drawing already shows `after`: the command's do() sets the same value.
    ctx.history.execute(new DrawingCommand('Resize or turn the placed SVG', mode, s, before, after, { do: mode.selection, undo: mode.selection }));
  }
}
