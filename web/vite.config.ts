import { defineConfig } from 'vite';

const root = new URL('.', import.meta.url).pathname;

// The editor: web/ is the app, public/ its sample assets, src/ the package it embeds.
export default defineConfig({
  root,
  publicDir: `${root}../public`,
  base: './',
  build: {
    outDir: `${root}../build/web`,
    emptyOutDir: true,
    target: 'es2022',
    chunkSizeWarningLimit: 2000,
  },
  worker: { format: 'es' },
  server: { fs: { allow: [`${root}..`] } },
});
