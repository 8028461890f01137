/**
 * What the browser's WebGL runs on. On a software rasteriser (SwiftShader, llvmpipe: a machine
 * without a usable GPU, or headless Chromium) every pixel and triangle is shaded on the CPU, and
 * 4× multisampling costs as much again as the frame: a 2M-triangle mesh then takes seconds per
 * frame with it. Views use this to leave multisampling out there.
 */
let software: boolean | undefined;

/** Whether WebGL is rendered in software (read once, from a throwaway context). */
export function softwareWebGL(): boolean {
  if (software !== undefined) return software;
  software = false;
  try {
    const gl = document.createElement('canvas').getContext('webgl2') ?? document.createElement('canvas').getContext('webgl');
    if (gl) {
      const info = gl.getExtension('WEBGL_debug_renderer_info');
      const name = String(info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER));
      software = /swiftshader|llvmpipe|softpipe|software/i.test(name);
      gl.getExtension('WEBGL_lose_context')?.loseContext();
    }
  } catch {
    // No WebGL at all: the view reports that when it creates its own context.
  }
  return software;
}
