// The 2D view's sanitiser (web/view2d/sanitize.ts), run here on @xmldom/xmldom's DOM (it uses
// only core DOM): hostile markup loses everything that could run script or reach the network,
// every shared drawing keeps every element it draws with and every attribute they are drawn with,
// and depth is no problem (no recursion).
import { DOMParser, XMLSerializer } from '@xmldom/xmldom';
import { beforeAll, describe, expect, test } from 'vitest';
import { SHAPE_ATTRIBUTE, init, parseSVG } from '../../src/index.js';
import { localCSS, sanitizeSvg } from '../../web/view2d/sanitize.js';
import { readShared, sharedSvgs } from './helpers.js';

beforeAll(async () => {
  await init();
});

function parse(markup: string): Element {
  return new DOMParser().parseFromString(markup, 'image/svg+xml').documentElement as unknown as Element;
}

function serialize(el: Element): string {
  return new XMLSerializer().serializeToString(el as unknown as Parameters<XMLSerializer['serializeToString']>[0]);
}

/** Every element under `root` (itself included), in document order. */
function elements(root: Element): Element[] {
  const out: Element[] = [];
  const stack: Element[] = [root];
  while (stack.length) {
    const el = stack.pop()!;
    out.push(el);
    const kids: Element[] = [];
    for (let c = el.firstChild; c; c = c.nextSibling) if (c.nodeType === 1) kids.push(c as Element);
    stack.push(...kids.reverse());
  }
  return out;
}

const HOSTILE = `<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" xmlns:html="http://www.w3.org/1999/xhtml" xmlns:x="urn:x" viewBox="0 0 100 100" onload="pwn(1)" ONCLICK="pwn(2)">
  <script>pwn(3)</script>
  <html:script>pwn(4)</html:script>
  <rect width="50" height="50" fill="#0c8" onmouseover="pwn(5)" onbegin="pwn(6)"/>
  <foreignObject width="100" height="100"><iframe xmlns="http://www.w3.org/1999/xhtml" src="javascript:pwn(7)"></iframe></foreignObject>
  <a xlink:href="javascript:pwn(8)"><circle cx="70" cy="70" r="20"/></a>
  <a href=" JavaScript:pwn(9)"><circle cx="10" cy="70" r="5"/></a>
  <a href="#inside"><circle id="inside" cx="30" cy="70" r="5"/></a>
  <animate xlink:href="#inside-link" attributeName="href" to="javascript:pwn(10)"/>
  <set attributeName="onclick" to="pwn(11)"/>
  <style>@import url(http://evil.test/x.css); rect { stroke: url(http://evil.test/p.svg#p) } circle { fill: url(#ok) }</style>
  <image href="http://evil.test/x.png" width="10" height="10"/>
  <image xlink:href="data:image/png;base64,iVBORw0KGgo=" width="10" height="10"/>
  <use href="http://evil.test/sprite.svg#s"/>
  <circle cx="20" cy="80" r="5" style="fill: url('http://evil.test/g.svg#g'); stroke: red" filter="url(http://evil.test/f.svg#f)" clip-path="url(#local)"/>
  <x:thing><path d="M0 0 L10 10" onclick="pwn(12)"/></x:thing>
  <rect width="1e39" height="5" transform="scale(1e40)"/>
</svg>`;

