/**
 * The subset of CSS that decides how a shape is painted: presentation attributes, `style`
 * attributes and simple `<style>` rules (type, class, id selectors and their compounds), with
 * SVG inheritance. The model keeps the original markup for export; this is for renderers
 * (the editor, an embedder drawing on a canvas) that paint from the splines.
 */

/** Paint-related properties of one shape, resolved through inheritance. */
export interface ResolvedStyle {
  /** 'none', a CSS color, or a `url(#id)` reference (see `SvgDocument.paintColor`). */
  fill: string;
  /** `fill-opacity`, 0..1. */
  fillOpacity: number;
  /** `fill-rule`. */
  fillRule: 'nonzero' | 'evenodd';
  /** Like `fill`: 'none', a CSS color or a `url(#id)` reference. */
  stroke: string;
  /** `stroke-opacity`, 0..1. */
  strokeOpacity: number;
  /** In the shape's own user units (scale it by the shape's transform to draw in document space). */
  strokeWidth: number;
  /** `stroke-linecap`. */
  strokeLinecap: 'butt' | 'round' | 'square';
  /** `stroke-linejoin`. */
  strokeLinejoin: 'miter' | 'round' | 'bevel' | 'miter-clip' | 'arcs';
  /** `stroke-miterlimit`. */
  strokeMiterlimit: number;
  /** Product of the `opacity` of the shape and its ancestors. */
  opacity: number;
  /** False when the shape or an ancestor has display:none, or visibility is hidden/collapse. */
  visible: boolean;
}

const INHERITED = [
  'fill', 'fill-opacity', 'fill-rule', 'stroke', 'stroke-opacity', 'stroke-width', 'stroke-linecap',
  'stroke-linejoin', 'stroke-miterlimit', 'visibility', 'color',
] as const;
const OWN = ['opacity', 'display'] as const;
const PROPERTIES = new Set<string>([...INHERITED, ...OWN]);

/** Specified (cascaded) values of one element, before inheritance. */
export type Declarations = Map<string, string>;

/** Inherited computed values flowing down the tree. */
export interface StyleContext {
  values: Record<string, string>;
  opacity: number;
  displayed: boolean;
}

export const ROOT_STYLE: StyleContext = {
  values: {
    fill: 'black', 'fill-opacity': '1', 'fill-rule': 'nonzero', stroke: 'none', 'stroke-opacity': '1',
    'stroke-width': '1', 'stroke-linecap': 'butt', 'stroke-linejoin': 'miter', 'stroke-miterlimit': '4',
    visibility: 'visible', color: 'black',
  },
  opacity: 1,
  displayed: true,
};

interface Rule {
  tag?: string;
  id?: string;
  classes: string[];
  specificity: number;
  order: number;
  declarations: Declarations;
}

/** Rules of the document's `<style>` elements. Unsupported selectors are reported, not guessed. */
export class StyleSheet {
  private rules: Rule[] = [];
  readonly unsupportedSelectors: string[] = [];

