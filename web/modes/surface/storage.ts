import { DEFAULT_TRACE_LEVELS, DEFAULT_TRACE_SCHEME, type SurfaceSplineJSON } from '../../../src/index.js';
import { documentKey, readJSON, writeJSON } from '../../app/autosave.js';
import type { SurfaceDrawing } from './drawing.js';
import type { SurfaceSession } from './session.js';
import { messageOf } from '../../app/errors.js';

/**
 * Surface mode's local autosave: per mesh (file name + content hash) its drawing in localStorage;
 * which mesh was open last; and the bytes of a mesh the user opened from a file (IndexedDB, which
 * holds large files; samples are fetched again instead). Failures are reported, never thrown.
 */

const SESSION_KEY = 'splinekit:surface-session';
const PREFS_KEY = 'splinekit:surface-prefs';
const DB_NAME = 'splinekit-surface';
const STORE = 'meshes';

export interface SavedSurfaceSession {
  version: 1;
  file: string;
  hash: string;
  sample: boolean;
}

export function saveDrawing(session: SurfaceSession, d: SurfaceDrawing): string | null {
  return writeJSON(documentKey('surface', session.file, session.hash), { version: 1, splines: d.splines.map((s) => s.json) });
}

/** The autosaved splines of a mesh (not validated yet), or null. */
export function loadDrawing(session: SurfaceSession): unknown[] | null {
  const stored = readJSON(documentKey('surface', session.file, session.hash)) as { version?: unknown; splines?: unknown } | null;
  return stored && stored.version === 1 && Array.isArray(stored.splines) ? (stored.splines as SurfaceSplineJSON[]) : null;
}

export function saveSurfaceSession(session: SurfaceSession): string | null {
  return writeJSON(SESSION_KEY, { version: 1, file: session.file, hash: session.hash, sample: session.sample } satisfies SavedSurfaceSession);
}

export function loadSurfaceSession(): SavedSurfaceSession | null {
  const s = readJSON(SESSION_KEY) as Partial<SavedSurfaceSession> | null;
  if (!s || s.version !== 1 || typeof s.file !== 'string' || typeof s.hash !== 'string') return null;
  return { version: 1, file: s.file, hash: s.hash, sample: s.sample === true };
}

// ---- preferences ---------------------------------------------------------------------------------

export type Scheme = 'olr' | 'rdc';
export type Subdivision = 'uniform' | 'adaptive';

export interface SurfacePrefs {
  scheme: Scheme;
  subdivision: Subdivision;
  /** Subdivision levels (uniform). */
  levels: number;
  /** Angle threshold in degrees (adaptive). */
  angle: number;
  flat: boolean;
  /** SVG placement: width as a fraction of the mesh size, rotation in degrees. */
  svgSize: number;
  svgRotation: number;
}

/** The package's trace defaults (scheme and its levels), the paper's 5° for adaptive, and the panel's own. */
export const DEFAULT_PREFS: SurfacePrefs = {
  scheme: DEFAULT_TRACE_SCHEME,
  subdivision: 'uniform',
  levels: DEFAULT_TRACE_LEVELS[DEFAULT_TRACE_SCHEME],
  angle: 5,
  flat: false,
  svgSize: 0.35,
  svgRotation: 0,
};

export function loadPrefs(): SurfacePrefs {
  const p = (readJSON(PREFS_KEY) ?? {}) as Partial<SurfacePrefs>;
  const num = (v: unknown, d: number, lo: number, hi: number) => (typeof v === 'number' && Number.isFinite(v) ? Math.min(hi, Math.max(lo, v)) : d);
  return {
    scheme: p.scheme === 'rdc' ? 'rdc' : 'olr',
    subdivision: p.subdivision === 'adaptive' ? 'adaptive' : 'uniform',
    levels: Math.round(num(p.levels, DEFAULT_PREFS.levels, 1, 8)),
    angle: num(p.angle, DEFAULT_PREFS.angle, 0.5, 45),
    flat: p.flat === true,
    svgSize: num(p.svgSize, DEFAULT_PREFS.svgSize, 0.01, 2),
    svgRotation: num(p.svgRotation, DEFAULT_PREFS.svgRotation, -360, 360),
  };
}

export function savePrefs(p: SurfacePrefs): void {
  writeJSON(PREFS_KEY, p);
}

// ---- mesh bytes (IndexedDB) ------------------------------------------------------------------------

function openDB(): Promise<IDBDatabase> {
  return new Promise((resolve, reject) => {
    let req: IDBOpenDBRequest;
    try {
      req = indexedDB.open(DB_NAME, 1);
    } catch (err) {
      reject(err instanceof Error ? err : new Error(String(err)));
      return;
    }
    req.onupgradeneeded = () => req.result.createObjectStore(STORE);
    req.onsuccess = () => resolve(req.result);
    req.onerror = () => reject(req.error ?? new Error('IndexedDB is not available'));
  });
}

/** Keeps the bytes of the user's mesh (only the last one: the store holds one entry). */
export async function storeMeshBytes(session: SurfaceSession): Promise<string | null> {
  try {
    const db = await openDB();
    await new Promise<void>((resolve, reject) => {
      const tx = db.transaction(STORE, 'readwrite');
      const store = tx.objectStore(STORE);
      store.clear();
      store.put(session.bytes, session.key);
      tx.oncomplete = () => resolve();
      tx.onerror = () => reject(tx.error ?? new Error('the mesh could not be stored'));
    });
    db.close();
    return null;
  } catch (err) {
    return messageOf(err);
  }
}

export async function loadMeshBytes(key: string): Promise<Uint8Array | null> {
  try {
    const db = await openDB();
    const value = await new Promise<unknown>((resolve, reject) => {
      const req = db.transaction(STORE, 'readonly').objectStore(STORE).get(key);
      req.onsuccess = () => resolve(req.result);
      req.onerror = () => reject(req.error ?? new Error('the mesh could not be read'));
    });
    db.close();
    return value instanceof Uint8Array ? value : value instanceof ArrayBuffer ? new Uint8Array(value) : null;
  } catch {
    return null;
  }
}
