#!/usr/bin/env node
// `npm start`: serves the editor (Vite dev server) and opens it in a browser where there is a
// display; it opens with a sample drawing loaded.
import { createServer } from 'vite';

const canOpen = process.platform === 'darwin' || process.platform === 'win32' || Boolean(process.env.DISPLAY || process.env.WAYLAND_DISPLAY);
const server = await createServer({
  configFile: new URL('../web/vite.config.ts', import.meta.url).pathname,
  server: { open: canOpen },
});
await server.listen();
server.printUrls();
if (!canOpen) console.log('  (no display found: open the URL above in a browser)');
