import type { MeshInfo } from '../../../src/index.js';
import { contentHash } from '../../app/autosave.js';
import { fetchBytes } from '../../app/loader.js';
import type { Picking } from './client.js';
import { OpenMeshCommand } from './commands.js';
import { messageOf, type ShownMeshInfo, type SurfaceContext } from './context.js';
import { parseSplines } from './drawing.js';
import { SurfaceSession } from './session.js';
import type { SampleFile } from './surface-panel.js';
import { loadDrawing, loadMeshBytes, loadSurfaceSession, storeMeshBytes } from './storage.js';

/**
 * The meshes Surface mode opened in this page (one SurfaceSession each: file bytes and drawing)
 * and the one shown: opening, loading in the worker and the view (one load after another; only the
 * last one asked for is done), the sample lists, and the mesh of the last visit at start.
 */
export class MeshSessions {
  private readonly sessions = new Map<string, SurfaceSession>();
  private _current: SurfaceSession | null = null;
  private _mesh: ShownMeshInfo | null = null;
  private _generation = 0;
  private loads: Promise<unknown> = Promise.resolve();
  private wanted: SurfaceSession | null = null;
  private starting: Promise<void> | null = null;
  /** The sample meshes and SVG drawings (public/samples). */
  meshSamples: SampleFile[] = [];
  svgSamples: SampleFile[] = [];

  /**
   * @param hooks `leaving` is called before the shown session changes (the previous one is still
   *   `current`: save what belongs to it), `attached` after (its mesh is in the view), `refreshed`
   *   when the shown mesh's facts change (its search structures built: `mesh.ready`).
   */
  constructor(
    private readonly mode: SurfaceContext,
    private readonly hooks: { leaving(): void; attached(s: SurfaceSession | null): void; refreshed(): void },
  ) {}

  /** The session shown, or null. */
  get current(): SurfaceSession | null {
    return this._current;
  }

  get mesh(): ShownMeshInfo | null {
    return this._mesh;
  }

  /** Counts mesh loads: replies for an older mesh are dropped. */
  get generation(): number {
    return this._generation;
  }

  /** Starts (once) loading the sample lists, then the mesh of the last visit or the first sample. */
  startOnce(): void {
    if (!this._current && !this.starting) this.starting = this.mode.work.track(this.start());
  }

  private async start(): Promise<void> {
    try {
      await this.loadSampleLists();
      const saved = loadSurfaceSession();
      let restored = false;
      // Unless the user opened a mesh meanwhile: the one of the last visit, else the first sample.
      if (saved && !this.wanted) {
        let bytes: Uint8Array | null = null;
        if (saved.sample && this.meshSamples.some((m) => m.file === saved.file)) {
          bytes = await fetchBytes(`samples/meshes/${saved.file}`, saved.file).catch(() => null);
        } else if (!saved.sample) {
          bytes = await loadMeshBytes(`${saved.hash}:${saved.file}`);
        }
        if (bytes) restored = await this.openBytes(bytes, saved.file, { sample: saved.sample, undoable: false });
      }
      if (!restored && !this.wanted && this.meshSamples.length > 0) await this.openSample(this.meshSamples[0].file, false);
    } catch (err) {
      this.mode.setError(messageOf(err));
    } finally {
      this.starting = null;
    }
  }

  private async loadSampleLists(): Promise<void> {
    const read = async (url: string) => JSON.parse(new TextDecoder().decode(await fetchBytes(url, url))) as unknown;
    const [meshes, svgs] = await Promise.all([read('samples/meshes/index.json'), read('samples/index.json').catch(() => ({ samples: [] }))]);
    this.meshSamples = (meshes as { meshes: SampleFile[] }).meshes;
    this.svgSamples = (svgs as { samples: SampleFile[] }).samples;
    this.showSampleChoice();
    this.mode.panel?.setSvgSamples(this.svgSamples);
  }

  /** Shows the mesh samples in the panel, the shown one chosen. */
  showSampleChoice(): void {
    const s = this._current;
    this.mode.panel?.setMeshSamples(this.meshSamples, s?.sample ? s.file : null);
  }

