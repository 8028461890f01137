// Vite bundles the package like any other dependency: import it by name, import the drawing as
// text. Parses the character, rigs it with two handles and poses the head with the pointer.
import { IDENTITY_MATRIX, SkinRig, SvgPuppet, init, parseSVG } from 'splinekit';
import characterSVG from './character.svg?raw';

await init();
const doc = parseSVG(characterSVG, { name: 'character.svg' });
const head = { x: 160, y: 85 };
const rig = SkinRig.create(doc, { handles: [{ x: 40, y: 85 }, head] });
const stage = document.getElementById('stage');
const puppet = SvgPuppet.mount(stage, doc, rig);

/** The head handle follows the pointer (document units), the tail stays. */
function moveHead(x, y) {
  puppet.pose([IDENTITY_MATRIX, [1, 0, 0, 1, x - head.x, y - head.y]]);
}

puppet.svg.addEventListener('pointermove', (event) => {
  const m = puppet.svg.getScreenCTM()?.inverse();
  if (!m) return;
  const p = new DOMPoint(event.clientX, event.clientY).matrixTransform(m);
  moveHead(p.x, p.y);
});

const { splines, segments } = doc.stats();
document.getElementById('status').textContent = `${doc.shapes.length} shapes, ${splines} splines, ${segments} segments`;
