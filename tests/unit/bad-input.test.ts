// Bad input gets a clear error that names the problem — from the API as a typed SplinekitError,
// from the CLI as one line on stderr and a non-zero exit — and never a crash or a partial result.
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { SplinekitError, init, parseSVG } from '../../src/index.js';
import { cli, useDoubling } from './helpers.js';

const dir = mkdtempSync(join(tmpdir(), 'splinekit-bad-'));

const svg = (body: string) => `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">${body}</svg>`;

const junk = new Uint8Array(4096);
for (let i = 0; i < junk.length; i++) junk[i] = (i * 2654435761) >>> 24; // deterministic noise with NULs

const nested = (depth: number) => svg(`${'<g>'.repeat(depth)}<path d="M0 0 L1 1"/>${'</g>'.repeat(depth)}`);
const lolz = (() => {
  let dtd = '<!ENTITY lol0 "lol">';
  for (let i = 1; i <= 9; i++) dtd += `<!ENTITY lol${i} "${`&lol${i - 1};`.repeat(10)}">`;
  return `<?xml version="1.0"?><!DOCTYPE svg [${dtd}]>${svg('<text>&lol9;</text>')}`;
})();

const cases: [string, string | Uint8Array, string, RegExp][] = [
  ['empty file', '', 'invalid-svg', /empty/],
  ['whitespace only', ' \n\t ', 'invalid-svg', /empty/],
  ['truncated XML', svg('<path d="M0 0 L1 1"/>').slice(0, 60), 'invalid-svg', /not well-formed XML/],
  ['mismatched tags', '<svg xmlns="http://www.w3.org/2000/svg"><g></svg>', 'invalid-svg', /not well-formed XML/],
  ['binary junk', junk, 'invalid-svg', /binary data/],
  ['gzip data', Uint8Array.from([0x1f, 0x8b, 8, 0, 0, 0]), 'invalid-svg', /gzip/],
  ['not an svg root', '<html><body/></html>', 'invalid-svg', /root element is <html>/],
  ['garbage path data', svg('<path id="leg" d="M0 0 L 5 foo"/>'), 'invalid-path-data', /<path id="leg"> at line 1: bad path data/],
  ['NaN in path data', svg('<path d="M NaN 0 L1 1"/>'), 'invalid-path-data', /bad path data/],
  ['number overflowing to Infinity', svg('<path d="M0 0 L1e999 1"/>'), 'invalid-path-data', /not finite/],
  ['path not starting with moveto', svg('<path d="L1 1"/>'), 'invalid-path-data', /moveto/],
  ['bad transform', svg('<g transform="rotate(30"><path d="M0 0 L1 1"/></g>'), 'invalid-svg', /<g> at line 1: bad transform/],
  ['NaN in polygon points', svg('<polygon points="0,0 1,NaN 2,2"/>'), 'invalid-svg', /<polygon> at line 1: points has "NaN"/],
  ['bad rect length', svg('<rect width="ten" height="1"/>'), 'invalid-svg', /width="ten" is not a length/],
  ['use cycle', svg('<g id="a"><use href="#a"/></g>'), 'invalid-svg', /cycle/],
  ['use elements doubling at 24 levels', useDoubling(24), 'too-complex', /<g id="l\d+"> at line 1 draws more than 200,000 elements/],
  ['20,000 nested groups', nested(20_000), 'too-complex', /<g> at line 1 is nested deeper than 1,000 levels/],
  ['an entity bomb', lolz, 'too-complex', /DTD entities expand to more than 1\.0 MiB/],
  ['an entity that refers to itself', `<!DOCTYPE svg [<!ENTITY a "x&b;"><!ENTITY b "&a;">]>${svg('<text>&a;</text>')}`, 'invalid-svg', /the entity &a; refers to itself/],
];

beforeAll(async () => {
  await init();
});

afterAll(() => rmSync(dir, { recursive: true, force: true }));

describe('API', () => {
  test.each(cases)('%s', (_name, input, code, message) => {
    let error: unknown;
    try {
      parseSVG(input, { name: 'bad.svg' });
    } catch (err) {
      error = err;
    }
    expect(error).toBeInstanceOf(SplinekitError);
    expect((error as SplinekitError).code).toBe(code);
    expect((error as SplinekitError).message).toMatch(message);
    expect((error as SplinekitError).message).toMatch(/^bad\.svg: /);
  });

  test('a 50 MB input is refused before parsing', () => {
    const big = new Uint8Array(50 * 2 ** 20);
    expect(() => parseSVG(big, { name: 'big.svg' })).toThrowError(/big\.svg: 50\.0 MiB is larger than the 32 MiB limit/);
    // The limit is an option: a small one refuses a small file.
    expect(() => parseSVG(svg(''), { maxBytes: 10 })).toThrowError(SplinekitError);
  });

  test('an error leaves an earlier document untouched and later parses work', () => {
    const good = parseSVG(svg('<path d="M0 0 L1 1"/>'));
    const before = good.splines[0].points.slice();
    expect(() => parseSVG(svg('<path d="M0 0 L"/>'))).toThrowError(SplinekitError);
    expect(good.splines[0].points).toEqual(before);
    expect(parseSVG(svg('<path d="M0 0 L2 2"/>')).splines[0].points[6]).toBe(2);
  });

  test('degenerate but legal input is handled, not rejected', () => {
    const doc = parseSVG(svg('<path d="M1 1 C1 1 1 1 1 1 Z"/><path d="M0 0 C0 0 5 5 5 5"/><path d=""/><circle r="0"/>'));
    expect(doc.shapes).toHaveLength(4);
    expect(doc.splines.every((s) => s.points.every(Number.isFinite))).toBe(true);
    expect(doc.splines[1].continuity).toEqual([]);
  });
});

describe('CLI', () => {
  test.each(cases)('%s: exits 1 with one line naming the problem', (name, input, _code, message) => {
    const file = join(dir, `${name.replace(/\W+/g, '_')}.svg`);
    writeFileSync(file, input);
    const r = cli(['info', file]);
    expect(r.code).toBe(1);
    const lines = r.stderr.trimEnd().split('\n');
    expect(lines).toHaveLength(1);
    expect(lines[0]).toMatch(/^splinekit: /);
    expect(lines[0]).toMatch(message);
    expect(r.stderr).not.toMatch(/\bat .*\.js:\d+/); // no stack trace
    expect(r.stdout).toBe('');
  });

  test('a 50 MB file: one line, exit 1', () => {
    const file = join(dir, 'big.svg');
    writeFileSync(file, Buffer.alloc(50 * 2 ** 20, 0x20));
    const r = cli(['info', file]);
    expect(r.code).toBe(1);
    expect(r.stderr).toBe('splinekit: big.svg: 50.0 MiB is larger than the 32 MiB limit\n');
  });

  test('missing file and bad usage', () => {
    const missing = cli(['info', join(dir, 'nope.svg')]);
    expect(missing.code).toBe(1);
    expect(missing.stderr).toMatch(/^splinekit: cannot read .*nope\.svg: ENOENT\n$/);
    const usage = cli(['frobnicate']);
    expect(usage.code).toBe(2);
    expect(usage.stderr).toMatch(/unknown command "frobnicate"/);
    expect(cli(['info']).code).toBe(2);
    expect(cli(['info', 'a.svg', '--bogus']).code).toBe(2);
  });
});
