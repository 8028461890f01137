import type { SvgDocument } from '../../src/index.js';
import { Emitter } from './events.js';

/** A document as the editor holds it: the model plus where it came from. */
export interface LoadedDocument {
  doc: SvgDocument;
  /** File name shown to the user (and used for export). */
  file: string;
  /** Time parseSVG took, in milliseconds. */
  importMs: number;
  /** Size of the file in bytes. */
  bytes: number;
  /** The file's bytes as read. */
  source: Uint8Array;
  /** Identifies the content (autosave keys): see app/autosave.ts contentHash. */
  hash: string;
}

/** A selected anchor: point index `anchor` (a multiple of 3) of spline `spline`. */
export interface AnchorSelection {
  spline: number;
  anchor: number;
}

export interface StateEvents extends Record<string, unknown> {
  /** The document was replaced (open, undo of an open). */
  document: LoadedDocument | null;
  /** Continuity tags of the current document changed (spline index, or -1 for many). */
  continuity: number;
  selection: AnchorSelection | null;
  overlay: boolean;
  /** A message for the user: an error (red) or null to clear it. */
  error: string | null;
  /** A long operation runs (its description), or null when it ended. */
  busy: string | null;
  /** Information for the status bar (progress of background work, notes), or null. */
  message: string | null;
}

/**
 * What the editor shows: the current document, the selection, view toggles and the last error.
 * Mutations go through these setters so every view hears about them; undoable changes go through
 * commands (app/commands.ts) which call the setters.
 */
export class EditorState {
  readonly events = new Emitter<StateEvents>();
  private _current: LoadedDocument | null = null;
  private _selection: AnchorSelection | null = null;
  private _overlay = true;
  private _error: string | null = null;
  private _busy: string | null = null;
  private _message: string | null = null;

  get current(): LoadedDocument | null {
    return this._current;
  }
  get doc(): SvgDocument | null {
    return this._current?.doc ?? null;
  }
  get selection(): AnchorSelection | null {
    return this._selection;
  }
  get overlay(): boolean {
    return this._overlay;
  }
  get error(): string | null {
    return this._error;
  }
  get busy(): string | null {
    return this._busy;
  }

  setDocument(current: LoadedDocument | null): void {
    if (current === this._current) return;
    this._current = current;
    this._selection = null;
    this.events.emit('document', current);
    this.events.emit('selection', null);
  }

  /** Tells listeners that tags of `doc` changed (ignored when `doc` is not the current document). */
  continuityChanged(doc: SvgDocument, spline: number): void {
    if (doc === this.doc) this.events.emit('continuity', spline);
  }

  select(selection: AnchorSelection | null): void {
    const same =
      selection === this._selection ||
      (selection && this._selection && selection.spline === this._selection.spline && selection.anchor === this._selection.anchor);
    if (same) return;
    this._selection = selection;
    this.events.emit('selection', selection);
  }

  setOverlay(visible: boolean): void {
    if (visible === this._overlay) return;
    this._overlay = visible;
    if (!visible) this.select(null);
    this.events.emit('overlay', visible);
  }

  setError(message: string | null): void {
    if (message === this._error) return;
    this._error = message;
    this.events.emit('error', message);
  }

  setBusy(what: string | null): void {
    if (what === this._busy) return;
    this._busy = what;
    this.events.emit('busy', what);
  }

  /** Shows a note in the status bar (background progress, autosave problems); null clears it. */
  setMessage(text: string | null): void {
    if (text === this._message) return;
    this._message = text;
    this.events.emit('message', text);
  }

  get message(): string | null {
    return this._message;
  }
}
