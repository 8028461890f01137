import { AnimationClip, BufferAttribute, BufferGeometry, Float32BufferAttribute, Mesh, MeshStandardMaterial, NumberKeyframeTrack, Scene } from 'three';
import { GLTFExporter } from 'three/examples/jsm/exporters/GLTFExporter.js';

/** A posed refined surface at a time of the animation. */
export interface SurfaceFrame {
  time: number;
  /** 3 per refined vertex. */
  positions: Float64Array;
}

/** Name of the exported mesh (and the animation track's target). */
export const GLTF_MESH_NAME = 'skinned-surface';
export const GLTF_CLIP_NAME = 'keyframes';

/** Smooth normals of a surface (three's, area weighted), for a morph target's shading. */
function normalsOf(positions: Float32Array, index: BufferAttribute): Float32Array {
  const g = new BufferGeometry();
  g.setAttribute('position', new BufferAttribute(positions, 3));
  g.setIndex(index);
  g.computeVertexNormals();
  return g.getAttribute('normal').array as Float32Array;
}

/**
 * The refined surface as a binary glTF (GLB) that plays in any viewer: the rest surface as the
 * mesh, one morph target per frame (absolute positions, with their normals), and one animation
 * whose weights track switches on frame k's target at frame k's time (linear in between, so an
 * in-between is the blend of its two frames' surfaces: the caller samples frames densely enough).
 * With a single frame the mesh shows it (its target's weight is 1).
 */
export async function animatedGLTF(rest: Float64Array, triangles: Uint32Array, frames: readonly SurfaceFrame[]): Promise<ArrayBuffer> {
  if (frames.length === 0) throw new Error('glTF export: no frames');
  const geometry = new BufferGeometry();
  const index = new BufferAttribute(triangles, 1);
  const restF = Float32Array.from(rest);
  geometry.setAttribute('position', new BufferAttribute(restF, 3));
  geometry.setIndex(index);
  geometry.computeVertexNormals();
  geometry.morphTargetsRelative = false;
  const morphPositions: Float32BufferAttribute[] = [], morphNormals: Float32BufferAttribute[] = [];
  geometry.morphAttributes.position = morphPositions;
  geometry.morphAttributes.normal = morphNormals;
  frames.forEach((f, k) => {
    if (f.positions.length !== rest.length) throw new Error(`glTF export: frame ${k} has ${f.positions.length / 3} vertices, the surface ${rest.length / 3}`);
    const p = Float32Array.from(f.positions);
    const position = new Float32BufferAttribute(p, 3);
    position.name = `t=${f.time.toFixed(3)}s`;
    morphPositions.push(position);
    morphNormals.push(new Float32BufferAttribute(normalsOf(p, index), 3));
  });
  const mesh = new Mesh(geometry, new MeshStandardMaterial({ color: 0xc4bcaf, roughness: 0.8, metalness: 0 }));
  mesh.name = GLTF_MESH_NAME;
  mesh.updateMorphTargets();
  const scene = new Scene();
  scene.add(mesh);
  const animations: AnimationClip[] = [];
  if (frames.length === 1) mesh.morphTargetInfluences![0] = 1;
  else {
    const n = frames.length;
    const values = new Float32Array(n * n);
    for (let k = 0; k < n; k++) values[k * n + k] = 1;
    const track = new NumberKeyframeTrack(`${GLTF_MESH_NAME}.morphTargetInfluences`, frames.map((f) => f.time), values);
    animations.push(new AnimationClip(GLTF_CLIP_NAME, frames[n - 1].time, [track]));
  }
  try {
    const out = await new GLTFExporter().parseAsync(scene, { binary: true, animations });
    if (!(out instanceof ArrayBuffer)) throw new Error('glTF export: the exporter did not answer binary glTF');
    return out;
  } finally {
    geometry.dispose();
    (mesh.material as MeshStandardMaterial).dispose();
  }
}
