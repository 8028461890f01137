// examples/html and examples/vite as a user runs them: the packed tarball installed into a copy of
// each example, the plain page served as it is, the Vite app built by `vite build`, both opened in
// Chromium. Each is served on a port the OS picks, so checkouts testing side by side never clash.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, statSync } from 'node:fs';
import { createServer, type Server } from 'node:http';
import { tmpdir } from 'node:os';
import { extname, join, normalize } from 'node:path';
import { installExample, packTarball, repoRoot } from '../packed-example.js';
import { expect, test } from './fixtures.js';

const TYPES: Record<string, string> = {
  '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.svg': 'image/svg+xml', '.json': 'application/json', '.css': 'text/css',
};

/** A static file server for `root` on 127.0.0.1 and a free port; resolves to its base URL. */
function serve(root: string, servers: Server[]): Promise<string> {
  const server = createServer((req, res) => {
    const path = normalize(join(root, decodeURIComponent(new URL(req.url ?? '/', 'http://x').pathname)));
    const file = path.endsWith('/') ? join(path, 'index.html') : path;
    try {
      if (!file.startsWith(root) || !statSync(file).isFile()) throw new Error('not a file');
      res.writeHead(200, { 'content-type': TYPES[extname(file)] ?? 'application/octet-stream' });
      res.end(readFileSync(file));
    } catch {
      res.writeHead(404).end();
    }
  });
  servers.push(server);
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => {
    const address = server.address();
    resolve(`http://127.0.0.1:${typeof address === 'object' && address ? address.port : 0}/`);
  }));
}

const work = mkdtempSync(join(tmpdir(), 'splinekit-examples-'));
const servers: Server[] = [];
let htmlURL = '', viteURL = '';

test.beforeAll(async () => {
  test.setTimeout(240_000);
  const tarball = packTarball(work);
  const html = installExample('html', tarball, work, true);
  const vite = installExample('vite', tarball, work, true);
  execFileSync(process.execPath, [join(repoRoot, 'node_modules/vite/bin/vite.js'), 'build', '--logLevel', 'warn'], { cwd: vite, stdio: 'ignore' });
  htmlURL = await serve(html, servers);
  viteURL = await serve(join(vite, 'dist'), servers);
});

test.afterAll(async () => {
  await Promise.all(servers.map((s) => new Promise((resolve) => s.close(resolve))));
  rmSync(work, { recursive: true, force: true });
});

/** The `d` of every path of the puppet's svg. */
const pathData = (page: import('@playwright/test').Page) => page.locator('#stage svg path').evaluateAll((ps) => ps.map((p) => p.getAttribute('d') ?? ''));

test('examples/html animates the character from the package browser bundle, without a bundler', async ({ page }) => {
  await page.goto(htmlURL);
  await expect(page.locator('#status')).toHaveText('animating 2 shapes with 2 handles');
  await expect(page.locator('#stage svg path')).toHaveCount(2); // the body and the eye, both rewritten as paths
  // Frames go on: the head nods, so the body's path data changes between two later frames.
  const frameCount = () => page.evaluate(() => Number(document.body.dataset.frames ?? 0));
  await expect.poll(frameCount).toBeGreaterThan(2);
  const first = await pathData(page);
  const after = await frameCount();
  await expect.poll(frameCount).toBeGreaterThan(after + 2);
  await expect.poll(async () => (await pathData(page))[0]).not.toBe(first[0]);
  // Every `d` is still cubic Bézier path data, nothing rasterized or flattened.
  for (const d of await pathData(page)) expect(d).toMatch(/^M[-\d.e ]+(C[-\d.e ]+)+Z$/);
});

test('examples/vite bundles the package by name and poses the character with the pointer', async ({ page }) => {
  await page.goto(viteURL);
  await expect(page.locator('#status')).toHaveText('2 shapes, 2 splines, 8 segments');
  await expect(page.locator('#stage svg path')).toHaveCount(2);
  const rest = await pathData(page);
  const box = (await page.locator('#stage svg').boundingBox())!;
  // The svg is 400 × 320 px for a 200 × 160 viewBox: move the head handle from (160, 85) to (160, 40).
  await page.mouse.move(box.x + 2 * 160, box.y + 2 * 40);
  await expect.poll(async () => (await pathData(page))[1]).not.toBe(rest[1]);
  // The eye (all but the head's weight) moved up by about 45 units: its path's first y drops.
  const firstY = (d: string) => Number(/^M\s*[-\d.e]+\s+([-\d.e]+)/.exec(d)![1]);
  const eye = (await pathData(page))[1];
  expect(firstY(rest[1]) - firstY(eye)).toBeGreaterThan(40);
  expect(firstY(rest[1]) - firstY(eye)).toBeLessThan(50);
});
