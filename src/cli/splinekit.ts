#!/usr/bin/env node
/**
 * The splinekit command line. Every command reads files, runs the wasm core and writes results;
 * a problem ends it with one line on stderr naming the problem (no stack trace) and a non-zero
 * exit code: 1 for bad input, 2 for bad usage.
 */
import { readFileSync, statSync, writeFileSync } from 'node:fs';
import { basename } from 'node:path';
import { parseArgs, type ParseArgsConfig } from 'node:util';
import { SplinekitError, init } from '../index.js';
import { info } from './info.js';
import { skin } from './skin.js';
import { geodesic, trace } from './surface.js';

/** Raised for wrong usage (exit code 2). */
export class UsageError extends Error {}

export interface Command {
  summary: string;
  usage: string;
  run(args: string[]): Promise<void>;
}

const COMMANDS: Record<string, Command> = { info, skin, geodesic, trace };

function help(): string {
  const lines = ['usage: splinekit <command> [options]', '', 'commands:'];
  for (const [name, c] of Object.entries(COMMANDS)) lines.push(`  ${name.padEnd(10)} ${c.summary}`);
  lines.push('', 'splinekit <command> --help shows its options.');
  return lines.join('\n');
}

/** parseArgs with usage errors turned into UsageError. */
export function parse<T extends ParseArgsConfig>(config: T): ReturnType<typeof parseArgs<T>> {
  try {
    return parseArgs<T>(config);
  } catch (err) {
    throw new UsageError(err instanceof Error ? err.message : String(err));
  }
}

/** Reads an input file as bytes, refusing huge files before reading them. */
export function readInput(path: string, maxBytes: number): Uint8Array {
  let size: number;
  try {
    const st = statSync(path);
    if (!st.isFile()) throw new SplinekitError('invalid-input', `${path} is not a file`);
    size = st.size;
  } catch (err) {
    if (err instanceof SplinekitError) throw err;
    throw new SplinekitError('invalid-input', `cannot read ${path}: ${(err as NodeJS.ErrnoException).code ?? String(err)}`);
  }
  if (size > maxBytes) {
    throw new SplinekitError('file-too-large', `${basename(path)}: ${(size / 2 ** 20).toFixed(1)} MiB is larger than the ${(maxBytes / 2 ** 20).toFixed(0)} MiB limit`);
  }
  return readFileSync(path);
}

/** Reads and parses a JSON input file; `what` names it in errors. */
export function readJSON(path: string, what: string): unknown {
  let text: string;
  try {
    text = readFileSync(path, 'utf8');
  } catch (err) {
    throw new SplinekitError('invalid-input', `cannot read ${what} ${path}: ${(err as NodeJS.ErrnoException).code ?? String(err)}`);
  }
  try {
    return JSON.parse(text);
  } catch (err) {
    throw new SplinekitError('invalid-input', `${basename(path)}: not valid JSON: ${(err as Error).message}`);
  }
}

/** Writes JSON to a file, or to stdout for "-". */
export function writeJSON(path: string, value: unknown): void {
  const text = `${JSON.stringify(value)}\n`;
  if (path === '-') process.stdout.write(text);
  else writeFileSync(path, text);
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
