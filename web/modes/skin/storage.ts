import { documentKey, readJSON, writeJSON } from '../../app/autosave.js';
import type { LoadedDocument } from '../../app/state.js';
import { specFromJSON, specToJSON, type SkinSpec } from './spec.js';

/**
 * Where a document's rig is kept: autosaved in localStorage (keyed by the file's name and content
 * hash), and in exported SVG files as a `<metadata id="splinekit-rig">` element with the same JSON,
 * so opening the exported file elsewhere brings the rig along.
 */

export interface SavedRig {
  spec: SkinSpec;
  time: number;
}

const METADATA_ID = 'splinekit-rig';

function key(current: LoadedDocument): string {
  return documentKey('skin', current.file, current.hash);
}

/** Autosaves; returns an error message when the storage refused. */
export function saveRig(current: LoadedDocument, spec: SkinSpec, time: number): string | null {
  return writeJSON(key(current), { rig: specToJSON(spec), time });
}

/** The autosaved rig of this document, else the one embedded in its markup, else null. */
export function loadRig(current: LoadedDocument): SavedRig | null {
  const stored = readJSON(key(current)) as { rig?: unknown; time?: unknown } | null;
  if (stored) {
    try {
      const spec = specFromJSON(stored.rig);
      const time = typeof stored.time === 'number' && Number.isFinite(stored.time) ? stored.time : 0;
      return { spec, time };
    } catch {
      // a damaged entry: fall back to the file's own
    }
  }
  const embedded = readEmbeddedRig(new TextDecoder().decode(current.source));
  return embedded ? { spec: embedded, time: 0 } : null;
}

const METADATA_RE = new RegExp(`<metadata\\b[^>]*\\bid=["']${METADATA_ID}["'][^>]*>([\\s\\S]*?)</metadata>\\s*`);

function unescapeXML(s: string): string {
  return s
    .replace(/<!\[CDATA\[([\s\S]*?)\]\]>/g, '$1')
    .replace(/&lt;/g, '<')
    .replace(/&gt;/g, '>')
    .replace(/&quot;/g, '"')
    .replace(/&apos;/g, "'")
    .replace(/&amp;/g, '&');
}

/** The rig embedded in SVG markup, or null (none, or not readable). */
export function readEmbeddedRig(svg: string): SkinSpec | null {
  const m = METADATA_RE.exec(svg);
  if (!m) return null;
  try {
    return specFromJSON(JSON.parse(unescapeXML(m[1])));
  } catch {
    return null;
  }
}

/** The markup with the rig embedded as the root's first child (replacing an embedded one). */
export function embedRig(svg: string, spec: SkinSpec): string {
  const json = JSON.stringify(specToJSON(spec)).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
  const element = `<metadata id="${METADATA_ID}">${json}</metadata>`;
  if (METADATA_RE.test(svg)) return svg.replace(METADATA_RE, `${element}\n`);
  const root = /<svg\b[^>]*>/.exec(svg);
  if (!root) return svg;
  const at = root.index + root[0].length;
  return `${svg.slice(0, at)}\n${element}${svg.slice(at)}`;
}
