// The API reference (build/api, TypeDoc, built by `npm run build` and `npm test`) covers the whole
// public surface: every export of the package is in it, with a doc comment. TypeDoc's own
// validation already fails the build on an undocumented symbol; this reads its JSON output
// independently, so a config change that switched the validation off would still be caught.
import { existsSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test } from 'vitest';
import * as api from '../../src/index.js';
import { repoRoot } from './helpers.js';

type CommentPart = { kind: string; text: string };
type Reflection = {
  name: string;
  kind: number;
  comment?: { summary: CommentPart[] };
  signatures?: Reflection[];
  getSignature?: Reflection;
  children?: Reflection[];
  flags?: { isPrivate?: boolean; isExternal?: boolean };
  /** 'reference' for a name exported again (e.g. inside the affine namespace): documented where it is declared. */
  variant?: string;
};

const json = join(repoRoot, 'build/api/splinekit.json');
const config = JSON.parse(readFileSync(join(repoRoot, 'typedoc.json'), 'utf8')) as { intentionallyNotDocumented?: string[] };
const exempt = new Set(config.intentionallyNotDocumented ?? []);

/** The text of a reflection's doc comment, from itself or its (get) signatures. */
function docText(r: Reflection): string {
  const own = [r.comment, ...(r.signatures ?? []).map((s) => s.comment), r.getSignature?.comment];
  return own.flatMap((c) => c?.summary ?? []).map((p) => p.text).join('').trim();
}

test('every runtime export of the package is in the API reference', () => {
  expect(existsSync(json), 'build/api/splinekit.json: run `npm run build` (npm test does)').toBe(true);
  const project = JSON.parse(readFileSync(json, 'utf8')) as Reflection;
  const documented = new Set((project.children ?? []).map((c) => c.name));
  const runtime = Object.keys(api);
  expect(runtime.length).toBeGreaterThan(30);
  expect(runtime.filter((name) => !documented.has(name))).toEqual([]);
  // and types only (interfaces, aliases) are there as well, e.g.:
  for (const name of ['Spline', 'ContinuityTag', 'SvgStats', 'TraceOptions', 'Keyframe', 'AffineMatrix']) expect(documented).toContain(name);
});

test('every exported symbol and its members have a doc comment', () => {
  const project = JSON.parse(readFileSync(json, 'utf8')) as Reflection;
  const missing: string[] = [];
  for (const top of project.children ?? []) {
    // Types re-exported from a dependency (Matrix from transformation-matrix) carry its comments.
    if (top.flags?.isExternal) continue;
    if (!exempt.has(top.name) && docText(top) === '') missing.push(top.name);
    // Members of classes and interfaces (constructors excepted: the class comment says how to make one).
    for (const member of top.children ?? []) {
      // Members inherited from outside (Error's message, stack, …) are documented where they come from.
      if (member.flags?.isPrivate || member.flags?.isExternal || member.variant === 'reference' || member.name === 'constructor') continue;
      const name = `${top.name}.${member.name}`;
      if (!exempt.has(name) && docText(member) === '') missing.push(name);
    }
  }
  expect(missing).toEqual([]);
  // Every public symbol is documented: typedoc.json exempts none.
  expect([...exempt]).toEqual([]);
});
