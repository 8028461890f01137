// Skins an SVG character with two point handles: the tail handle stays, the head handle turns up
// by 30° and rises; writes the posed drawing to posed.svg, still cubic Bézier splines.
//   node skin.mjs [out.svg]
import { readFileSync, writeFileSync } from 'node:fs';
import { IDENTITY_MATRIX, SkinRig, init, parseSVG } from 'splinekit';

await init();
const doc = parseSVG(readFileSync(new URL('./character.svg', import.meta.url), 'utf8'), { name: 'character.svg' });
const { elements, splines, segments } = doc.stats();
console.log(`character.svg: ${elements} shapes, ${splines} splines, ${segments} segments`);

const tail = { x: 40, y: 85 }, head = { x: 160, y: 85 };
const rig = SkinRig.create(doc, { handles: [tail, head] }); // Shepard weights

/** matrix(a b c d e f) turning by `radians` about (cx, cy), then moving by (dx, dy). */
function turnAbout(cx, cy, radians, dx = 0, dy = 0) {
  const c = Math.cos(radians), s = Math.sin(radians);
  return [c, s, -s, c, cx - c * cx + s * cy + dx, cy - s * cx - c * cy + dy];
}

rig.pose([IDENTITY_MATRIX, turnAbout(head.x, head.y, -Math.PI / 6, 0, -20)]);
const out = process.argv[2] ?? 'posed.svg';
writeFileSync(out, rig.toSVG());
const fit = rig.error('fit').rms, naive = rig.error('naive').rms;
console.log(`posed with 2 handles: fit rms ${fit.toFixed(4)}, naive rms ${naive.toFixed(4)}; wrote ${out}`);

// Both handles moved alike move the whole drawing rigidly: every control point by exactly (10, -5).
const rest = doc.splines.flatMap((s) => Array.from(s.points));
const moved = rig.pose([[1, 0, 0, 1, 10, -5], [1, 0, 0, 1, 10, -5]]);
let worst = 0;
for (let i = 0; i < rest.length; i++) worst = Math.max(worst, Math.abs(moved[i] - rest[i] - (i % 2 === 0 ? 10 : -5)));
console.log(`translation of both handles reproduced within ${worst.toExponential(2)}`);
rig.dispose();
