// A document handed from a Web Worker to the page (toTransfer → structuredClone → fromTransfer)
// must be the same document: same model, same export, unchanged and after an edit.
import { beforeAll, describe, expect, test } from 'vitest';
import { SvgDocument, init, parseSVG, type SvgDocumentTransfer } from '../../src/index.js';
import { ILLUSTRATOR_BODY, ILLUSTRATOR_HEAD, readShared } from './helpers.js';

beforeAll(async () => {
  await init();
});

const FILES: [string, () => string][] = [
  // The largest shared drawing.
  ['oc_road_runner_car', () => readShared('svg/illustrations/oc_road_runner_car.svg')],
  // gradients (paint that follows a moved shape)
  ['oc_breakdancer', () => readShared('svg/characters/oc_breakdancer.svg')],
  ['oc_van_gogh_room', () => readShared('svg/illustrations/oc_van_gogh_room.svg')],
  ['ghostscript_tiger_inkscape', () => readShared('svg/illustrations/ghostscript_tiger_inkscape.svg')],
  ['twemoji_1f419_octopus', () => readShared('svg/characters/twemoji_1f419_octopus.svg')],
  // Shapes drawn through <use> (of a shape, a group, a symbol, nested), one painted with a gradient.
  ['uses', () => USES],
  // internal DTD entities, expanded before parsing; the DOCTYPE stays in the markup
  ['illustrator-entities', () => ILLUSTRATOR_HEAD + ILLUSTRATOR_BODY],
];

const USES = `<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 200 100">
  <defs>
    <linearGradient id="g" x1="0" x2="1"><stop offset="0" stop-color="red"/><stop offset="1" stop-color="blue"/></linearGradient>
    <rect id="box" width="10" height="10" fill="url(#g)"/>
    <g id="pair"><circle cx="5" cy="5" r="4"/><use xlink:href="#box" x="12"/></g>
    <symbol id="sym" viewBox="0 0 10 10"><path d="M0 0L10 10L0 10Z"/></symbol>
  </defs>
  <use xlink:href="#box" x="5" y="5"/>
  <use href="#pair" x="40" y="5" transform="rotate(10)"/>
  <use xlink:href="#sym" x="100" y="50" width="20" height="20"/>
  <path d="M150 50C160 40 170 60 180 50"/>
</svg>`;

/** Moves shape i's points (in both documents the same way). */
function move(doc: SvgDocument, i: number): void {
  for (const s of doc.splinesOf(i)) for (let k = 0; k < s.points.length; k++) s.points[k] += k % 2 === 0 ? 3.25 : -1.5;
}

function expectSame(a: SvgDocument, b: SvgDocument): void {
  expect(b.stats()).toEqual(a.stats());
  expect(b.warnings).toEqual(a.warnings);
  expect(b.shapes).toEqual(a.shapes);
  expect(b.splines.length).toBe(a.splines.length);
  const differ = a.splines.findIndex((s, i) => {
    const t = b.splines[i];
    return t.closed !== s.closed || t.points.length !== s.points.length || s.points.some((v, k) => !Object.is(v, t.points[k])) ||
      JSON.stringify(t.continuity) !== JSON.stringify(s.continuity);
  });
  expect(differ, 'first spline that differs').toBe(-1);
  expect([b.width, b.height, b.viewBox, b.bounds]).toEqual([a.width, a.height, a.viewBox, a.bounds]);
  expect(b.toSVG()).toBe(a.toSVG());
  expect(b.toSVG({ rewrite: 'all', tagShapes: true })).toBe(a.toSVG({ rewrite: 'all', tagShapes: true }));
}

describe('SvgDocument.toTransfer / fromTransfer', () => {
  for (const [name, text] of FILES) {
    test(`${name}: the rebuilt document models and exports like the original, also after an edit`, () => {
      const doc = parseSVG(text(), { name });
      expect(doc.shapes.length).toBeGreaterThan(0);
      for (const via of ['direct', 'structuredClone'] as const) {
        const t = doc.toTransfer();
        const back = SvgDocument.fromTransfer(via === 'direct' ? t : (structuredClone(t) as SvgDocumentTransfer));
        expectSame(doc, back);
        // An edit shows the same in both: the rebuilt document still knows the imported geometry
        // and which element each shape is (including shapes drawn through <use>).
        const original = doc.clone();
        const picks = [0, Math.floor(doc.shapes.length / 2), doc.shapes.length - 1];
        doc.shapes.forEach((s, i) => {
          if (s.via.length > 0) picks.push(i);
        });
        if (name === 'uses') expect(picks.length).toBeGreaterThan(4);
        for (const i of picks) {
          move(original, i);
          move(back, i);
        }
        const changed = original.toSVG();
        expect(changed).not.toBe(doc.toSVG());
        expect(back.toSVG()).toBe(changed);
        expect(back.toSVG({ rewrite: 'all', tagShapes: true })).toBe(original.toSVG({ rewrite: 'all', tagShapes: true }));
      }
    });
  }

  test('the transfer is plain data: no DOM, and copies (moving the transfer does not move the document)', () => {
    const doc = parseSVG(ILLUSTRATOR_HEAD + ILLUSTRATOR_BODY, { name: 'ai' });
    const t = doc.toTransfer();
    expect(typeof t.markup).toBe('string');
    expect(t.markup).toContain('<!DOCTYPE svg');
    expect(t.markup).not.toContain('&ns_svg;<'); // references were expanded before parsing
    t.splines.points[0] += 100;
    t.sources.original[0] += 100;
    expect(doc.toSVG()).toBe(parseSVG(ILLUSTRATOR_HEAD + ILLUSTRATOR_BODY, { name: 'ai' }).toSVG());
    expect(doc.splines[0].points[0]).not.toBe(t.splines.points[0]);
  });

  test('a transfer whose elements do not fit its markup is refused', () => {
    const t = parseSVG('<svg xmlns="http://www.w3.org/2000/svg"><path d="M0 0L1 1"/></svg>').toTransfer();
    t.sources.elements[0] = 7;
    expect(() => SvgDocument.fromTransfer(t)).toThrow(/element 7 is not in the markup/);
  });
});
