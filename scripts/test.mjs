#!/usr/bin/env node
// `npm test`: lint (ESLint, clang-format), native (ctest), unit (Vitest, real wasm in Node), e2e
// (Playwright in Debian Chromium), in that order. Stops at the first failing level and ends with
// one line, "N passed, N failed", totalled over the levels that ran (lint counts one check per tool).
import { spawn } from 'node:child_process';
import { mkdirSync, readFileSync, rmSync } from 'node:fs';
import { cppFiles, unformatted } from './lint.mjs';

const root = new URL('..', import.meta.url).pathname;
mkdirSync(`${root}build`, { recursive: true });
let passed = 0;
let failed = 0;

function run(cmd, args, env = {}) {
  return new Promise((resolve) => {
    let output = '';
    const child = spawn(cmd, args, { cwd: root, env: { ...process.env, ...env }, stdio: ['ignore', 'pipe', 'pipe'] });
    child.stdout.on('data', (d) => { output += d; process.stdout.write(d); });
    child.stderr.on('data', (d) => { output += d; process.stderr.write(d); });
    child.on('error', (err) => { output += String(err); });
    child.on('close', (code) => resolve({ code: code ?? 1, output }));
  });
}

function finish(ok) {
  console.log(`\n${passed} passed, ${failed} failed`);
  process.exit(ok ? 0 : 1);
}

function readJSON(path) {
  try {
    return JSON.parse(readFileSync(path, 'utf8'));
  } catch {
    return null;
  }
}

// ---- lint ----------------------------------------------------------------------------------
console.log('\n== lint (eslint, clang-format) ==');
{
  const { code } = await run('npx', ['eslint', '.']);
  if (code === 0) {
    console.log('eslint: no errors');
    passed += 1;
  } else {
    failed += 1;
    finish(false);
  }
  const cpp = cppFiles();
  const cf = await run('clang-format', ['--dry-run', '--Werror', ...cpp]);
  if (cf.code === 0) {
    console.log(`clang-format: ${cpp.length} C++ files formatted`);
    passed += 1;
  } else {
    console.log(`clang-format: ${unformatted(cf.output).length} C++ files are not formatted (npm run format formats them)`);
    failed += 1;
    finish(false);
  }
}

// ---- native -------------------------------------------------------------------------------
console.log('\n== native (ctest) ==');
{
  const { code, output } = await run('ctest', ['--test-dir', 'build/native', '--output-on-failure']);
  const m = /(\d+)% tests passed, (\d+) tests? failed out of (\d+)/.exec(output);
  if (m) {
    failed += Number(m[2]);
    passed += Number(m[3]) - Number(m[2]);
  }
  if (code !== 0 || !m || Number(m[3]) === 0) {
    if (!m) failed += 1;
    finish(false);
  }
}

// ---- unit -----------------------------------------------------------------------------------
console.log('\n== unit (vitest) ==');
{
  const json = `${root}build/vitest-results.json`;
  rmSync(json, { force: true });
  const { code } = await run('npx', ['vitest', 'run', '--reporter=default', '--reporter=json', `--outputFile.json=${json}`]);
  const r = readJSON(json);
  if (r) {
    passed += r.numPassedTests;
    failed += r.numFailedTests;
  }
  if (code !== 0 || !r || r.numTotalTests === 0) {
    if (!r) failed += 1;
    finish(false);
  }
}

// ---- e2e ------------------------------------------------------------------------------------
console.log('\n== e2e (playwright) ==');
{
  const json = `${root}build/playwright-results.json`;
  rmSync(json, { force: true });
  const { code } = await run('npx', ['playwright', 'test', '--reporter=list,json'], { PLAYWRIGHT_JSON_OUTPUT_NAME: json });
  const r = readJSON(json);
  if (r?.stats) {
    passed += r.stats.expected + (r.stats.flaky ?? 0);
    failed += r.stats.unexpected;
  }
  if (code !== 0 || !r?.stats || r.stats.expected === 0) {
    if (!r?.stats) failed += 1;
    finish(false);
  }
}

finish(true);
