// Declarations of bench/meshes.mjs for the TypeScript tests that use it.
export function bumpyTorusPLY(n: number): Buffer;
