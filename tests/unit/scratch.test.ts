import { test } from 'vitest';
import { readFileSync, readdirSync } from 'node:fs';
import { init, parseSVG } from '../../src/index.js';
test('scratch', async () => {
  await init();
  for (const dir of ['characters', 'illustrations', 'morph']) {
    const hist: Record<string, number> = {};
    for (const f of readdirSync(`../shared/data/svg/${dir}`)) {
      const doc = parseSVG(readFileSync(`../shared/data/svg/${dir}/${f}`, 'utf8'), { name: f });
      for (const s of doc.splines) for (const t of s.continuity) {
        if (t.ratio === 0) continue;
        const sn = Math.abs(Math.sin(t.angle));
        const k = Math.abs(t.angle) > Math.PI / 2 ? 'back' : sn === 0 ? 'zero' : String(Math.floor(Math.log10(sn)));
        hist[k] = (hist[k] ?? 0) + 1;
      }
    }
    console.log(dir, JSON.stringify(Object.entries(hist).sort()));
  }
});
