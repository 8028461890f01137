/**
 * The mesh files Surface mode opens: the package's format list (MESH_FORMATS), so the file inputs'
 * accept list and the test that sends a dropped or opened file to Surface mode read exactly what
 * SurfaceMesh.load reads.
 */
import { MESH_FILE_ACCEPT, MESH_FORMATS } from '../../../src/index.js';

/** The accept attribute of a mesh file input: ".obj,.off,…". */
export const MESH_ACCEPT = MESH_FILE_ACCEPT;

/** Whether a file name is a mesh Surface mode opens (by its extension, any case). */
export function isMeshFile(name: string): boolean {
  const dot = name.lastIndexOf('.');
  return dot >= 0 && (MESH_FORMATS as readonly string[]).includes(name.slice(dot + 1).toLowerCase());
}
