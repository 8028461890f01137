import type { SplinekitErrorCode, SvgDocumentTransfer } from '../../src/index.js';
import type { ErrorReply } from './worker-host.js';

/** Messages between the editor and web/app/import.worker.ts (plain data only). */
export interface ImportRequest {
  type: 'import';
  id: number;
  /** The file's bytes (a copy: the editor keeps its own for autosave). */
  bytes: Uint8Array;
  /** The file's name, for messages. */
  name: string;
}

export type ImportReply =
  | {
      type: 'done';
      id: number;
      /** The document as plain data (SvgDocument.fromTransfer rebuilds it). */
      transfer: SvgDocumentTransfer;
      /** Its live markup, `toSVG({ rewrite: 'all', tagShapes: true })`, for the 2D view (null if that failed). */
      markup: string | null;
      /** Time parseSVG took in the worker, in milliseconds. */
      parseMs: number;
    }
  /** The file could not be opened: the message the editor shows, and the SplinekitError code if any. */
  | { type: 'failed'; id: number; message: string; code: SplinekitErrorCode | null }
  | ErrorReply;
