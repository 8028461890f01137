// The allow-list the 2D view applies to a drawing's markup before it enters the page: SVG elements
// that draw or define paint (no script, no foreign content, no animation that could set a link),
// attributes that style or place them (no event handlers), references only inside the file (or
// to embedded images), numbers a 32-bit float can hold. One walk without recursion over the parsed
// tree, linear in its size (a 100,000-path drawing is sanitised in a fraction of a second).

const SVG_NS = 'http://www.w3.org/2000/svg';
const XLINK_NS = 'http://www.w3.org/1999/xlink';
const XML_NS = 'http://www.w3.org/XML/1998/namespace';
const XMLNS_NS = 'http://www.w3.org/2000/xmlns/';

/**
 * SVG elements kept, compared in lower case: shapes, containers, text, paint servers, clips,
 * masks, markers, filter primitives, images, `use`, style sheets and descriptions. Not kept, with
 * everything inside them: script, foreignObject, `animate` and `set` (they can change any
 * attribute, a link's target too), fonts, and any element outside the SVG namespace.
 */
const ELEMENTS = new Set(
  [
    'svg', 'g', 'defs', 'symbol', 'use', 'switch', 'a', 'title', 'desc', 'metadata', 'style', 'view',
    'path', 'rect', 'circle', 'ellipse', 'line', 'polyline', 'polygon',
    'text', 'tspan', 'textpath', 'tref',
    'lineargradient', 'radialgradient', 'stop', 'pattern', 'clippath', 'mask', 'marker', 'image',
    'animatecolor', 'animatemotion', 'animatetransform', 'mpath',
    'filter', 'feblend', 'fecolormatrix', 'fecomponenttransfer', 'fecomposite', 'feconvolvematrix', 'fediffuselighting',
    'fedisplacementmap', 'fedistantlight', 'fedropshadow', 'feflood', 'fefunca', 'fefuncb', 'fefuncg', 'fefuncr',
    'fegaussianblur', 'feimage', 'femerge', 'femergenode', 'femorphology', 'feoffset', 'fepointlight',
    'fespecularlighting', 'fespotlight', 'fetile', 'feturbulence',
  ],
);

/** Attributes (no namespace) kept, compared in lower case; `data-*` and `aria-*` are kept too. */
const ATTRIBUTES = new Set(
  [
    'accent-height', 'accumulate', 'additive', 'alignment-baseline', 'attributename', 'attributetype', 'amplitude', 'ascent', 'azimuth', 'basefrequency',
    'baseline-shift', 'begin', 'bias', 'by', 'class', 'clip', 'clippathunits', 'clip-path', 'clip-rule', 'color',
    'color-interpolation', 'color-interpolation-filters', 'color-profile', 'color-rendering', 'cx', 'cy', 'd', 'dx', 'dy',
    'diffuseconstant', 'direction', 'display', 'divisor', 'dominant-baseline', 'dur', 'edgemode', 'elevation', 'end',
    'exponent', 'fill', 'fill-opacity', 'fill-rule', 'filter', 'filterunits', 'flood-color', 'flood-opacity', 'font',
    'font-family', 'font-size', 'font-size-adjust', 'font-stretch', 'font-style', 'font-variant', 'font-weight', 'fr', 'fx',
    'fy', 'gradientunits', 'gradienttransform', 'height', 'href', 'id', 'image-rendering', 'in', 'in2', 'intercept', 'isolation',
    'k', 'k1', 'k2', 'k3', 'k4', 'kerning', 'keypoints', 'keysplines', 'keytimes', 'lang', 'lengthadjust', 'letter-spacing',
    'kernelmatrix', 'kernelunitlength', 'lighting-color', 'marker', 'marker-end', 'marker-mid', 'marker-start', 'markerheight',
    'markerunits', 'markerwidth', 'maskcontentunits', 'maskunits', 'mask', 'mask-type', 'media', 'method', 'mix-blend-mode',
    'mode', 'numoctaves', 'offset', 'operator', 'opacity', 'order', 'orient', 'orientation', 'origin', 'overflow',
    'paint-order', 'path', 'pathlength', 'patterncontentunits', 'patterntransform', 'patternunits', 'pointer-events', 'points',
    'preservealpha', 'preserveaspectratio', 'primitiveunits', 'r', 'rx', 'ry', 'radius', 'refx', 'refy', 'repeatcount',
    'repeatdur', 'restart', 'result', 'rotate', 'scale', 'seed', 'shape-rendering', 'slope', 'specularconstant',
    'specularexponent', 'spreadmethod', 'startoffset', 'stddeviation', 'stitchtiles', 'stop-color', 'stop-opacity',
    'stroke-dasharray', 'stroke-dashoffset', 'stroke-linecap', 'stroke-linejoin', 'stroke-miterlimit', 'stroke-opacity',
    'stroke', 'stroke-width', 'style', 'surfacescale', 'systemlanguage', 'tablevalues', 'targetx', 'targety', 'transform',
    'transform-box', 'transform-origin', 'text-anchor', 'text-decoration', 'text-orientation', 'text-rendering', 'textlength',
    'type', 'unicode-bidi', 'values', 'vector-effect', 'viewbox', 'visibility', 'version', 'width', 'word-spacing',
    'writing-mode', 'xchannelselector', 'ychannelselector', 'x', 'x1', 'x2', 'y', 'y1', 'y2', 'z', 'xmlns',
  ],
);

