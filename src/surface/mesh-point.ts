/** A point on a face: (1−u−v)·p0 + u·p1 + v·p2 of the face's vertices, in file order. */
export interface MeshPoint {
  /** The face (file order). */
  face: number;
  /** Barycentric coordinates (u, v) with respect to the face's 2nd and 3rd vertex. */
  uv: [number, number];
}

/** A mesh point, or a vertex index (file order). */
export type MeshPointLike = MeshPoint | number;
