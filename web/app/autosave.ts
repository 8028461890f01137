/**
 * Local autosave (localStorage): the open document (its file name and text, so a reload opens it
 * again) and, per document, what modes store for it (e.g. the skin rig). Keys are namespaced
 * "splinekit:"; per-document entries are keyed by file name and a hash of the text, so the same
 * file opened again finds its data and a different file with the same name does not.
 * Storage can be unavailable or full: every call reports failure instead of throwing.
 */

const SESSION_KEY = 'splinekit:session';

/** FNV-1a (32 bit) of the bytes, as 8 hex digits, plus the length: identifies a file's content. */
export function contentHash(bytes: Uint8Array): string {
  let h = 0x811c9dc5;
  for (let i = 0; i < bytes.length; i++) {
    h ^= bytes[i];
    h = Math.imul(h, 0x01000193);
  }
  return `${(h >>> 0).toString(16).padStart(8, '0')}-${bytes.length.toString(36)}`;
}

export interface SavedSession {
  version: 1;
  file: string;
  hash: string;
  /** The active mode's id. */
  mode: string;
  /** The document's text (UTF-8 decoded). */
  svg: string;
}

function storage(): Storage | null {
  try {
    return window.localStorage;
  } catch {
    return null; // disabled (privacy settings, sandboxed frames)
  }
}

/** Writes a value as JSON; returns an error message, or null when it was stored. */
export function writeJSON(key: string, value: unknown): string | null {
  const s = storage();
  if (!s) return 'local storage is not available';
  try {
    s.setItem(key, JSON.stringify(value));
    return null;
  } catch (err) {
    return err instanceof DOMException && err.name === 'QuotaExceededError' ? 'local storage is full' : String(err);
  }
}

export function readJSON(key: string): unknown {
  try {
    const text = storage()?.getItem(key);
    return text ? (JSON.parse(text) as unknown) : null;
  } catch {
    return null;
  }
}

export function remove(key: string): void {
  try {
    storage()?.removeItem(key);
  } catch {
    // nothing to do
  }
}

/** The key of a per-document entry, e.g. documentKey('skin', file, hash). */
export function documentKey(kind: string, file: string, hash: string): string {
  return `splinekit:${kind}:${hash}:${file}`;
}

export function saveSession(session: Omit<SavedSession, 'version'>): string | null {
  return writeJSON(SESSION_KEY, { version: 1, ...session } satisfies SavedSession);
}

export function loadSession(): SavedSession | null {
  const s = readJSON(SESSION_KEY) as Partial<SavedSession> | null;
  if (!s || s.version !== 1 || typeof s.file !== 'string' || typeof s.svg !== 'string' || typeof s.hash !== 'string' || typeof s.mode !== 'string') return null;
  return s as SavedSession;
}

export function clearSession(): void {
  remove(SESSION_KEY);
}

/**
 * Saves once things have been quiet for `ms` (schedule() after each change), or at once on flush()
 * (mode switch, page hide) when a save is pending. Used by the modes that keep their own drawings.
 */
export class DebouncedSave {
  private timer = 0;

  constructor(
    private readonly ms: number,
    private readonly save: () => void,
  ) {}

  get pending(): boolean {
    return this.timer !== 0;
  }

  schedule(): void {
    window.clearTimeout(this.timer);
    this.timer = window.setTimeout(() => this.flush(), this.ms);
  }

  flush(): void {
    if (!this.timer) return;
    window.clearTimeout(this.timer);
    this.timer = 0;
    this.save();
  }
}
