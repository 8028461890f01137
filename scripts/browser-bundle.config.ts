import { defineConfig } from 'vite';

const root = new URL('..', import.meta.url).pathname;

// The package's browser bundle, dist/browser/splinekit.js: the built package (dist/index.js) with
// its dependencies (@xmldom/xmldom is CommonJS, so a page without a bundler cannot import the
// package's own dist/ through an import map) in one ES module. A plain page loads it with
// <script type="module">; three.js comes along as lazy chunks beside it, fetched only by
// SurfaceMesh.load / parseMesh for STL, glTF and GLB files. Built by scripts/setup.sh after tsc.
export default defineConfig({
  root,
  logLevel: 'warn',
  publicDir: false,
  build: {
    outDir: `${root}dist/browser`,
    emptyOutDir: true,
    target: 'es2022',
    minify: true,
    copyPublicDir: false,
    chunkSizeWarningLimit: 2000,
    lib: {
      entry: `${root}dist/index.js`,
      formats: ['es'],
      fileName: () => 'splinekit.js',
    },
  },
});
