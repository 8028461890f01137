// fast-check arbitraries for hostile and odd SVG documents, shared by the Node property test
// (tests/unit/svg-fuzz.test.ts) and the browser one (tests/e2e). They cover what real files and
// attackers throw at an importer: every path command (absolute and relative, with odd number
// syntax), degenerate segments, zero-length subpaths, NaN, Infinity and huge coordinates, nested
// transforms, every stroke cap / join and fill rule, dashes, <use> references (cycles included),
// deep nesting, internal DTD entities, text and images.
import fc from 'fast-check';

const SVG_NS = 'http://www.w3.org/2000/svg';

/** Numbers as they appear in path data: ordinary, tiny, huge, degenerate, and not numbers at all. */
export const coordinate: fc.Arbitrary<string> = fc.oneof(
  { weight: 8, arbitrary: fc.integer({ min: -200, max: 200 }).map(String) },
  { weight: 4, arbitrary: fc.double({ min: -500, max: 500, noNaN: true }).map((v) => String(v)) },
  { weight: 1, arbitrary: fc.constantFrom('0', '-0', '1e-300', '1e300', '-1e308', '1e400', 'NaN', 'Infinity', '.5.5', '1e', '--1', '') },
);

const flag = fc.constantFrom('0', '1', '2');

/** One path command with its arguments (sometimes the wrong number of them). */
const command: fc.Arbitrary<string> = fc.oneof(
  fc.tuple(fc.constantFrom('M', 'm', 'L', 'l', 'T', 't'), coordinate, coordinate).map(([c, x, y]) => `${c}${x} ${y}`),
  fc.tuple(fc.constantFrom('H', 'h', 'V', 'v'), coordinate).map(([c, x]) => `${c}${x}`),
  fc.tuple(fc.constantFrom('C', 'c'), fc.array(coordinate, { minLength: 6, maxLength: 6 })).map(([c, a]) => `${c}${a.join(' ')}`),
  fc.tuple(fc.constantFrom('S', 's', 'Q', 'q'), fc.array(coordinate, { minLength: 4, maxLength: 4 })).map(([c, a]) => `${c}${a.join(',')}`),
  fc
    .tuple(fc.constantFrom('A', 'a'), coordinate, coordinate, coordinate, flag, flag, coordinate, coordinate)
    .map(([c, rx, ry, rot, large, sweep, x, y]) => `${c}${rx} ${ry} ${rot} ${large} ${sweep} ${x} ${y}`),
  fc.constantFrom('Z', 'z', 'M0 0', 'm0 0z', 'L0 0 0 0 0 0', 'C0 0 0 0 0 0', 'M1 1 Z Z Z'),
  fc.constantFrom('M', 'L1', 'X', '1 2 3'),
);

/** Path data: mostly well-formed with an initial moveto, sometimes garbage. */
export const pathData: fc.Arbitrary<string> = fc.oneof(
  { weight: 6, arbitrary: fc.tuple(coordinate, coordinate, fc.array(command, { maxLength: 12 })).map(([x, y, rest]) => `M${x} ${y} ${rest.join(' ')}`) },
  { weight: 1, arbitrary: fc.array(command, { maxLength: 6 }).map((c) => c.join('')) },
);

const transform: fc.Arbitrary<string> = fc.oneof(
  fc.tuple(coordinate, coordinate).map(([x, y]) => `translate(${x} ${y})`),
  fc.tuple(coordinate, coordinate, coordinate).map(([a, x, y]) => `rotate(${a} ${x} ${y})`),
  fc.tuple(coordinate, coordinate).map(([x, y]) => `scale(${x},${y})`),
  fc.constantFrom('scale(0)', 'skewX(90)', 'skewY(89.999)', 'matrix(1 0 0 1 0 0)', 'matrix(0 0 0 0 0 0)', 'rotate(30', 'nonsense(1)', ''),
  fc.array(coordinate, { minLength: 6, maxLength: 6 }).map((m) => `matrix(${m.join(' ')})`),
);

