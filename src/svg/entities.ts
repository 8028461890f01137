/**
 * Internal DTD entities, expanded before the XML parser sees the text.
 *
 * Adobe Illustrator's "SVG 1.1" exports declare their namespaces as internal entities and use them
 * in attributes (`<!ENTITY ns_svg "http://www.w3.org/2000/svg">` … `<svg xmlns="&ns_svg;">`).
 * Browsers draw such files; the DOM parser splinekit uses (xmldom) reads the DOCTYPE but does not
 * expand what it declares. This module does, with two safeguards:
 * - a budget on the expanded size, computed before anything is expanded, so an entity bomb
 *   ("billion laughs") is refused with a clear error instead of filling memory;
 * - external entities (`SYSTEM` / `PUBLIC`) are never loaded: their references expand to nothing,
 *   as in browsers, and the caller is told which ones were dropped.
 * Parameter entities (`%name;`) only matter inside the DTD and are ignored.
 */
import { SplinekitError } from '../core/errors.js';

/** The result of {@link expandEntities}. */
export interface ExpandedText {
  /** The text with every reference to a declared internal entity replaced (the DOCTYPE is kept). */
  text: string;
  /** Names of the external entities whose references were dropped (each once). */
  droppedExternal: string[];
}

/** Expanded text may be this many times the input, or 1 MiB larger, whichever is more. */
export const ENTITY_EXPANSION_FACTOR = 4;
const ENTITY_EXPANSION_SLACK = 1 << 20;

const PREDEFINED = new Set(['lt', 'gt', 'amp', 'quot', 'apos']);
const NAME = '[A-Za-z_:][\\w.:\\-\\u00B7-\\uFFFF]*';
/** A general entity's declaration: name, then a quoted value or an external id. */
const ENTITY_DECL = new RegExp(`^<!ENTITY\\s+(${NAME})\\s+(?:"([^"]*)"|'([^']*)'|(SYSTEM|PUBLIC)\\b)`);

interface Declarations {
  internal: Map<string, string>;
  external: Set<string>;
  /** Index just past the DOCTYPE declaration. */
  end: number;
}

/**
 * Expands the internal general entities a document declares in its DOCTYPE. Text without an
 * internal subset comes back unchanged. Throws SplinekitError('too-complex') when the expansion
 * would exceed the budget and SplinekitError('invalid-svg') for an entity that refers to itself.
 */
export function expandEntities(text: string, name: string): ExpandedText {
  const declared = readDeclarations(text);
  if (!declared || (declared.internal.size === 0 && declared.external.size === 0)) return { text, droppedExternal: [] };
  const { internal, external, end } = declared;

  // Length of each entity's full expansion, memoised, with cycle detection.
  const lengths = new Map<string, number>();
  const visiting = new Set<string>();
  const reference = new RegExp(`&(${NAME});`, 'g');
  const expandedLength = (entity: string): number => {
    const known = lengths.get(entity);
    if (known !== undefined) return known;
    if (visiting.has(entity)) throw new SplinekitError('invalid-svg', `${name}: the entity &${entity}; refers to itself`);
    visiting.add(entity);
    const value = internal.get(entity)!;
    let length = value.length;
    for (const m of value.matchAll(reference)) {
      if (internal.has(m[1])) length += expandedLength(m[1]) - m[0].length;
      else if (external.has(m[1])) length -= m[0].length;
    }
    visiting.delete(entity);
    lengths.set(entity, length);
    return length;
  };

  // Comments and CDATA sections are not scanned for references.
  const body = text.slice(end);
  const scan = new RegExp(`<!--[\\s\\S]*?-->|<!\\[CDATA\\[[\\s\\S]*?\\]\\]>|&(${NAME});`, 'g');
  const budget = Math.max(ENTITY_EXPANSION_FACTOR * text.length, text.length + ENTITY_EXPANSION_SLACK);
  let total = text.length;
  for (const m of body.matchAll(scan)) {
    if (m[1] === undefined) continue;
    if (internal.has(m[1])) total += expandedLength(m[1]) - m[0].length;
    if (total > budget) {
      throw new SplinekitError(
        'too-complex',
        `${name}: its DTD entities expand to more than ${(budget / 2 ** 20).toFixed(1)} MiB (an entity bomb?): refused`,
      );
    }
  }

  const dropped = new Set<string>();
  const expanded = new Map<string, string>();
  const expand = (entity: string): string => {
    let value = expanded.get(entity);
    if (value === undefined) {
      value = internal.get(entity)!.replace(reference, (ref, inner: string) => substitute(ref, inner));
      expanded.set(entity, value);
    }
    return value;
  };
  const substitute = (ref: string, entity: string): string => {
    if (internal.has(entity)) return expand(entity);
    if (external.has(entity)) {
      dropped.add(entity);
      return '';
    }
    return ref;
  };
  const out = body.replace(scan, (whole, entity: string | undefined) => (entity === undefined ? whole : substitute(whole, entity)));
  return { text: text.slice(0, end) + out, droppedExternal: [...dropped] };
}

