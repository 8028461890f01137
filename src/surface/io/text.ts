/**
 * Reading numbers and tokens from the bytes of text mesh files (OBJ, OFF, ASCII PLY and STL):
 * byte codes, an exact fast decimal parser and a line-counting Scanner.
 */
import { SplinekitError } from '../../core/errors.js';

/** Byte codes the text readers test for. */
export const LF = 10, CR = 13, SP = 32, TAB = 9, SLASH = 47, MINUS = 45, PLUS = 43;
const HASH = 35, BSL = 92, DOT = 46;
const POW10 = [1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
  1e17, 1e18, 1e19, 1e20, 1e21, 1e22];
const DECIMAL = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;
/** A token that spells NaN or an infinity (which the readers refuse as coordinates). */
export const NON_FINITE = /^[+-]?(nan|inf|infinity)$/i;

/** The bytes b[s, e) as a Latin-1 string (for messages and keywords). */
export function latin1(b: Uint8Array, s: number, e: number): string {
  let out = '';
  for (let i = s; i < e; i++) out += String.fromCharCode(b[i]);
  return out;
}

/**
 * The decimal number in b[s, e), exactly as Number() would read it; NaN if it is not a plain decimal
 * (or ±Infinity / NaN when it spells one). Fast path (Clinger): at most 15 significant digits and a
 * decimal exponent within ±22, where one IEEE multiply or divide of exact values rounds correctly.
 */
export function parseDecimal(b: Uint8Array, s: number, e: number): number {
  let i = s, neg = false, c = b[i];
  if (c === MINUS) { neg = true; i++; } else if (c === PLUS) i++;
  let mant = 0, sig = 0, exp = 0, nd = 0;
  while (i < e) {
    c = b[i] - 48;
    if (c >>> 0 > 9) break;
    if (mant !== 0 || c !== 0) { mant = mant * 10 + c; sig++; }
    nd++;
    i++;
  }
  if (i < e && b[i] === DOT) {
    i++;
    while (i < e) {
      c = b[i] - 48;
      if (c >>> 0 > 9) break;
      if (mant !== 0 || c !== 0) { mant = mant * 10 + c; sig++; }
      exp--;
      nd++;
      i++;
    }
  }
  if (nd > 0 && i < e && (b[i] | 32) === 101 /* e */) {
    i++;
    let eneg = false;
    c = b[i];
    if (c === MINUS) { eneg = true; i++; } else if (c === PLUS) i++;
    let ev = 0, ed = 0;
    while (i < e && ev < 100000) {
      c = b[i] - 48;
      if (c >>> 0 > 9) break;
      ev = ev * 10 + c;
      ed++;
      i++;
    }
    if (ed === 0) return NaN;
    exp += eneg ? -ev : ev;
  }
  if (nd === 0 || i !== e) return slowDecimal(b, s, e);
  if (sig > 15 || exp > 22 || exp < -22) return Number(latin1(b, s, e)); // a valid decimal, off the fast path
  const v = mant === 0 ? 0 : exp >= 0 ? mant * POW10[exp] : mant / POW10[-exp];
  return neg ? -v : v;
}

function slowDecimal(b: Uint8Array, s: number, e: number): number {
  const text = latin1(b, s, Math.min(e, s + 400));
  if (DECIMAL.test(text)) return Number(text);
  if (NON_FINITE.test(text)) return text.toLowerCase().includes('inf') ? (text[0] === '-' ? -Infinity : Infinity) : NaN;
  return NaN;
}

/**
 * A cursor over the bytes of a text file that keeps the line number. Tokens are runs of bytes
 * above space; '#' starts a comment to the end of the line; with `continuation` (OBJ) a backslash
 * at the end of a line joins it with the next.
 */
export class Scanner {
  readonly b: Uint8Array;
  readonly n: number;
  pos: number;
  line: number;
  /** The last token read is b[ts, te). */
  ts = 0;
  te = 0;