const paint = fc.constantFrom('none', 'black', '#c33', '#4a8c', 'rgb(10, 200, 30)', 'hsl(120 50% 50%)', 'url(#grad)', 'url(#missing)', 'currentColor', 'bogus');

/** Presentation attributes: every cap, join and fill rule, dashes, opacity, markers and clips. */
const styleAttributes: fc.Arbitrary<string> = fc
  .record(
    {
      fill: paint,
      stroke: paint,
      'stroke-width': fc.constantFrom('0', '1', '3.5', '-2', '1e6', 'NaN'),
      'stroke-linecap': fc.constantFrom('butt', 'round', 'square', 'bogus'),
      'stroke-linejoin': fc.constantFrom('miter', 'round', 'bevel', 'arcs', 'miter-clip'),
      'stroke-miterlimit': fc.constantFrom('1', '4', '0.5'),
      'fill-rule': fc.constantFrom('nonzero', 'evenodd'),
      'stroke-dasharray': fc.constantFrom('none', '5 3', '0', '1,2,3', '-1 2', '0 0'),
      'stroke-dashoffset': fc.constantFrom('0', '7', '-3'),
      opacity: fc.constantFrom('1', '0.5', '0', '2'),
      'clip-path': fc.constantFrom('url(#clip)', 'url(#missing)'),
      'marker-end': fc.constantFrom('url(#arrow)'),
    },
    { requiredKeys: [] },
  )
  .map((r) =>
    Object.entries(r)
      .map(([k, v]) => ` ${k}="${v}"`)
      .join(''),
  );

const shape: fc.Arbitrary<string> = fc.oneof(
  { weight: 6, arbitrary: fc.tuple(pathData, styleAttributes).map(([d, s]) => `<path d="${d}"${s}/>`) },
  fc.tuple(coordinate, coordinate, coordinate, coordinate, coordinate, styleAttributes).map(
    ([x, y, w, h, r, s]) => `<rect x="${x}" y="${y}" width="${w}" height="${h}" rx="${r}"${s}/>`,
  ),
  fc.tuple(coordinate, coordinate, coordinate, styleAttributes).map(([x, y, r, s]) => `<circle cx="${x}" cy="${y}" r="${r}"${s}/>`),
  fc.tuple(coordinate, coordinate, coordinate, coordinate, styleAttributes).map(
    ([x, y, rx, ry, s]) => `<ellipse cx="${x}" cy="${y}" rx="${rx}" ry="${ry}"${s}/>`,
  ),
  fc.tuple(coordinate, coordinate, coordinate, coordinate, styleAttributes).map(
    ([a, b, c, d, s]) => `<line x1="${a}" y1="${b}" x2="${c}" y2="${d}"${s}/>`,
  ),
  fc.tuple(fc.constantFrom('polyline', 'polygon'), fc.array(coordinate, { maxLength: 9 }), styleAttributes).map(
    ([tag, p, s]) => `<${tag} points="${p.join(' ')}"${s}/>`,
  ),
  fc.constantFrom(
    '<text x="10" y="20" font-size="12">Hello &amp; ünïcode</text>',
    '<image x="0" y="0" width="10" height="10" href="data:image/png;base64,iVBORw0KGgo="/>',
    '<use href="#s0"/>',
    '<use href="#g0" x="5" y="5"/>',
    '<use href="#missing"/>',
    '<use href="#cycle"/>',
    '<foreignObject width="10" height="10"><div xmlns="http://www.w3.org/1999/xhtml">x</div></foreignObject>',
  ),
);

