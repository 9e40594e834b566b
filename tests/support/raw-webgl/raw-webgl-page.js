// The raw WebGL2 test page's own code, in the browser: plain WebGL2, no three.js, no page code.
// raw-webgl.html loads it through the harness's routes (routes.js: the files as they are on disk), so that it uses the same modules as
// the page and the Node side: Shadertoy's uniforms and their first-frame values from the
// Shadertoy module, the row flip and base64 from src/shared/pixels.js. raw-webgl.js (in Node) and
// the benchmark's timer (tests/bench/timer.js) call it through page.evaluate as window.__rawWebGL.

import { flipRows, toBase64 } from '../../../src/shared/pixels.js';
import { FIRST_FRAME_UNIFORMS, SHADERTOY_UNIFORMS } from '../../../src/shadertoy/header.js';

// One triangle that covers the viewport.
const VERTEX = `#version 300 es
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
`;

/** A WebGL2 context on a new width x height canvas, without anti-aliasing, depth or stencil (or null). */
function context(width, height, attributes = {}) {
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  return canvas.getContext('webgl2', { antialias: false, depth: false, stencil: false, ...attributes });
}

/**
 * Compiles the fullscreen vertex shader and `fragment`, links and uses them: { program } or { stage, log }.
 * @param {WebGL2RenderingContext} gl
 * @param {string} fragment
 * @returns {{program: WebGLProgram, stage?: undefined, log?: undefined} | {stage: 'vertex' | 'compile' | 'link', log: string, program?: undefined}}
 */
function program(gl, fragment) {
  const compile = (type, text) => {
    const shader = gl.createShader(type);
    if (!shader) throw new Error('createShader failed: the WebGL2 context is lost');
    gl.shaderSource(shader, text);
    gl.compileShader(shader);
    return shader;
  };
  const vs = compile(gl.VERTEX_SHADER, VERTEX);
  if (!gl.getShaderParameter(vs, gl.COMPILE_STATUS)) return { stage: 'vertex', log: gl.getShaderInfoLog(vs) ?? '' };
  const fs = compile(gl.FRAGMENT_SHADER, fragment);
  if (!gl.getShaderParameter(fs, gl.COMPILE_STATUS)) return { stage: 'compile', log: gl.getShaderInfoLog(fs) ?? '' };
  const linked = gl.createProgram();
  if (!linked) throw new Error('createProgram failed: the WebGL2 context is lost');
  gl.attachShader(linked, vs);
  gl.attachShader(linked, fs);
  gl.linkProgram(linked);
  if (!gl.getProgramParameter(linked, gl.LINK_STATUS)) return { stage: 'link', log: gl.getProgramInfoLog(linked) ?? '' };
  gl.useProgram(linked);
  return { program: linked };
}

/**
 * Sets a uniform of the current program from its GLSL type ('float', 'int', 'bool', 'vecN',
 * 'sampler2D', or an array of one of them, 'float[4]') and a number or a list of numbers.
 */
function setUniform(gl, location, type, value) {
  const values = typeof value === 'number' || typeof value === 'boolean' ? [Number(value)] : Array.from(value);
  const base = type.replace(/\[\d+\]$/, '');
  if (base === 'int' || base === 'bool' || base.startsWith('sampler')) gl.uniform1iv(location, values);
  else if (base === 'float') gl.uniform1fv(location, values);
  else if (/^vec[234]$/.test(base)) gl[`uniform${base.slice(3)}fv`](location, values);
  else throw new Error(`setUniform: no setter for GLSL type ${type}`);
}

/**
 * Sets every uniform of Shadertoy's header at its first-frame value (FIRST_FRAME_UNIFORMS),
 * iResolution = (width, height, 1), iDate from the clock (frozen by the deterministic injection),
 * iChannelN to texture unit N; then `overrides`, e.g. { iTime: 1.5, iFrame: 3, iMouse: [...] }.
 */
