import { documentKey, readJSON, writeJSON } from '../../app/autosave.js';
import type { LoadedDocument } from '../../app/state.js';
import { specFromJSON, type MorphSpec } from './spec.js';

/**
 * The morph set-up is autosaved in localStorage per open document (its name and content hash), so
 * a reload brings the keys, pins, interpolation and t back.
 */
function key(current: LoadedDocument | null): string {
  return current ? documentKey('morph', current.file, current.hash) : 'splinekit:morph:none';
}

/** Autosaves; returns an error message when the storage refused. */
export function saveSpec(current: LoadedDocument | null, spec: MorphSpec): string | null {
  return writeJSON(key(current), spec);
}

/** The autosaved set-up for this document, or null. */
export function loadSpec(current: LoadedDocument | null): MorphSpec | null {
  return specFromJSON(readJSON(key(current)));
}
