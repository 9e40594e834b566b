// The stand-in a pass's material carries past three.js's preprocessing (src/player/gpu/verbatim-source.js):
// the context is handed back the text it stands for, byte for byte, whatever three.js put around it.
import { expect, test } from 'vitest';
import { sendVerbatimSources, verbatimStandIn } from '../../src/player/gpu/verbatim-source.js';

/** A context whose shaderSource only keeps what it was given. */
function fakeContext() {
  const received = [];
  const gl = /** @type {any} */ ({ shaderSource: (/** @type {unknown} */ _shader, /** @type {string} */ text) => received.push(text) });
  sendVerbatimSources(gl);
  return { gl, received };
}

const TEXTS = [
  ['an #include in a comment and unroll pragmas', '#version 300 es\n/*\n#include <iostream>\n*/\n#pragma unroll_loop_start\n'],
  ["three.js's light and clipping-plane names", 'int a = NUM_DIR_LIGHTS + NUM_CLIPPING_PLANES + UNION_CLIPPING_PLANES;\n'],
  ['text beyond ASCII, and no line break at the end', '// café, 光, 🌈\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(1); }'],
];

test.each(TEXTS)('%s: the stand-in, inside what three.js builds around it, compiles as the text itself', (_, text) => {
  const standIn = verbatimStandIn(text);
  // nothing three.js's rewriting looks for: no `#`, no capitals past the stand-in's mark
  expect(standIn.slice(standIn.indexOf(':') + 1)).toMatch(/^[ 0-9a-f]+\n$/);
  const { gl, received } = fakeContext();
  gl.shaderSource(null, `#version 300 es\n#define SHADER_TYPE RawShaderMaterial\n#define SHADER_NAME \n${standIn}`);
  expect(received).toEqual([text]);
});

test('a source with no stand-in (three.js own, the copy pass) goes to WebGL unchanged', () => {
  const { gl, received } = fakeContext();
  gl.shaderSource(null, '#version 300 es\nvoid main() {}\n');
  expect(received).toEqual(['#version 300 es\nvoid main() {}\n']);
});
