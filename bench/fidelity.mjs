// Fidelity figures (imported by bench/run.mjs): runs the e2e fidelity spec (tests/e2e/fidelity.spec.ts),
// which renders every SVG natively and in the editor and writes the per-file share of pixels that
// differ beyond anti-aliasing to build/fidelity*.json, and turns those files into the
// "Editor fidelity" section of BENCHMARKS.md. The test asserts the 1% bound; this records the figures.
import { execFileSync } from 'node:child_process';
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';

/** Runs the fidelity spec and returns its per-file figures, the posed comparisons apart. */
export function fidelityFigures(root) {
  execFileSync('bash', [join(root, 'scripts/setup.sh'), '--web'], { cwd: root, stdio: ['ignore', 'ignore', 'inherit'] });
  execFileSync('npx', ['playwright', 'test', 'tests/e2e/fidelity.spec.ts'], { cwd: root, stdio: ['ignore', 'ignore', 'inherit'] });
  const files = JSON.parse(readFileSync(join(root, 'build/fidelity.json'), 'utf8'));
  const posed = {};
  for (const f of readdirSync(join(root, 'build')).filter((f) => f.startsWith('fidelity-posed-'))) Object.assign(posed, JSON.parse(readFileSync(join(root, 'build', f), 'utf8')));
  return { files, posed };
}

/** The "Editor fidelity" section of BENCHMARKS.md. */
export function fidelitySection(r, { date, machine }) {
  const pct = (x) => `${(100 * x).toFixed(3)}%`;
  const row = ([name, c]) => `| ${name} | ${c.width}×${Math.round(c.height)} | ${pct(c.painted)} | ${pct(c.different)} |`;
  const entries = Object.entries(r.files).sort(([a], [b]) => a.localeCompare(b));
  const worst = entries.reduce((w, e) => (e[1].different > w[1].different ? e : w), entries[0]);
  return `## Editor fidelity (Chromium)

Measured by tests/e2e/fidelity.spec.ts (through bench/fidelity.mjs) on ${date} (${machine}): each
SVG rendered by Chromium as an \`<img>\` of the file and in the editor's view with the document's
frame at the same pixels (400 px on its longer side), and the share of pixels that differ beyond
anti-aliasing (no pixel of the other image's 3×3 neighbourhood within 40 per channel). The test
fails above 1%. Worst: ${worst[0]}, ${pct(worst[1].different)}.

| file | pixels | painted | differ |
|---|---:|---:|---:|
${entries.map(row).join('\n')}

Posed drawings (Skin mode, three handles, the last dragged), the editor's live view against
Chromium's rendering of the exported posed SVG; "rest vs posed view" (the file at rest against the posed view) shows the comparison can fail:

| comparison | pixels | painted | differ |
|---|---:|---:|---:|
${Object.entries(r.posed).map(row).join('\n')}
`;
}