function setShadertoyUniforms(gl, linked, { width, height, overrides = {} }) {
  const now = new Date();
  const seconds = now.getHours() * 3600 + now.getMinutes() * 60 + now.getSeconds() + now.getMilliseconds() / 1000;
  const values = {
    ...FIRST_FRAME_UNIFORMS,
    iResolution: [width, height, 1],
    iDate: [now.getFullYear(), now.getMonth(), now.getDate(), seconds],
    ...overrides,
  };
  for (const name of Object.keys(overrides)) {
    if (!(name in SHADERTOY_UNIFORMS)) throw new Error(`${name} is not one of Shadertoy's uniforms`);
  }
  for (const [name, type] of Object.entries(SHADERTOY_UNIFORMS)) {
    const value = type.startsWith('sampler') ? Number(name.slice('iChannel'.length)) : values[name];
    setUniform(gl, gl.getUniformLocation(linked, name), type, value);
  }
}

/** The drawing buffer's RGBA8 pixels as base64, rows top to bottom. */
function readBase64(gl, width, height) {
  const pixels = new Uint8Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  return toBase64(flipRows(pixels, width, height));
}

function rendererName(gl) {
  const debug = gl.getExtension('WEBGL_debug_renderer_info');
  return debug ? gl.getParameter(debug.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
}

/**
 * What render() returns: why it could not draw, or the frame (base64 RGBA8, rows top to bottom).
 * Each has the other's fields as undefined, so that `stage` or `glError` can be read on either.
 * @typedef {{stage: 'vertex' | 'compile' | 'link' | 'setup', log: string, data?: undefined, glError?: undefined, renderer?: undefined}} RawRenderFailure
 * @typedef {{data: string, glError: number, renderer: string, stage?: undefined, log?: undefined}} RawRenderFrame
 */

/**
 * One frame of a complete fragment shader with Shadertoy's uniforms (see renderRawShader).
 * @returns {RawRenderFailure | RawRenderFrame}
 */
function render(fragment, { width, height, uniforms = {} }) {
  if (!window.__deterministic) return { stage: 'setup', log: 'the deterministic injection did not run' };
  const gl = context(width, height, { premultipliedAlpha: false, preserveDrawingBuffer: true });
  if (!gl) return { stage: 'setup', log: 'no WebGL2 context' };
  document.body.appendChild(/** @type {HTMLCanvasElement} */ (gl.canvas));
  const built = program(gl, fragment);
  if (built.stage) return { stage: built.stage, log: built.log };
  try {
    setShadertoyUniforms(gl, built.program, { width, height, overrides: uniforms });
  } catch (error) {
    return { stage: 'setup', log: error.message };
  }
  gl.viewport(0, 0, width, height);
  gl.drawArrays(gl.TRIANGLES, 0, 3);
  const data = readBase64(gl, width, height);
  return { data, glError: gl.getError(), renderer: rendererName(gl) };
}

/**
 * A fragment shader over a table of inputs, read back as RGBA32F (see evaluateFloatShader).
 * @returns {{error: string, data?: undefined} | {data: number[], error?: undefined}}
 */
function evaluateFloat(fragment, { width, height, table, tableHeight, tableUniform }) {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return { error: 'no WebGL2 context' };
  if (!gl.getExtension('EXT_color_buffer_float')) return { error: 'EXT_color_buffer_float is not supported' };
  const built = program(gl, fragment);
  if (built.stage) return { error: `${built.stage}: ${built.log}` };
  setShadertoyUniforms(gl, built.program, { width, height });
  const input = gl.createTexture();
  gl.activeTexture(gl.TEXTURE0);
  gl.bindTexture(gl.TEXTURE_2D, input);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, tableHeight, 0, gl.RGBA, gl.FLOAT, new Float32Array(table));
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  gl.uniform1i(gl.getUniformLocation(built.program, tableUniform), 0);
  const target = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, target);
  gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32F, width, height);
  const framebuffer = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, target, 0);
  gl.bindTexture(gl.TEXTURE_2D, input);
  gl.viewport(0, 0, width, height);
  gl.drawArrays(gl.TRIANGLES, 0, 3);
  const out = new Float32Array(width * height * 4);
  gl.readPixels(0, 0, width, height, gl.RGBA, gl.FLOAT, out);
  const glError = gl.getError();
  if (glError) return { error: `GL error ${glError}` };
  return { data: Array.from(out) };
}

const rawWebGL = { context, program, setUniform, setShadertoyUniforms, readBase64, render, evaluateFloat };
/** @typedef {typeof rawWebGL} RawWebGL window.__rawWebGL (tests/globals.ts) */
window.__rawWebGL = rawWebGL;
