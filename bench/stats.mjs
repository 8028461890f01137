// The statistics every benchmark section prints: medians, and the median time of a function.

/** The median of `xs` (the upper one of an even count); NaN for none. */
export function median(xs) {
  const s = [...xs].sort((a, b) => a - b);
  return s.length ? s[Math.floor(s.length / 2)] : NaN;
}

/** Median ms of fn over `repeats` runs after `warmup` runs. */
export function time(fn, repeats, warmup = 3) {
  for (let i = 0; i < warmup; i++) fn();
  const t = [];
  for (let i = 0; i < repeats; i++) {
    const a = performance.now();
    fn();
    t.push(performance.now() - a);
  }
  return median(t);
}