/** Groups nested up to `depth` levels, with transforms and styles. */
const content = (depth: number): fc.Arbitrary<string> =>
  depth <= 0
    ? fc.array(shape, { maxLength: 4 }).map((a) => a.join(''))
    : fc
        .array(
          fc.oneof(
            { weight: 3, arbitrary: shape },
            {
              weight: 1,
              arbitrary: fc
                .tuple(fc.option(transform, { nil: undefined }), styleAttributes, fc.boolean(), content(depth - 1))
                .map(([t, s, id, inner]) => `<g${t === undefined ? '' : ` transform="${t}"`}${s}${id ? ' id="g0"' : ''}>${inner}</g>`),
            },
          ),
          { maxLength: 4 },
        )
        .map((a) => a.join(''));

const DEFS = `<defs>
  <linearGradient id="grad" gradientTransform="rotate(20)"><stop offset="0" stop-color="red"/><stop offset="1" stop-color="blue" stop-opacity="0.5"/></linearGradient>
  <clipPath id="clip"><rect width="50" height="50"/></clipPath>
  <marker id="arrow" markerWidth="4" markerHeight="4" refX="2" refY="2"><path d="M0 0 L4 2 L0 4 Z"/></marker>
  <path id="s0" d="M0 0 C10 0 10 10 0 10"/>
  <g id="cycle"><use href="#cycle"/></g>
</defs>`;

/** A whole document: root attributes, defs, content, and sometimes a DOCTYPE or extreme structure. */
export const svgDocument: fc.Arbitrary<string> = fc.oneof(
  {
    weight: 10,
    arbitrary: fc
      .tuple(
        fc.constantFrom('viewBox="0 0 100 100"', 'width="100" height="100"', 'viewBox="0 0 0 0"', 'viewBox="-50 -50 100 100" width="10cm"', ''),
        fc.boolean(),
        content(3),
      )
      .map(([root, defs, body]) => `<svg xmlns="${SVG_NS}" xmlns:xlink="http://www.w3.org/1999/xlink" ${root}>${defs ? DEFS : ''}${body}</svg>`),
  },
  {
    weight: 1,
    arbitrary: fc.tuple(fc.oneof(fc.integer({ min: 1, max: 40 }), fc.integer({ min: 995, max: 1005 }), fc.constant(20_000)), shape).map(([n, s]) => `<svg xmlns="${SVG_NS}">${'<g>'.repeat(n)}${s}${'</g>'.repeat(n)}</svg>`),
  },
  {
    weight: 1,
    // Either small (at most 729 copies) or a bomb (2^18 copies and far more): the limits must tell them apart.
    arbitrary: fc.oneof(fc.tuple(fc.integer({ min: 1, max: 6 }), fc.integer({ min: 2, max: 3 })), fc.tuple(fc.integer({ min: 18, max: 30 }), fc.integer({ min: 2, max: 4 }))).map(([levels, fan]) => {
      let body = '<defs><path id="u0" d="M0 0 L1 1"/>';
      for (let i = 1; i <= levels; i++) body += `<g id="u${i}">${`<use href="#u${i - 1}"/>`.repeat(fan)}</g>`;
      return `<svg xmlns="${SVG_NS}">${body}</defs><use href="#u${levels}"/></svg>`;
    }),
  },
  {
    weight: 1,
    // Either small (at most 729 expansions) or a bomb (10^6 and far more).
    arbitrary: fc
      .tuple(fc.oneof(fc.tuple(fc.integer({ min: 1, max: 6 }), fc.integer({ min: 1, max: 3 })), fc.tuple(fc.integer({ min: 6, max: 12 }), fc.integer({ min: 10, max: 12 }))), shape)
      .map(([[levels, fan], s]) => {
      let dtd = '<!ENTITY e0 "M0 0 L1 1">';
      for (let i = 1; i <= levels; i++) dtd += `<!ENTITY e${i} "${`&e${i - 1}; `.repeat(fan)}">`;
      return `<!DOCTYPE svg [${dtd}<!ENTITY ext SYSTEM "file:///etc/hostname">]><svg xmlns="${SVG_NS}"><path d="&e${levels};"/><desc>&ext;</desc>${s}</svg>`;
    }),
  },
);
