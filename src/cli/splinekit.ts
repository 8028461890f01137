#!/usr/bin/env node
/**
 * The splinekit command line. Every command reads files, runs the wasm core and writes results;
 * a problem ends it with one line on stderr naming the problem (no stack trace) and a non-zero
 * exit code: 1 for bad input, 2 for bad usage.
 */
import { readFileSync } from 'node:fs';
import { init } from '../index.js';
import { UsageError, type Command } from './common.js';
import { edit } from './edit.js';
import { info } from './info.js';
import { morph } from './morph.js';
import { skin } from './skin.js';
import { skin3d } from './skin3d.js';
import { geodesic, trace } from './surface.js';

const COMMANDS: Record<string, Command> = { info, skin, skin3d, geodesic, trace, edit, morph };

function help(): string {
  const lines = ['usage: splinekit <command> [options]', '', 'commands:'];
  for (const [name, c] of Object.entries(COMMANDS)) lines.push(`  ${name.padEnd(10)} ${c.summary}`);
  lines.push('', 'splinekit <command> --help shows its options.');
  return lines.join('\n');
}

async function main(argv: string[]): Promise<number> {
  const [name, ...rest] = argv;
  if (!name || name === '--help' || name === '-h' || name === 'help') {
    console.log(help());
    return name ? 0 : 2;
  }
  if (name === '--version') {
    const pkg = JSON.parse(readFileSync(new URL('../../package.json', import.meta.url), 'utf8')) as { version: string };
    console.log(pkg.version);
    return 0;
  }
  const command = COMMANDS[name];
  if (!command) throw new UsageError(`unknown command "${name}" (commands: ${Object.keys(COMMANDS).join(', ')})`);
  if (rest.includes('--help') || rest.includes('-h')) {
    console.log(command.usage);
    return 0;
  }
  await init();
  await command.run(rest);
  return 0;
}

main(process.argv.slice(2)).then(
  (code) => process.exit(code),
  (err: unknown) => {
    if (err instanceof UsageError) {
      console.error(`splinekit: ${err.message}`);
      process.exit(2);
    }
    const message = err instanceof Error ? err.message : String(err);
    console.error(`splinekit: ${message.split('\n')[0]}`);
    process.exit(1);
  },
);
