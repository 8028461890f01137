// The npm package as a user gets it: `npm pack`, install the tarball into an empty folder, and
// use the API (the README's embedding example, verbatim) and the CLI from there, with nothing
// but node on the PATH (no emscripten, no build tools).
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import ts from 'typescript';
import { afterAll, beforeAll, expect, test } from 'vitest';
import { repoRoot, sharedData } from './helpers.js';

const work = mkdtempSync(join(tmpdir(), 'splinekit-pkg-'));
const app = join(work, 'app');
const bin = join(work, 'bin');
let files: string[] = [];

/** PATH with node alone: proves the installed package needs no toolchain. */
const env = () => ({ PATH: bin, HOME: work });

beforeAll(() => {
  if (!existsSync(join(repoRoot, 'dist/index.js'))) throw new Error('dist/ is missing: run `npm run build` (npm test does) first');
  const packed = JSON.parse(execFileSync('npm', ['pack', '--json', '--pack-destination', work], { cwd: repoRoot, encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }));
  files = packed[0].files.map((f: { path: string }) => f.path);
  mkdirSync(app);
  writeFileSync(join(app, 'package.json'), JSON.stringify({ name: 'app', version: '1.0.0', type: 'module', private: true }));
  execFileSync('npm', ['install', '--no-audit', '--no-fund', '--prefer-offline', '--loglevel=error', join(work, packed[0].filename)], { cwd: app, stdio: 'ignore' });
  mkdirSync(bin);
  symlinkSync(process.execPath, join(bin, 'node'));
}, 180_000);

afterAll(() => rmSync(work, { recursive: true, force: true }));

test('the tarball holds the built JS, the wasm, types and the CLI, and no tests or data', () => {
  for (const f of ['dist/index.js', 'dist/index.d.ts', 'dist/core/splinekit-core.mjs', 'dist/core/splinekit-core.d.mts', 'dist/cli/splinekit.js', 'README.md', 'LICENSE', 'package.json']) {
    expect(files).toContain(f);
  }
  expect(files.filter((f) => !f.startsWith('dist/') && !['README.md', 'LICENSE', 'package.json'].includes(f))).toEqual([]);
  expect(files.some((f) => /\.(svg|obj|ply|ttf|otf)$/.test(f) || f.includes('test'))).toBe(false);
});

test('the README embedding example runs from the installed package', () => {
  const readme = readFileSync(join(repoRoot, 'README.md'), 'utf8');
  const m = /<!-- embed-example:start -->\s*```js\n([\s\S]*?)```\s*<!-- embed-example:end -->/.exec(readme);
  expect(m, 'README embedding example').not.toBeNull();
  writeFileSync(join(app, 'example.mjs'), m![1]);
  const r = spawnSync(join(bin, 'node'), ['example.mjs'], { cwd: app, env: env(), encoding: 'utf8' });
  expect(r.stderr).toBe('');
  expect(r.status).toBe(0);
  const [counts, ...svg] = r.stdout.split('\n');
  expect(counts).toBe('2 elements, 2 splines, 5 segments, 4 C1 junctions');
  const out = svg.join('\n');
  // The circle became a path in its group's space (document y 25 → local 15), keeping its fill.
  expect(out).toContain('<g transform="translate(10 10)"><path fill="teal" d="M35 15C35 28.2842712475 ');
  expect(out).toContain('<path d="M5 90 Q50 40 95 90" stroke="black" fill="none"/>');
});

test('the installed CLI runs with node alone on the PATH', () => {
  const r = spawnSync(join(app, 'node_modules/.bin/splinekit'), ['info', join(sharedData, 'svg/icons/fa_dragon.svg'), '--json', '-'], { cwd: app, env: env(), encoding: 'utf8' });
  expect(r.stderr).toBe('');
  expect(r.status).toBe(0);
  const json = JSON.parse(r.stdout);
  expect(json.counts.elements).toBe(1);
  expect(json.splines).toHaveLength(4); // the dragon's 4 subpaths (outline and holes)
  const bad = spawnSync(join(app, 'node_modules/.bin/splinekit'), ['info', join(app, 'package.json')], { cwd: app, env: env(), encoding: 'utf8' });
  expect(bad.status).toBe(1);
  expect(bad.stderr).toMatch(/^splinekit: package\.json: not well-formed XML|^splinekit: package\.json: /);
});

