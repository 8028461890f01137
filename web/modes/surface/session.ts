import { contentHash } from '../../app/autosave.js';
import { Emitter } from '../../app/events.js';
import { EMPTY_DRAWING, type SurfaceDrawing } from './drawing.js';

/**
 * One mesh the user opened and what they drew on it. The file's bytes stay here so that undoing
 * an "Open mesh" (or coming back to Surface mode) can load the mesh again; the drawing is an
 * immutable value replaced by each edit.
 */
export class SurfaceSession {
  readonly events = new Emitter<{ drawing: SurfaceDrawing }>();
  readonly hash: string;
  private _drawing: SurfaceDrawing = EMPTY_DRAWING;
  private _nextId = 1;

  constructor(
    readonly file: string,
    readonly bytes: Uint8Array,
    /** Opened from the sample list (a reload fetches it again instead of storing it). */
    readonly sample: boolean,
    /** contentHash(bytes), when the caller has it (hashing a 2M-triangle mesh takes ~50 ms). */
    hash?: string,
  ) {
    this.hash = hash ?? contentHash(bytes);
  }

  /** Identifies the mesh (file name and content). */
  get key(): string {
    return `${this.hash}:${this.file}`;
  }

  get drawing(): SurfaceDrawing {
    return this._drawing;
  }

  /** A fresh spline id. */
  newId(): number {
    return this._nextId++;
  }

  setDrawing(d: SurfaceDrawing): void {
    if (d === this._drawing) return;
    this._drawing = d;
    for (const s of d.splines) this._nextId = Math.max(this._nextId, s.id + 1);
    this.events.emit('drawing', d);
  }
}
