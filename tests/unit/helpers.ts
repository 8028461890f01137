// Shared helpers of the unit tests: where the shared data is, and independent geometry
// (plain JS, not the wasm core) to check the core against.
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';

export const repoRoot = new URL('../../', import.meta.url).pathname;
export const sharedData = join(repoRoot, '../shared/data');

/** Every SVG in ../shared/data/svg, as paths relative to the data folder. */
export function sharedSvgs(): string[] {
  const out: string[] = [];
  for (const dir of readdirSync(join(sharedData, 'svg'))) {
    for (const f of readdirSync(join(sharedData, 'svg', dir))) if (f.endsWith('.svg')) out.push(`svg/${dir}/${f}`);
  }
  return out.sort();
}

export function readShared(rel: string): string {
  return readFileSync(join(sharedData, rel), 'utf8');
}

/** Point of a cubic at t by the power basis (independent of the core's Bernstein evaluation). */
export function cubicAt(c: ArrayLike<number>, t: number): [number, number] {
  const out: [number, number] = [0, 0];
  for (let a = 0; a < 2; a++) {
    const p0 = c[a], p1 = c[2 + a], p2 = c[4 + a], p3 = c[6 + a];
    out[a] = p0 + t * (3 * (p1 - p0) + t * (3 * (p0 - 2 * p1 + p2) + t * (p3 - 3 * p2 + 3 * p1 - p0)));
  }
  return out;
}

/** Largest distance between corresponding x,y pairs of two arrays of the same length. */
export function maxDistance(a: ArrayLike<number>, b: ArrayLike<number>): number {
  if (a.length !== b.length) throw new Error(`lengths differ: ${a.length} vs ${b.length}`);
  let m = 0;
  for (let i = 0; i < a.length; i += 2) m = Math.max(m, Math.hypot(a[i] - b[i], a[i + 1] - b[i + 1]));
  return m;
}

import { spawnSync } from 'node:child_process';

/** Runs the built CLI (dist/cli/splinekit.js, made by `npm run build` / scripts/setup.sh). */
export function cli(args: string[], cwd = repoRoot): { code: number; stdout: string; stderr: string } {
  const r = spawnSync(process.execPath, [join(repoRoot, 'dist/cli/splinekit.js'), ...args], { cwd, encoding: 'utf8' });
  return { code: r.status ?? -1, stdout: r.stdout, stderr: r.stderr };
}

/** `<use>`s that double at each of `levels` levels: 2^levels copies of one path from a small file. */
export function useDoubling(levels: number): string {
  let body = '<defs><path id="l0" d="M0 0 L1 1"/>';
  for (let i = 1; i <= levels; i++) body += `<g id="l${i}"><use href="#l${i - 1}"/><use href="#l${i - 1}"/></g>`;
  return `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">${body}</defs><use href="#l${levels}"/></svg>`;
}

// The head of an Illustrator 16 "SVG 1.1" export, as it writes it.
export const ILLUSTRATOR_HEAD = `<?xml version="1.0" encoding="utf-8"?>
<!-- Generator: Adobe Illustrator 16.0.0, SVG Export Plug-In . SVG Version: 6.00 Build 0)  -->
<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" "http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd" [
	<!ENTITY ns_extend "http://ns.adobe.com/Extensibility/1.0/">
	<!ENTITY ns_ai "http://ns.adobe.com/AdobeIllustrator/10.0/">
	<!ENTITY ns_graphs "http://ns.adobe.com/Graphs/1.0/">
	<!ENTITY ns_vars "http://ns.adobe.com/Variables/1.0/">
	<!ENTITY ns_imrep "http://ns.adobe.com/ImageReplacement/1.0/">
	<!ENTITY ns_sfw "http://ns.adobe.com/SaveForWeb/1.0/">
	<!ENTITY ns_custom "http://ns.adobe.com/GenericCustomNamespace/1.0/">
	<!ENTITY ns_adobe_xpath "http://ns.adobe.com/XPath/1.0/">
	<!ENTITY ns_svg "http://www.w3.org/2000/svg">
	<!ENTITY ns_xlink "http://www.w3.org/1999/xlink">
]>`;
export const ILLUSTRATOR_BODY = `
<svg version="1.1" id="Layer_1" xmlns:x="&ns_extend;" xmlns:i="&ns_ai;" xmlns:graph="&ns_graphs;"
	 xmlns="&ns_svg;" xmlns:xlink="&ns_xlink;" x="0px" y="0px" width="200px" height="100px"
	 viewBox="0 0 200 100" enable-background="new 0 0 200 100" xml:space="preserve">
<switch>
	<foreignObject requiredExtensions="&ns_ai;" x="0" y="0" width="1" height="1">
		<i:pgfRef  xlink:href="#adobe_illustrator_pgf"></i:pgfRef>
	</foreignObject>
	<g i:extraneous="self">
		<path fill="#D84A38" d="M20,80 C20,20 80,20 80,80 Z"/>
		<circle fill="none" stroke="#000000" stroke-width="2" cx="140" cy="50" r="30"/>
		<rect x="10" y="10" width="20" height="10"/>
	</g>
</switch>
<i:pgf  id="adobe_illustrator_pgf"><![CDATA[ eJzs &ns_svg; stays as it is ]]></i:pgf>
</svg>`;

/** A flat U mesh (uShape) and the mesh points on it. */
export interface UShape {
  positions: number[];
  triangles: number[];
  /** Whether (x, y) lies on the U (outside the slot and the grid's edges). */
  on(x: number, y: number): boolean;
  /** The mesh point at (x, y): its cell's lower-right triangle when x - i >= y - j, else the other. */
  pointAt(x: number, y: number): { face: number; uv: [number, number] };
}

/**
 * A flat U in the plane z = 0: a w × h grid of unit cells, each split in two, without the slot of
 * cells x in [s, s + 2), y >= b: two arms joined at the bottom (points close in space, far apart on
 * the surface; the shortest path between the arms goes round the slot's two corners (s, b) and (s + 2, b)).
 */
export function uShape(w: number, h: number, s: number, b: number): UShape {
  const positions: number[] = [], triangles: number[] = [];
  const id = (i: number, j: number) => j * (w + 1) + i;
  for (let j = 0; j <= h; j++) for (let i = 0; i <= w; i++) positions.push(i, j, 0);
  const cells = new Map<number, number>();
  for (let j = 0; j < h; j++) {
    for (let i = 0; i < w; i++) {
      if (j >= b && i >= s && i < s + 2) continue;
      cells.set(j * w + i, triangles.length / 6);
      triangles.push(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  }
  const cell = (x: number, y: number) => (x >= 0 && x < w && y >= 0 && y < h ? cells.get(Math.floor(y) * w + Math.floor(x)) : undefined);
  return {
    positions,
    triangles,
    on: (x, y) => cell(x, y) !== undefined,
    pointAt(x, y) {
      const c = cell(x, y);
      if (c === undefined) throw new Error(`(${x}, ${y}) is not on the U`);
      const u = x - Math.floor(x), v = y - Math.floor(y);
      // Face 2c: (i,j), (i+1,j), (i+1,j+1): x = i + a + b, y = j + b. Face 2c+1: (i,j), (i+1,j+1), (i,j+1): x = i + a, y = j + a + b.
      return u >= v ? { face: 2 * c, uv: [u - v, v] } : { face: 2 * c + 1, uv: [u, v - u] };
    },
  };
}