/**
 * Finds the DOCTYPE in the prolog and reads the general entities of its internal subset.
 * Null when the document has no DOCTYPE with an internal subset.
 */
function readDeclarations(text: string): Declarations | null {
  let i = 0;
  // The prolog: XML declaration, processing instructions, comments, white space, then the DOCTYPE.
  for (;;) {
    while (i < text.length && /\s|\uFEFF/.test(text[i])) i++;
    if (text.startsWith('<?', i)) i = after(text, '?>', i);
    else if (text.startsWith('<!--', i)) i = after(text, '-->', i);
    else break;
    if (i < 0) return null;
  }
  if (!text.startsWith('<!DOCTYPE', i)) return null;
  // Up to the '[' of the internal subset (or the '>' that ends a DOCTYPE without one), skipping quoted ids.
  let j = i + 9;
  for (; j < text.length && text[j] !== '[' && text[j] !== '>'; j++) {
    if (text[j] === '"' || text[j] === "'") {
      j = text.indexOf(text[j], j + 1);
      if (j < 0) return null;
    }
  }
  if (text[j] !== '[') return null;
  const internal = new Map<string, string>();
  const external = new Set<string>();
  // The internal subset: declarations, comments, PIs and parameter-entity references until ']'.
  let k = j + 1;
  while (k < text.length && text[k] !== ']') {
    if (text.startsWith('<!--', k)) k = after(text, '-->', k);
    else if (text.startsWith('<?', k)) k = after(text, '?>', k);
    else if (text.startsWith('<!', k)) {
      const start = k;
      k = declarationEnd(text, k);
      if (k < 0) return null;
      const decl = ENTITY_DECL.exec(text.slice(start, k));
      if (decl && !PREDEFINED.has(decl[1]) && !internal.has(decl[1]) && !external.has(decl[1])) {
        // The first declaration of a name binds (XML 1.0 §4.2).
        if (decl[4]) external.add(decl[1]);
        else internal.set(decl[1], decl[2] ?? decl[3]);
      }
    } else k++;
    if (k < 0) return null;
  }
  const close = text.indexOf('>', k);
  return close < 0 ? null : { internal, external, end: close + 1 };
}

/** Index just past the first `token` at or after `from`, or -1. */
function after(text: string, token: string, from: number): number {
  const at = text.indexOf(token, from);
  return at < 0 ? -1 : at + token.length;
}

/** Index just past the '>' that ends the markup declaration starting at `from` (quotes respected), or -1. */
function declarationEnd(text: string, from: number): number {
  for (let i = from + 2; i < text.length; i++) {
    const c = text[i];
    if (c === '"' || c === "'") {
      i = text.indexOf(c, i + 1);
      if (i < 0) return -1;
    } else if (c === '>') return i + 1;
  }
  return -1;
}
