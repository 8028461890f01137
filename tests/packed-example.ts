// Shared by the unit and e2e tests of examples/: the package as a user gets it (`npm pack`), and a
// copy of one example project with that tarball installed, as its README tells a user to do.
import { execFileSync } from 'node:child_process';
import { cpSync, existsSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

export const repoRoot = new URL('..', import.meta.url).pathname;

/** Packs the built package into `dest` and returns the tarball's path (dist/ must be built). */
export function packTarball(dest: string): string {
  if (!existsSync(join(repoRoot, 'dist/browser/splinekit.js'))) throw new Error('dist/ is missing: run `npm run build` (npm test does) first');
  const packed = JSON.parse(execFileSync('npm', ['pack', '--json', '--pack-destination', dest], { cwd: repoRoot, encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }));
  return join(dest, packed[0].filename);
}

/**
 * Copies examples/<name> to `work`/<name> (without what running it may have left: node_modules,
 * its lock, outputs), points its `splinekit` dependency at `tarball` and runs `npm install`
 * there; `omitDev` leaves out its devDependencies (the tests run the repository's own vite
 * instead of installing another). Returns the copy's folder.
 */
export function installExample(name: string, tarball: string, work: string, omitDev = false): string {
  const dir = join(work, name);
  cpSync(join(repoRoot, 'examples', name), dir, { recursive: true, filter: (src) => !/[\\/](node_modules|dist|package-lock\.json|posed\.svg)$/.test(src) });
  const pkg = JSON.parse(readFileSync(join(dir, 'package.json'), 'utf8'));
  pkg.dependencies.splinekit = `file:${tarball}`;
  writeFileSync(join(dir, 'package.json'), JSON.stringify(pkg, null, 2));
  const args = ['install', '--no-audit', '--no-fund', '--prefer-offline', '--loglevel=error', ...(omitDev ? ['--omit=dev'] : [])];
  execFileSync('npm', args, { cwd: dir, stdio: 'ignore' });
  return dir;
}