  add(cssText: string): void {
    const text = cssText.replace(/\/\*[\s\S]*?\*\//g, '').replace(/<!\[CDATA\[|\]\]>/g, '');
    for (const block of text.split('}')) {
      const brace = block.indexOf('{');
      if (brace < 0) continue;
      const declarations = parseDeclarations(block.slice(brace + 1));
      if (declarations.size === 0) continue;
      for (const raw of block.slice(0, brace).split(',')) {
        const selector = raw.trim();
        if (selector === '' || selector.startsWith('@')) continue;
        const m = /^(\*|[a-zA-Z][\w-]*)?((?:[.#][\w-]+)*)$/.exec(selector);
        if (!m) {
          this.unsupportedSelectors.push(selector);
          continue;
        }
        const classes: string[] = [];
        let id: string | undefined;
        for (const part of m[2].match(/[.#][\w-]+/g) ?? []) {
          if (part[0] === '.') classes.push(part.slice(1));
          else id = part.slice(1);
        }
        const tag = m[1] && m[1] !== '*' ? m[1] : undefined;
        const specificity = (id ? 100 : 0) + 10 * classes.length + (tag ? 1 : 0);
        this.rules.push({ tag, id, classes, specificity, order: this.rules.length, declarations });
      }
    }
    this.rules.sort((a, b) => a.specificity - b.specificity || a.order - b.order);
  }

  /** Declarations of the rules matching an element, in cascade order (later wins). */
  match(tag: string, id: string | null, classList: string[], into: Declarations): void {
    for (const r of this.rules) {
      if (r.tag && r.tag !== tag) continue;
      if (r.id && r.id !== id) continue;
      if (!r.classes.every((c) => classList.includes(c))) continue;
      for (const [k, v] of r.declarations) into.set(k, v);
    }
  }
}

/** Parses "a: b; c: d" into declarations of the properties we resolve (others are ignored). */
export function parseDeclarations(text: string): Declarations {
  const out: Declarations = new Map();
  for (const decl of text.split(';')) {
    const colon = decl.indexOf(':');
    if (colon < 0) continue;
    const name = decl.slice(0, colon).trim().toLowerCase();
    const value = decl.slice(colon + 1).replace(/!important/i, '').trim();
    if (PROPERTIES.has(name) && value !== '') out.set(name, value);
  }
  return out;
}

/** Cascaded declarations of an element: presentation attributes < style sheet < style attribute. */
export function declarationsOf(el: Element, sheet: StyleSheet): Declarations {
  const out: Declarations = new Map();
  for (const name of PROPERTIES) {
    const v = el.getAttribute(name);
    if (v !== null && v.trim() !== '') out.set(name, v.trim());
  }
  const cls = el.getAttribute('class');
  sheet.match(el.localName, el.getAttribute('id'), cls ? cls.trim().split(/\s+/) : [], out);
  const style = el.getAttribute('style');
  if (style) for (const [k, v] of parseDeclarations(style)) out.set(k, v);
  return out;
}

/** The context children inherit from an element with these declarations. */
export function inherit(parent: StyleContext, decl: Declarations): StyleContext {
  const values = { ...parent.values };
  for (const name of INHERITED) {
    const v = decl.get(name);
    if (v !== undefined && v !== 'inherit') values[name] = v;
  }
  if (values.fill === 'currentColor') values.fill = values.color;
  if (values.stroke === 'currentColor') values.stroke = values.color;
  const op = parseFloat(decl.get('opacity') ?? '1');
  return {
    values,
    opacity: parent.opacity * (Number.isFinite(op) ? Math.min(1, Math.max(0, op)) : 1),
    displayed: parent.displayed && decl.get('display') !== 'none',
  };
}

function number(v: string, fallback: number): number {
  const x = parseFloat(v);
  return Number.isFinite(x) ? x : fallback;
}

function fraction(v: string): number {
  const x = v.trim().endsWith('%') ? parseFloat(v) / 100 : parseFloat(v);
  return Number.isFinite(x) ? Math.min(1, Math.max(0, x)) : 1;
}

export function resolve(ctx: StyleContext): ResolvedStyle {
  const v = ctx.values;
  return {
    fill: v.fill,
    fillOpacity: fraction(v['fill-opacity']),
    fillRule: v['fill-rule'] === 'evenodd' ? 'evenodd' : 'nonzero',
    stroke: v.stroke,
    strokeOpacity: fraction(v['stroke-opacity']),
    strokeWidth: Math.max(0, number(v['stroke-width'], 1)),
    strokeLinecap: (['butt', 'round', 'square'].includes(v['stroke-linecap']) ? v['stroke-linecap'] : 'butt') as ResolvedStyle['strokeLinecap'],
    strokeLinejoin: (['miter', 'round', 'bevel', 'miter-clip', 'arcs'].includes(v['stroke-linejoin'])
      ? v['stroke-linejoin']
      : 'miter') as ResolvedStyle['strokeLinejoin'],
    strokeMiterlimit: Math.max(1, number(v['stroke-miterlimit'], 4)),
    opacity: ctx.opacity,
    visible: ctx.displayed && v.visibility !== 'hidden' && v.visibility !== 'collapse',
  };
}
