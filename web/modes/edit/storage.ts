import { documentKey, readJSON, writeJSON } from '../../app/autosave.js';
import type { LoadedDocument } from '../../app/state.js';
import type { CurveSnapshot } from './curves.js';

/** Edit curves are autosaved in localStorage per document (file name and content hash). */
function key(current: LoadedDocument): string {
  return documentKey('edit', current.file, current.hash);
}

/** Autosaves; returns an error message when the storage refused. */
export function saveCurves(current: LoadedDocument, curves: CurveSnapshot[]): string | null {
  return writeJSON(key(current), { curves });
}

/** The autosaved curves of this document ([] when none or damaged). */
export function loadCurves(current: LoadedDocument): CurveSnapshot[] {
  const stored = readJSON(key(current)) as { curves?: unknown } | null;
  if (!stored || !Array.isArray(stored.curves)) return [];
  return stored.curves.filter(
    (c): c is CurveSnapshot => !!c && typeof c === 'object' && Array.isArray((c as CurveSnapshot).points) && typeof (c as CurveSnapshot).closed === 'boolean',
  );
}
