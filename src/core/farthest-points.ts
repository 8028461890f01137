/**
 * Farthest-point sampling of 2D (or `dim`-D) points: `count` of them, spread out, starting from
 * the first and adding each time the point farthest from those chosen (deterministic). Used to
 * place handles over a drawing or a cage by the tests and benchmarks.
 *
 * @param points coordinates, `dim` per point (#points × dim).
 * @param dim coordinates per point (default 2).
 * @returns the chosen points (count × dim), in the order they were chosen.
 */
export function farthestPoints(points: Float64Array, count: number, dim = 2): Float64Array {
  const n = points.length / dim, chosen = [0], dist = new Float64Array(n).fill(Infinity);
  const distance = (p: number, q: number) => {
    let s = 0;
    for (let a = 0; a < dim; a++) s += (points[dim * p + a] - points[dim * q + a]) ** 2;
    return Math.sqrt(s);
  };
  while (chosen.length < Math.min(count, n)) {
    const last = chosen[chosen.length - 1];
    let best = 0;
    for (let p = 0; p < n; p++) {
      dist[p] = Math.min(dist[p], distance(p, last));
      if (dist[p] > dist[best]) best = p;
    }
    chosen.push(best);
  }
  return Float64Array.from(chosen.flatMap((p) => Array.from(points.subarray(dim * p, dim * p + dim))));
}