describe('sanitizeSvg', () => {
  test('hostile markup keeps no script, handler, foreign content, link or outside reference', () => {
    const root = parse(HOSTILE);
    const report = sanitizeSvg(root);
    const out = serialize(root);
    for (const bad of ['pwn(', 'script', 'foreignObject', 'iframe', 'javascript', 'JavaScript', 'evil.test', '@import', 'animate', '<set', 'x:thing']) expect(out, bad).not.toContain(bad);
    // script, html:script, foreignObject, animate, set and x:thing, each with what is inside it.
    expect(report.elements).toBe(6);
    // What is not hostile stays: shapes, local links and references, embedded images, plain style.
    expect(out).toContain('href="#inside"');
    expect(out).toContain('xlink:href="data:image/png;base64,iVBORw0KGgo="');
    expect(out).toContain('clip-path="url(#local)"');
    expect(out).toContain('circle { fill: url(#ok) }');
    expect(out).toContain('stroke: red');
    expect(elements(root).filter((e) => e.localName === 'circle')).toHaveLength(4);
    // Numbers a float cannot hold go (the height stays).
    const big = elements(root).filter((e) => e.localName === 'rect')[1];
    expect(big.hasAttribute('width')).toBe(false);
    expect(big.hasAttribute('transform')).toBe(false);
    expect(big.getAttribute('height')).toBe('5');
  });

  test('local CSS: outside url(…)s become none, @import goes, inside references stay', () => {
    expect(localCSS('fill: url(#g); stroke: url("http://x.test/a#b"); @import "y.css";')).toBe('fill: url(#g); stroke: none; ');
    expect(localCSS('background: url(data:image/png;base64,AAAA)')).toBe('background: url(data:image/png;base64,AAAA)');
  });

  test('every shared drawing keeps every element and attribute it is drawn with', () => {
    let checked = 0;
    for (const rel of sharedSvgs()) {
      const doc = parseSVG(readShared(rel), { name: rel });
      const root = parse(doc.toSVG({ rewrite: 'all', tagShapes: true }));
      const before = elements(root).filter((e) => e.namespaceURI === 'http://www.w3.org/2000/svg' && !['script', 'foreignObject', 'animate', 'set'].includes(e.localName) && !insideForeign(e));
      const attrs = new Map(before.map((e) => [e, Array.from(e.attributes).filter((a) => drawingAttribute(a)).map((a) => `${a.name}=${a.value}`)]));
      sanitizeSvg(root, (e) => e.hasAttribute(SHAPE_ATTRIBUTE));
      const after = new Set(elements(root));
      for (const e of before) {
        expect(after.has(e), `${rel}: <${e.localName}> kept`).toBe(true);
        for (const a of attrs.get(e)!) expect(`${e.localName} ${a.split('=')[0]}=${e.getAttribute(a.split('=')[0])}`, rel).toBe(`${e.localName} ${a}`);
      }
      expect(elements(root).filter((e) => e.hasAttribute(SHAPE_ATTRIBUTE))).toHaveLength(doc.shapes.length);
      checked++;
    }
    expect(checked).toBeGreaterThan(40);
  });

  test('20,000 nested groups are walked without recursion', () => {
    const depth = 20_000;
    const root = parse(`<svg xmlns="http://www.w3.org/2000/svg">${'<g>'.repeat(depth)}<path d="M0 0h1" onclick="x()"/>${'</g>'.repeat(depth)}</svg>`);
    const report = sanitizeSvg(root);
    expect(report.attributes).toBe(1);
    const path = elements(root).find((e) => e.localName === 'path')!;
    expect(path.getAttribute('d')).toBe('M0 0h1');
  });
});

/** Whether an element sits inside one the sanitiser drops with its content. */
function insideForeign(e: Element): boolean {
  for (let p = e.parentNode as Element | null; p && p.nodeType === 1; p = p.parentNode as Element | null) {
    if (p.namespaceURI !== 'http://www.w3.org/2000/svg' || ['foreignObject', 'script'].includes(p.localName)) return true;
  }
  return false;
}

const IGNORED = ['enable-background', 'space'];

/** Attributes that change how a drawing looks (not editors' own metadata in other namespaces, nor handlers or links out). */
function drawingAttribute(a: Attr): boolean {
  if (a.namespaceURI && a.namespaceURI !== 'http://www.w3.org/1999/xlink') return false;
  if (a.name.startsWith('on') || a.name.includes(':') && !a.name.startsWith('xlink:')) return false;
  if ((a.localName === 'href') && !/^\s*(#|data:image\/)/i.test(a.value)) return false;
  if (/url\(/.test(a.value) && !/url\(\s*['"]?#/.test(a.value)) return false;
  // Editors' own attributes without a namespace, which browsers ignore (oc_cartoon_cat.svg has a bare
  // `space`, not xml:space; Illustrator writes enable-background).
  return !IGNORED.includes(a.name);
}