test('the packed types expose no wasm (embind) object and no raw handle', () => {
  // Walks every type reachable from the package's exports in the installed declarations (members,
  // signatures, type arguments, unions) with the TypeScript checker: none may be declared in the
  // module's hand-written embind declarations, and no public member may be called `handle` or
  // `raw`. (Private members are emitted without their types, so they expose nothing.)
  const root = join(app, 'node_modules/splinekit/dist');
  const program = ts.createProgram([join(root, 'index.d.ts')], { noEmit: true, skipLibCheck: true, strict: true });
  const checker = program.getTypeChecker();
  const entry = checker.getSymbolAtLocation(program.getSourceFile(join(root, 'index.d.ts'))!)!;
  const exports = checker.getExportsOfModule(entry);
  expect(exports.map((s) => s.name)).toEqual(expect.arrayContaining(['SurfaceMesh', 'SplineSet', 'SkinRig', 'SkinWeights', 'affine', 'AffineMatrix']));
  const ours = (d: ts.Declaration) => d.getSourceFile().fileName.startsWith(root);
  const leaks: string[] = [];
  const seen = new Set<ts.Type>();
  const visit = (type: ts.Type, where: string, depth = 0): void => {
    if (seen.has(type) || depth > 12) return;
    seen.add(type);
    const decls = (type.aliasSymbol ?? type.getSymbol())?.getDeclarations() ?? [];
    for (const d of decls) if (/splinekit-core\.d\.mts$/.test(d.getSourceFile().fileName)) leaks.push(`${where}: ${checker.typeToString(type)}`);
    if (decls.length && !decls.some(ours)) return; // lib, DOM, node, three: not ours to walk
    if (type.isUnionOrIntersection()) type.types.forEach((t) => visit(t, where, depth + 1));
    for (const t of (type as ts.TypeReference).typeArguments ?? []) visit(t, where, depth + 1);
    for (const t of type.aliasTypeArguments ?? []) visit(t, where, depth + 1);
    for (const p of checker.getPropertiesOfType(type)) {
      const d = p.valueDeclaration ?? p.getDeclarations()?.[0];
      if (!d || !ours(d)) continue;
      if (ts.getCombinedModifierFlags(d) & (ts.ModifierFlags.Private | ts.ModifierFlags.Protected)) continue;
      if (p.name === 'handle' || p.name === 'raw') leaks.push(`${where}.${p.name}`);
      visit(checker.getTypeOfSymbolAtLocation(p, d), `${where}.${p.name}`, depth + 1);
    }
    for (const kind of [ts.SignatureKind.Call, ts.SignatureKind.Construct]) {
      for (const sig of checker.getSignaturesOfType(type, kind)) {
        const decl = sig.getDeclaration();
        if (decl && ts.getCombinedModifierFlags(decl) & ts.ModifierFlags.Private) continue;
        sig.getParameters().forEach((p) => visit(checker.getTypeOfSymbol(p), `${where}(${p.name})`, depth + 1));
        visit(sig.getReturnType(), `${where}()`, depth + 1);
      }
    }
  };
  for (const symbol of exports) {
    const s = symbol.flags & ts.SymbolFlags.Alias ? checker.getAliasedSymbol(symbol) : symbol;
    const decl = s.valueDeclaration ?? s.getDeclarations()?.[0];
    if (!decl) continue;
    if (s.flags & ts.SymbolFlags.Value) visit(checker.getTypeOfSymbolAtLocation(s, decl), s.name); // statics, constructors, functions
    if (s.flags & (ts.SymbolFlags.Type | ts.SymbolFlags.Class)) visit(checker.getDeclaredTypeOfSymbol(s), s.name); // instances, interfaces
  }
  expect(seen.size).toBeGreaterThan(50); // the walk reached the API, not just its names
  expect(leaks).toEqual([]);
});