/** Attributes holding numbers, lengths or lists of them, which the browser parses as 32-bit floats. */
const NUMERIC_ATTRIBUTES = new Set([
  'd', 'points', 'transform', 'gradientTransform', 'patternTransform', 'viewBox', 'x', 'y', 'width', 'height', 'r', 'rx', 'ry',
  'cx', 'cy', 'fx', 'fy', 'fr', 'x1', 'y1', 'x2', 'y2', 'offset', 'stroke-width', 'stroke-dasharray', 'stroke-dashoffset',
  'stroke-miterlimit', 'opacity', 'fill-opacity', 'stroke-opacity', 'stop-opacity', 'refX', 'refY', 'markerWidth', 'markerHeight',
  'font-size', 'stdDeviation', 'dx', 'dy', 'rotate',
]);
/** Attributes that may name a paint server, clip, mask, filter or marker with url(…). */
const URL_ATTRIBUTES = new Set(['fill', 'stroke', 'clip-path', 'mask', 'filter', 'marker', 'marker-start', 'marker-mid', 'marker-end']);
/** Largest finite 32-bit float. */
const FLOAT32_MAX = 3.4028234663852886e38;

/** A reference inside the file (`#id`) or embedded in it (a data: image). */
const LOCAL_REFERENCE = /^\s*(#|data:image\/)/i;

/** CSS (or a presentation attribute) with its references outside the file removed: url(…) to other places, @import. */
export function localCSS(text: string): string {
  return text.replace(/@import[^;]*;?/gi, '').replace(/url\(\s*(['"]?)([^)'"]*)\1\s*\)/gi, (all, _q: string, target: string) => (LOCAL_REFERENCE.test(target) ? all : 'none'));
}

/** What a sanitising walk removed (for tests and warnings). */
export interface SanitizeReport {
  elements: number;
  attributes: number;
}

/**
 * Sanitises the SVG element `root` in place: elements not allowed are removed with everything in
 * them, attributes not allowed are removed, links and url(…) references that leave the file are
 * removed, style sheets lose their @import rules and outside url(…)s, and numeric attributes with
 * a number a 32-bit float cannot hold are removed (the browser would refuse them and log an
 * error). `fromSplines(el)`: elements whose path data is rewritten from the model anyway (their
 * `d` is not read). Uses only core DOM (no browser API), so it runs on any DOM implementation.
 */
export function sanitizeSvg(root: Element, fromSplines: (el: Element) => boolean = () => false): SanitizeReport {
  const report: SanitizeReport = { elements: 0, attributes: 0 };
  let el: Element | null = root;
  while (el) {
    let next: Element | null;
    if (!allowedElement(el)) {
      // Not kept, nor anything inside it: go on after it.
      next = after(el, root);
      if (el === root) throw new Error('the drawing is not an SVG element');
      el.parentNode!.removeChild(el);
      report.elements++;
    } else {
      cleanAttributes(el, fromSplines(el), report);
      if (el.localName === 'style') {
        const text = el.textContent ?? '';
        if (/url\(|@import/i.test(text)) el.textContent = localCSS(text);
      }
      next = firstElement(el) ?? after(el, root);
    }
    el = next;
  }
  return report;
}

function allowedElement(el: Element): boolean {
  return el.namespaceURI === SVG_NS && ELEMENTS.has(el.localName.toLowerCase());
}

function cleanAttributes(el: Element, fromSplines: boolean, report: SanitizeReport): void {
  // Attribute names as strings where the DOM has them (a browser does not make an Attr node per
  // attribute then); an attribute without a prefix has no namespace.
  if (typeof el.getAttributeNames !== 'function') {
    const attrs = el.attributes;
    for (let i = attrs.length - 1; i >= 0; i--) cleanAttribute(el, attrs[i].name, attrs[i], fromSplines, report);
    return;
  }
  for (const name of el.getAttributeNames()) cleanAttribute(el, name, name.includes(':') ? el.getAttributeNode(name) : null, fromSplines, report);
}

/** Keeps, rewrites or removes attribute `qname` of `el` (`attr`: its node, needed when it has a prefix). */
function cleanAttribute(el: Element, qname: string, attr: Attr | null, fromSplines: boolean, report: SanitizeReport): void {
  const ns = attr ? attr.namespaceURI : null;
  const name = attr ? (attr.localName ?? qname) : qname;
  let keep: boolean;
  if ((ns === null || ns === '') && qname.includes(':')) {
    // A prefix without a namespace: only xml: (bound by XML itself, which some DOMs leave unset).
    keep = qname === 'xml:space' || qname === 'xml:lang';
  } else if (ns === null || ns === '') {
    const lower = name.toLowerCase();
    keep = !lower.startsWith('on') && (ATTRIBUTES.has(lower) || lower.startsWith('data-') || lower.startsWith('aria-'));
  } else if (ns === XLINK_NS) {
    keep = name === 'href' || name === 'title';
  } else {
    keep = ns === XML_NS ? name === 'space' || name === 'lang' : ns === XMLNS_NS;
  }
  if (keep) {
    if (name === 'href') keep = LOCAL_REFERENCE.test(el.getAttribute(qname) ?? '');
    else if (name === 'style' || URL_ATTRIBUTES.has(name)) {
      const value = el.getAttribute(qname) ?? '';
      if (/url\(|@import/i.test(value)) el.setAttribute(qname, localCSS(value));
    } else if (NUMERIC_ATTRIBUTES.has(name) && !(fromSplines && name === 'd')) keep = !unrepresentable(el.getAttribute(qname) ?? '');
  }
  if (!keep) {
    if (attr) el.removeAttributeNode(attr);
    else el.removeAttribute(qname);
    report.attributes++;
  }
}

/** Whether a numeric attribute's value has a number a 32-bit float cannot hold. */
function unrepresentable(value: string): boolean {
  const numbers = value.match(/[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?/g);
  if (!numbers) return false;
  for (const n of numbers) if (!(Math.abs(Number(n)) <= FLOAT32_MAX)) return true;
  return false;
}

function firstElement(el: Element): Element | null {
  for (let c = el.firstChild; c; c = c.nextSibling) if (c.nodeType === 1) return c as Element;
  return null;
}

function nextElement(el: Node): Element | null {
  for (let c = el.nextSibling; c; c = c.nextSibling) if (c.nodeType === 1) return c as Element;
  return null;
}

/** The element after `el` and its content in document order, within `root`. */
function after(el: Element, root: Element): Element | null {
  for (let e: Node | null = el; e && e !== root; e = e.parentNode) {
    const n = nextElement(e);
    if (n) return n;
  }
  return null;
}
