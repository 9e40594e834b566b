// A pass's fragment shader reaches WebGL byte for byte as composed (issue 37), past three.js.
//
// three.js's program builder (WebGLProgram, r187) rewrites a RawShaderMaterial's text before
// WebGL sees it: it puts `#version` (from glslVersion) and `#define SHADER_TYPE` / `SHADER_NAME`
// lines first; it resolves every line-leading `#include <name>`, in comments too, and throws for
// a name that is none of its chunks; it unrolls `#pragma unroll_loop_start` … `unroll_loop_end`
// loops; and it replaces NUM_DIR_LIGHTS, NUM_CLIPPING_PLANES and their kin with numbers wherever
// they stand. Shadertoy hands WebGL the text it composed and nothing else, so a shader that
// compiles on the site could fail here, or fail at another line.
//
// So the material three.js compiles carries a stand-in: one comment line holding the text in
// hexadecimal, where none of those patterns can occur (each needs a `#` or capitals). The
// context's shaderSource, given a source with a stand-in in it (what three.js built around it),
// sends the text the stand-in holds instead. three.js keeps everything else: the program, its
// uniforms, its cache (keyed by the stand-in, so by the text), the error hook, whose
// gl.getShaderSource then reads the text as composed.

const STAND_IN_MARK = '// verbatim source, UTF-8 in hex: ';

/** The character codes of the hexadecimal digits, by value. */
const HEX_DIGITS = new TextEncoder().encode('0123456789abcdef');

/** The value of a lower-case hexadecimal digit, given its character code. */
const hexValue = (/** @type {number} */ code) => (code <= 57 ? code - 48 : code - 87);

/**
 * The stand-in for a fragment shader's text: what goes in the material's fragmentShader.
 * (Byte arrays both ways: building the string a digit at a time took ~25 ms for an 85 kB shader.)
 * @param {string} text the whole shader, `#version` line first
 */
export function verbatimStandIn(text) {
  const bytes = new TextEncoder().encode(text);
  const digits = new Uint8Array(bytes.length * 2);
  for (let i = 0; i < bytes.length; i++) {
    digits[2 * i] = HEX_DIGITS[bytes[i] >> 4];
    digits[2 * i + 1] = HEX_DIGITS[bytes[i] & 15];
  }
  return `${STAND_IN_MARK}${new TextDecoder().decode(digits)}\n`;
}

/**
 * The text a shader source stands in for, or the source itself where it holds no stand-in.
 * @param {string} source
 */
function verbatimText(source) {
  const at = source.indexOf(STAND_IN_MARK);
  if (at < 0) return source;
  const start = at + STAND_IN_MARK.length;
  const end = source.indexOf('\n', start);
  const digits = new TextEncoder().encode(source.slice(start, end < 0 ? source.length : end));
  const bytes = new Uint8Array(digits.length / 2);
  for (let i = 0; i < bytes.length; i++) bytes[i] = (hexValue(digits[2 * i]) << 4) | hexValue(digits[2 * i + 1]);
  return new TextDecoder().decode(bytes);
}

/**
 * Makes `gl` compile the text of every stand-in it is given (verbatimStandIn), whatever three.js
 * put around it. Other sources pass unchanged.
 * @param {WebGL2RenderingContext} gl
 */
export function sendVerbatimSources(gl) {
  const shaderSource = gl.shaderSource;
  gl.shaderSource = (shader, source) => shaderSource.call(gl, shader, verbatimText(source));
}
