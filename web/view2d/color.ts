/** sRGB components in 0…1 and alpha. */
export type RGBA = [number, number, number, number];

const cache = new Map<string, RGBA | null>();
let ctx: CanvasRenderingContext2D | null = null;

/**
 * Parses any CSS color the browser knows (names, #rgb[a], #rrggbb[aa], rgb(), hsl(), …) by
 * letting a 2D canvas normalize it. Returns null for 'none', 'transparent'-like empties and
 * strings that are not colors.
 */
export function cssColor(text: string): RGBA | null {
  const key = text.trim().toLowerCase();
  if (key === '' || key === 'none') return null;
  const hit = cache.get(key);
  if (hit !== undefined) return hit;
  ctx ??= document.createElement('canvas').getContext('2d');
  let out: RGBA | null = null;
  if (ctx) {
    // An invalid assignment leaves fillStyle unchanged: try from two different starting values.
    ctx.fillStyle = '#000000';
    ctx.fillStyle = key;
    const a = String(ctx.fillStyle);
    ctx.fillStyle = '#ffffff';
    ctx.fillStyle = key;
    const b = String(ctx.fillStyle);
    if (a === b) out = parseNormalized(a);
  }
  cache.set(key, out);
  return out;
}

/** Parses what a canvas reports: '#rrggbb' or 'rgba(r, g, b, a)'. */
function parseNormalized(s: string): RGBA | null {
  if (s.startsWith('#') && s.length === 7) {
    const n = parseInt(s.slice(1), 16);
    return [((n >> 16) & 255) / 255, ((n >> 8) & 255) / 255, (n & 255) / 255, 1];
  }
  const m = /^rgba?\(([^)]*)\)$/.exec(s);
  if (!m) return null;
  const v = m[1].split(/[\s,/]+/).filter(Boolean).map(Number);
  if (v.length < 3 || v.some((x) => !Number.isFinite(x))) return null;
  return [v[0] / 255, v[1] / 255, v[2] / 255, v.length > 3 ? v[3] : 1];
}