  constructor(b: Uint8Array, readonly file: string, readonly continuation: boolean, pos = 0, line = 1) {
    this.b = b;
    this.n = b.length;
    if (pos === 0 && b.length >= 3 && b[0] === 0xef && b[1] === 0xbb && b[2] === 0xbf) pos = 3; // UTF-8 BOM
    this.pos = pos;
    this.line = line;
  }

  fail(message: string, line = this.line): never {
    throw new SplinekitError('invalid-input', `${this.file} line ${line}: ${message}`);
  }

  /** True when b[p] is a backslash that ends its line (only trailing CRs after it). */
  isContinuation(p: number): boolean {
    if (!this.continuation || this.b[p] !== BSL) return false;
    let q = p + 1;
    while (q < this.n && this.b[q] === CR) q++;
    return q >= this.n || this.b[q] === LF;
  }

  /** Skips spaces, tabs and CRs within the line (and line continuations). */
  skipBlanks(): void {
    const b = this.b, n = this.n;
    let p = this.pos;
    for (;;) {
      while (p < n) {
        const c = b[p];
        if (c === SP || c === TAB || c === CR || c === 11 || c === 12) p++;
        else break;
      }
      if (p < n && b[p] === BSL && this.isContinuation(p)) {
        p++;
        while (p < n && b[p] === CR) p++;
        if (p < n) { p++; this.line++; }
        continue;
      }
      break;
    }
    this.pos = p;
  }

  /** True at the end of the line, at a comment, or at the end of the input (after skipBlanks). */
  atLineEnd(): boolean {
    const p = this.pos;
    if (p >= this.n) return true;
    const c = this.b[p];
    return c === LF || c === HASH;
  }

  /** Moves past the end of the current line (and the lines it continues onto). */
  nextLine(): void {
    const b = this.b, n = this.n;
    let p = this.pos;
    for (;;) {
      const start = p;
      while (p < n && b[p] !== LF) p++;
      if (p >= n) break;
      let q = p - 1;
      while (q >= start && b[q] === CR) q--;
      p++;
      this.line++;
      if (!(this.continuation && q >= start && b[q] === BSL)) break;
    }
    this.pos = p;
  }

  /** Reads the next token of this line into [ts, te); false at the end of the line. */
  token(): boolean {
    this.skipBlanks();
    if (this.atLineEnd()) return false;
    const b = this.b, n = this.n;
    let p = this.pos;
    this.ts = p;
    while (p < n) {
      const c = b[p];
      if (c <= SP || c === HASH || (c === BSL && this.isContinuation(p))) break;
      p++;
    }
    this.te = p;
    this.pos = p;
    return true;
  }

  /** Reads the next token, crossing blank and comment lines; false at the end of the input. */
  anyToken(): boolean {
    while (!this.token()) {
      if (this.pos >= this.n) return false;
      this.nextLine();
    }
    return true;
  }

  /** The last token, shortened for messages. */
  text(): string {
    const t = latin1(this.b, this.ts, Math.min(this.te, this.ts + 40));
    return this.te - this.ts > 40 ? `${t}…` : t;
  }

  number(): number {
    return parseDecimal(this.b, this.ts, this.te);
  }

  /** The last token as a non-negative integer, or fails naming `what`. */
  count(what: string): number {
    const v = this.number();
    if (!Number.isInteger(v) || v < 0 || v > 2 ** 31 - 1) this.fail(`${what} '${this.text()}' is not a non-negative integer`);
    return v;
  }

  /** The last token as a finite coordinate of vertex `vertex` (0-based), or fails. */
  coordinate(vertex: number): number {
    const v = this.number();
    if (Number.isFinite(v)) return v;
    const t = this.text();
    if (Number.isNaN(v) && !NON_FINITE.test(t)) this.fail(`invalid coordinate '${t}' in vertex ${vertex + 1}`);
    return this.fail(`non-finite coordinate '${t}' in vertex ${vertex + 1}`);
  }
}
