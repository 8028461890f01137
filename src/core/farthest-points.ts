/**
 * Farthest-point sampling of 2D points: `count` of them, spread out, starting from the first and
 * adding each time the point farthest from those chosen (deterministic). Used to place handles
 * over a drawing by the tests and benchmarks.
 *
 * @param points x,y pairs (#points × 2).
 * @returns the chosen points, x,y pairs (count × 2), in the order they were chosen.
 */
export function farthestPoints(points: Float64Array, count: number): Float64Array {
  const n = points.length / 2, chosen = [0], dist = new Float64Array(n).fill(Infinity);
  while (chosen.length < Math.min(count, n)) {
    const last = chosen[chosen.length - 1];
    let best = 0;
    for (let p = 0; p < n; p++) {
      dist[p] = Math.min(dist[p], Math.hypot(points[2 * p] - points[2 * last], points[2 * p + 1] - points[2 * last + 1]));
      if (dist[p] > dist[best]) best = p;
    }
    chosen.push(best);
  }
  return Float64Array.from(chosen.flatMap((p) => [points[2 * p], points[2 * p + 1]]));
}
