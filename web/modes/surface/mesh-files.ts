/**
 * The mesh files Surface mode opens, listed once: the file inputs' accept list and the test the
 * editor uses to send a dropped or opened file to Surface mode both come from here. (The package
 * reads the same formats: SurfaceMesh.load, meshFormatOf.)
 */
export const MESH_EXTENSIONS = ['obj', 'off', 'ply', 'stl', 'gltf', 'glb'] as const;

/** The accept attribute of a mesh file input: ".obj,.off,…". */
export const MESH_ACCEPT = MESH_EXTENSIONS.map((e) => `.${e}`).join(',');

/** Whether a file name is a mesh Surface mode opens (by its extension, any case). */
export function isMeshFile(name: string): boolean {
  const dot = name.lastIndexOf('.');
  return dot >= 0 && (MESH_EXTENSIONS as readonly string[]).includes(name.slice(dot + 1).toLowerCase());
}
