#!/usr/bin/env node
// `npm run lint`: ESLint over the TypeScript and JavaScript (eslint.config.js) and clang-format
// over the C++ (.clang-format), both checking only. `npm run format` (`--fix`): clang-format -i
// on the C++, then eslint --fix. `npm test` runs the same two checks as its first level.
import { spawnSync } from 'node:child_process';
import { readdirSync } from 'node:fs';
import { join } from 'node:path';

const root = new URL('..', import.meta.url).pathname;

/** Folders whose C++ sources clang-format checks. */
export const CPP_DIRS = ['wasm', 'tests/native', 'bench/native'];

/** The C++ sources under CPP_DIRS (.cpp, .h), relative to the repository root, sorted. */
export function cppFiles() {
  return CPP_DIRS.flatMap((dir) =>
    readdirSync(join(root, dir), { recursive: true })
      .map(String)
      .filter((f) => /\.(cpp|h)$/.test(f))
      .map((f) => join(dir, f)),
  ).sort();
}

/** The files clang-format would change, parsed from its --dry-run warnings. */
export function unformatted(output) {
  return [...new Set([...output.matchAll(/^(.+?):\d+:\d+: (?:warning|error): code should be clang-formatted/gm)].map((m) => m[1]))];
}

function sh(cmd, args) {
  const r = spawnSync(cmd, args, { cwd: root, stdio: ['ignore', 'inherit', 'pipe'], encoding: 'utf8' });
  if (r.error) throw r.error;
  return { code: r.status ?? 1, stderr: r.stderr };
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const fix = process.argv.includes('--fix');
  let ok = true;
  if (fix) {
    ok = sh('clang-format', ['-i', ...cppFiles()]).code === 0 && ok;
    ok = sh('npx', ['eslint', '--fix', '.']).code === 0 && ok;
  } else {
    ok = sh('npx', ['eslint', '.']).code === 0 && ok;
    const { stderr } = sh('clang-format', ['--dry-run', ...cppFiles()]);
    const files = unformatted(stderr);
    if (files.length > 0) {
      process.stderr.write(stderr);
      console.log(`clang-format: ${files.length} C++ files are not formatted (npm run format formats them): ${files.join(' ')}`);
      ok = false;
    }
  }
  process.exit(ok ? 0 : 1);
}
