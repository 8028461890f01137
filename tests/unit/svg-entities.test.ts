// What browsers open, splinekit opens, within limits: internal DTD entities (Adobe Illustrator's
// "SVG 1.1" exports declare their namespaces that way) are expanded, external ones never loaded;
// the element and nesting limits count exactly what is drawn. The refusals themselves (entity
// bombs, <use> doubling, deep nesting) are in bad-input.test.ts, through the API and the CLI.
import { beforeAll, describe, expect, test } from 'vitest';
import { SplinekitError, expandEntities, init, parseSVG } from '../../src/index.js';
import { ILLUSTRATOR_BODY, ILLUSTRATOR_HEAD, useDoubling } from './helpers.js';

beforeAll(async () => {
  await init();
});

describe('internal DTD entities', () => {
  test('an Illustrator "SVG 1.1" export opens and draws what the same file with its entities written out draws', () => {
    const doc = parseSVG(ILLUSTRATOR_HEAD + ILLUSTRATOR_BODY, { name: 'illustrator.svg' });
    const written = ILLUSTRATOR_BODY.replaceAll('&ns_svg;', 'http://www.w3.org/2000/svg')
      .replaceAll('&ns_xlink;', 'http://www.w3.org/1999/xlink')
      .replaceAll('&ns_extend;', 'http://ns.adobe.com/Extensibility/1.0/')
      .replaceAll('&ns_ai;', 'http://ns.adobe.com/AdobeIllustrator/10.0/')
      .replaceAll('&ns_graphs;', 'http://ns.adobe.com/Graphs/1.0/')
      .replace('<![CDATA[ eJzs http://www.w3.org/2000/svg', '<![CDATA[ eJzs &ns_svg;');
    const plain = parseSVG(written);
    // The switch draws its <g> (Illustrator's private foreignObject requires an extension).
    expect(doc.shapes.map((s) => s.tag)).toEqual(['path', 'circle', 'rect']);
    expect(doc.splines).toHaveLength(plain.splines.length);
    doc.splines.forEach((s, i) => expect(Array.from(s.points)).toEqual(Array.from(plain.splines[i].points)));
    expect(doc.width).toBe(200);
    expect(doc.warnings.filter((w) => w.code.startsWith('entity:'))).toEqual([]);
    // Written back, it is an SVG again with its namespace written out.
    const out = doc.toSVG();
    expect(out).toContain('xmlns="http://www.w3.org/2000/svg"');
    expect(parseSVG(out).splines).toHaveLength(plain.splines.length);
  });

  test('entities may refer to other entities; comments and CDATA sections are left as they are', () => {
    const { text, droppedExternal } = expandEntities(
      '<!DOCTYPE svg [<!ENTITY a "A&b;A"><!ENTITY b \'&c;&c;\'><!ENTITY c "c"><!-- <!ENTITY d "no"> -->]>' +
        '<svg><!-- &a; --><text>&a;&amp;&#65;&d;<![CDATA[&a;]]></text></svg>',
      't',
    );
    expect(droppedExternal).toEqual([]);
    expect(text.slice(text.indexOf('<svg>'))).toBe('<svg><!-- &a; --><text>AccA&amp;&#65;&d;<![CDATA[&a;]]></text></svg>');
  });

  test('the first declaration of a name binds, and predefined entities cannot be redefined', () => {
    const { text } = expandEntities('<!DOCTYPE x [<!ENTITY a "1"><!ENTITY a "2"><!ENTITY lt "LT">]><x>&a;&lt;</x>', 't');
    expect(text.endsWith('<x>1&lt;</x>')).toBe(true);
  });

  test('external entities are never loaded: their references come out empty, with a warning', () => {
    const input = `<!DOCTYPE svg [<!ENTITY secret SYSTEM "file:///etc/passwd"><!ENTITY pub PUBLIC "-//X//Y" "http://example.invalid/x">
      <!ENTITY ns "http://www.w3.org/2000/svg">]><svg xmlns="&ns;"><text>&secret;&pub;</text><path d="M0 0 L1 1"/></svg>`;
    const doc = parseSVG(input, { name: 'ext.svg' });
    expect(doc.splines).toHaveLength(1);
    const codes = doc.warnings.map((w) => w.code);
    expect(codes).toContain('entity:secret');
    expect(codes).toContain('entity:pub');
    expect(doc.warnings.find((w) => w.code === 'entity:secret')!.message).toMatch(/&secret; is not loaded/);
    expect(doc.toSVG()).not.toContain('root:');
  });

  test('text without an internal subset comes back unchanged', () => {
    const plain = '<?xml version="1.0"?><!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" "x.dtd"><svg>&amp;</svg>';
    expect(expandEntities(plain, 't').text).toBe(plain);
  });

  test('the expansion budget counts the expanded size: a large but legitimate expansion passes', () => {
    // 1,000 references to a 1 kB entity: 1 MB expanded from a 7 kB file, under the 1 MiB slack.
    const input = `<!DOCTYPE svg [<!ENTITY k "${'k'.repeat(1000)}">]><svg xmlns="http://www.w3.org/2000/svg"><desc>${'&k;'.repeat(1000)}</desc></svg>`;
    expect(parseSVG(input).splines).toHaveLength(0);
    const twice = input.replace(`${'&k;'.repeat(1000)}`, `${'&k;'.repeat(2100)}`);
    expect(() => parseSVG(twice)).toThrowError(expect.objectContaining({ code: 'too-complex' }) as unknown as Error);
  });
});

describe('element and nesting limits', () => {
  // Elements drawn by useDoubling(L): the root <svg>, the last <use>, and the g/use tree under it.
  const drawn = (levels: number): number => {
    let g = 1; // the path l0
    for (let i = 1; i <= levels; i++) g = 1 + 2 * (1 + g); // <g> + two <use>s each drawing the level below
    return 2 + g;
  };

  test('maxElements counts exactly the elements drawn, every <use> copy included', () => {
    const text = useDoubling(10);
    const n = drawn(10);
    const doc = parseSVG(text, { maxElements: n });
    expect(doc.splines).toHaveLength(1024);
    expect(() => parseSVG(text, { maxElements: n - 1 })).toThrowError(SplinekitError);
  });

  test('maxDepth counts the nesting levels, <svg> root included', () => {
    const nested = (depth: number) =>
      `<svg xmlns="http://www.w3.org/2000/svg">${'<g>'.repeat(depth)}<path d="M0 0 L1 1"/>${'</g>'.repeat(depth)}</svg>`;
    // root (1) + 8 groups + the path = 10 levels.
    expect(parseSVG(nested(8), { maxDepth: 10 }).splines).toHaveLength(1);
    expect(() => parseSVG(nested(9), { maxDepth: 10 })).toThrowError(/nested deeper than 10 levels/);
    // A subtree counted once near the root, drawn again much deeper through <use>.
    const deepUse = `<svg xmlns="http://www.w3.org/2000/svg"><g id="a"><g><path d="M0 0 L1 1"/></g></g>${'<g>'.repeat(6)}<use href="#a"/>${'</g>'.repeat(6)}</svg>`;
    expect(parseSVG(deepUse, { maxDepth: 11 }).splines).toHaveLength(2);
    expect(() => parseSVG(deepUse, { maxDepth: 10 })).toThrowError(/nested deeper than 10 levels/);
  });
});
