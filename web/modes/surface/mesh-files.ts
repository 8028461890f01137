/**
 * The mesh files Surface mode opens: the package's format list (MESH_FORMATS), so the file inputs'
 * accept list and the test that sends a dropped or opened file to Surface mode read exactly what
 * SurfaceMesh.load reads.
 */
import { DEFAULT_MAX_BYTES, DEFAULT_MAX_MESH_BYTES, MESH_FILE_ACCEPT, MESH_FORMATS } from '../../../src/index.js';

/** The accept attribute of a mesh file input: ".obj,.off,…". */
export const MESH_ACCEPT = MESH_FILE_ACCEPT;

/** Whether a file name is a mesh Surface mode opens (by its extension, any case). */
export function isMeshFile(name: string): boolean {
  const dot = name.lastIndexOf('.');
  return dot >= 0 && (MESH_FORMATS as readonly string[]).includes(name.slice(dot + 1).toLowerCase());
}

/** Whether a file opened in Surface mode is an SVG drawing to place (else it is read as a mesh). */
export function isSvgFile(file: { name: string; type: string }): boolean {
  return /\.svg$/i.test(file.name) || file.type === 'image/svg+xml';
}

/**
 * The most bytes Surface mode reads of a file: the library's mesh limit for meshes (a 2M-triangle
 * scan is 40–80 MB), the SVG limit for drawings.
 */
export function surfaceFileLimit(file: { name: string; type: string }): number {
  return isSvgFile(file) ? DEFAULT_MAX_BYTES : DEFAULT_MAX_MESH_BYTES;
}
