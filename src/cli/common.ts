/**
 * What the CLI's commands share: the Command shape, usage errors, argument parsing and reading
 * and writing files. Each command module imports this (never the entry, src/cli/splinekit.ts), so
 * a command can be imported and run in-process: `await init(); await info.run(['a.svg'])`.
 */
import { readFileSync, statSync, writeFileSync } from 'node:fs';
import { basename } from 'node:path';
import { parseArgs, type ParseArgsConfig } from 'node:util';
import { SplinekitError } from '../core/errors.js';

/** Raised for wrong usage (exit code 2). */
export class UsageError extends Error {}

/** A CLI command: `splinekit <name> ...args`. */
export interface Command {
  /** One line for `splinekit --help`. */
  summary: string;
  /** The text of `splinekit <name> --help`. */
  usage: string;
  /** Runs the command on its arguments (after the name); needs `await init()` first. */
  run(args: string[]): Promise<void>;
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

/** The median of `xs` (the upper one of an even count). */
export function median(xs: number[]): number {
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.floor(s.length / 2)];
}

/** Median milliseconds of `fn` over `runs` calls after `warmup` calls (the update timings the commands report). */
export function medianMs(fn: () => void, runs = 100, warmup = 10): number {
  const times: number[] = [];
  for (let i = 0; i < warmup + runs; i++) {
    const a = performance.now();
    fn();
    if (i >= warmup) times.push(performance.now() - a);
  }
  return median(times);
}