  /** Opens a sample mesh (public/samples/meshes). */
  async openSample(file: string, undoable: boolean): Promise<boolean> {
    try {
      const bytes = await fetchBytes(`samples/meshes/${file}`, file);
      return await this.openBytes(bytes, file, { sample: true, undoable });
    } catch (err) {
      this.mode.setError(messageOf(err));
      this.showSampleChoice();
      return false;
    }
  }

  /** Opens a mesh file's bytes: a mesh opened before comes back with its drawing. */
  async openBytes(bytes: Uint8Array, name: string, options: { sample: boolean; undoable: boolean }): Promise<boolean> {
    const hash = contentHash(bytes);
    const key = `${hash}:${name}`;
    const target = this.sessions.get(key) ?? new SurfaceSession(name, bytes, options.sample, hash);
    const previous = this._current;
    if (target === previous) return true;
    const ok = await this.show(target);
    if (!ok) return false;
    const ctx = this.mode.ctx;
    if (options.undoable && previous && ctx) ctx.history.execute(new OpenMeshCommand(this.mode, previous, target));
    if (!target.sample) {
      void storeMeshBytes(target).then((problem) => {
        if (problem) this.mode.ctx?.state.setMessage(`The mesh is not kept for the next visit: ${problem}`);
      });
    }
    return true;
  }

  /**
   * Shows a session: loads its mesh in the worker (the previous one stays if that fails) and in
   * the view, then its drawing. Loads run one after another; only the last one asked for is done.
   */
  show(target: SurfaceSession | null): Promise<boolean> {
    this.wanted = target;
    const job = this.loads.then(async () => {
      if (this.wanted !== target) return false;
      if (target === this._current) return true;
      if (!target) {
        this.attach(null);
        return true;
      }
      return this.load(target);
    });
    this.loads = job.catch(() => false);
    return this.mode.work.track(job);
  }

  private async load(target: SurfaceSession): Promise<boolean> {
    const ctx = this.mode.ctx;
    ctx?.state.setBusy(`Opening ${target.file}…`);
    try {
      // Shown (and attached: edits and traces wait in the worker) once the mesh is built; ready once
      // its search structures are too.
      let shown: ShownMeshInfo | null = null;
      let generation = -1;
      const pickingLater = (reply: Picking) => {
        if (this._generation === generation) this.mode.view?.setPicking(reply.bvh);
      };
      const loaded = await this.mode.client.load(target.bytes, target.file, (reply) => {
        generation = ++this._generation;
        this.mode.view!.setMesh(reply.positions, reply.triangles, { fit: true, normals: reply.normals, bvh: reply.bvh ?? 'later', proxy: reply.proxy, bounds: reply.bounds });
        shown = this._mesh = { info: reply.info, scale: reply.scale, loadMs: reply.ms, ready: false };
        if (!this.sessions.has(target.key)) {
          this.sessions.set(target.key, target);
          this.restoreDrawing(target, reply.info);
        }
        this.attach(target);
        ctx?.state.setBusy(`Preparing ${target.file} for tracing…`);
      }, pickingLater);
      if (shown && this._mesh === shown) {
        this._mesh = { ...(shown as ShownMeshInfo), info: loaded.info, loadMs: loaded.ms, ready: true };
        this.hooks.refreshed();
      }
      if (ctx?.state.error?.startsWith(target.file)) ctx.state.setError(null);
      return true;
    } catch (err) {
      ctx?.state.setError(messageOf(err));
      return false;
    } finally {
      ctx?.state.setBusy(null);
    }
  }

  /** The autosaved drawing of a mesh opened for the first time in this page. */
  private restoreDrawing(s: SurfaceSession, info: MeshInfo): void {
    const saved = loadDrawing(s);
    if (!saved) return;
    try {
      const splines = parseSplines(saved, info.faces);
      s.setDrawing({ splines: splines.map((json) => ({ id: s.newId(), json })) });
    } catch (err) {
      this.mode.ctx?.state.setMessage(`The autosaved drawing was not restored: ${messageOf(err)}`);
    }
  }

  private attach(s: SurfaceSession | null): void {
    this.hooks.leaving();
    this._current = s;
    if (!s) {
      this._mesh = null;
      this.mode.view?.clearMesh();
    }
    this.hooks.attached(s);
  }
}
