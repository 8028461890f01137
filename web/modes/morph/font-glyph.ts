import { parse } from 'opentype.js';

/**
 * A glyph of a local font file (TrueType, OpenType/CFF, WOFF) as SVG markup, for a morph key:
 * its outline in font units with y pointing down (baseline at the ascender), the viewBox around
 * the outline. Throws an Error naming the file or the character when there is no outline.
 */
export function fontGlyphSVG(bytes: ArrayBuffer, char: string, file: string): { name: string; svg: string } {
  let font;
  try {
    font = parse(bytes);
  } catch (err) {
    throw new Error(`${file}: not a font opentype.js can read (${err instanceof Error ? err.message : String(err)})`, { cause: err });
  }
  const ch = [...char.trim()][0];
  if (!ch) throw new Error('type a character to take from the font');
  const path = font.getPath(ch, 0, font.ascender, font.unitsPerEm);
  // Glyph contours are closed; opentype.js ends them at their start without a Z: close each one.
  const d = path
    .toPathData(3)
    .split(/(?=M)/)
    .filter((sub) => sub.trim())
    .map((sub) => (/Z\s*$/i.test(sub) ? sub : `${sub}Z`))
    .join('');
  if (!d) throw new Error(`${file} has no outline for “${ch}”`);
  const b = path.getBoundingBox();
  const pad = 0.05 * Math.max(b.x2 - b.x1, b.y2 - b.y1);
  const vb = [b.x1 - pad, b.y1 - pad, b.x2 - b.x1 + 2 * pad, b.y2 - b.y1 + 2 * pad].map((v) => +v.toFixed(3));
  const family = font.names.fullName?.en ?? font.names.fontFamily?.en ?? file.replace(/\.[^.]+$/, '');
  return {
    name: `${family} “${ch}”`,
    svg: `<svg xmlns="http://www.w3.org/2000/svg" viewBox="${vb.join(' ')}" width="${vb[2]}" height="${vb[3]}"><path fill="#3b6fd8" fill-rule="nonzero" d="${d}"/></svg>`,
  };
}
