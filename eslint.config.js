// ESLint (flat config) for every TypeScript and JavaScript file of the repository: the package
// (src/), the editor (web/), the tests, the benchmarks and the scripts. `npm run lint` runs it,
// `npm test` runs it first (its "lint" level), `npm run format` applies its fixes.
//
// It checks correctness, not taste: ESLint's and typescript-eslint's recommended rules, and
// import-x/no-cycle, which keeps the layers' data flow one-way (core -> bindings -> src -> web; a
// command module imports its helpers, never the CLI entry that imports it). Layout is left as the
// code has it; the C++ is formatted by clang-format (.clang-format).
import js from '@eslint/js';
import { defineConfig } from 'eslint/config';
import { createTypeScriptImportResolver } from 'eslint-import-resolver-typescript';
import { importX } from 'eslint-plugin-import-x';
import globals from 'globals';
import tseslint from 'typescript-eslint';

export default defineConfig(
  {
    ignores: [
      'build/',
      'dist/',
      'node_modules/',
      'test-results/',
      'playwright-report/',
      // Emitted by em++ from wasm/bindings (its declarations, splinekit-core.d.mts, are linted).
      'src/core/splinekit-core.mjs',
    ],
  },
  js.configs.recommended,
  tseslint.configs.recommended,
  {
    plugins: { 'import-x': importX },
    settings: {
      // Follows imports into TypeScript and JavaScript modules alike (by default only .js).
      'import-x/extensions': ['.ts', '.mts', '.js', '.mjs'],
      'import-x/parsers': { '@typescript-eslint/parser': ['.ts', '.mts'] },
      // Resolves the NodeNext-style './x.js' specifiers to their './x.ts' sources.
      'import-x/resolver-next': [
        createTypeScriptImportResolver({
          project: ['tsconfig.json', 'web/tsconfig.json', 'tests/e2e/tsconfig.json'],
          noWarnOnMultipleProjects: true,
        }),
      ],
    },
    rules: {
      // A cycle makes a module's exports undefined while the cycle initialises, depending on which
      // module is imported first, and ties layers that should stand alone.
      'import-x/no-cycle': ['error', { ignoreExternal: true }],
    },
  },
  {
    rules: {
      // `_`-prefixed names are deliberately unused (a callback's leading parameters, a
      // destructured member left out).
      '@typescript-eslint/no-unused-vars': [
        'error',
        { argsIgnorePattern: '^_', varsIgnorePattern: '^_', caughtErrors: 'none', ignoreRestSiblings: true },
      ],
    },
  },
  // Where each file runs: the package runs in Node and browsers alike; the editor in the browser;
  // tests, benchmarks, scripts and configs in Node (e2e tests also hand callbacks to the page).
  { files: ['src/**'], languageOptions: { globals: { ...globals.browser, ...globals.node } } },
  { files: ['web/**'], languageOptions: { globals: globals.browser } },
  { files: ['tests/e2e/**'], languageOptions: { globals: { ...globals.node, ...globals.browser } } },
  {
    files: ['tests/unit/**', 'bench/**', 'scripts/**', 'public/**/*.mjs', 'examples/node/**', '*.js', '*.ts'],
    languageOptions: { globals: globals.node },
  },
  // The editor benchmark drives Chromium: its page.evaluate callbacks run in the page.
  { files: ['bench/editor.mjs', 'bench/editor-drag.mjs', 'bench/fidelity.mjs'], languageOptions: { globals: { ...globals.node, ...globals.browser } } },
  // The embedding examples that run in a browser page.
  { files: ['examples/html/**', 'examples/vite/**'], languageOptions: { globals: globals.browser } },
);
