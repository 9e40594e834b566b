// llvmpipe's loop limit (src/shadertoy/loop-guard.js, src/api/loop-limit.js), run as a person runs
// the command line: each pass kind (Image, Buffer A, Cube A, Sound) counts the trips of ten loop
// shapes, one shape to a column of 8 pixels (8 samples for the Sound tab), so that the pixels that
// llvmpipe shades together (8 lanes) share a shape. Each count is written exactly into the colour
// (or the sample), and checked against the trips the shape makes, computed here. With the default
// renderer the picture is right whatever the count (llvmpipe, or SwiftShader where a loop would be
// cut, said in one line); asked for, llvmpipe fails, saying what it cut, and draws the loops it
// does not cut in full.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { builtPage } from '../../src/headless/page-server.js';
import { findMesa } from '../../src/headless/renderers.js';
import { readPng } from '../support/images.js';
import { runShaderproof } from '../support/shaderproof-child.js';

/**
 * The shapes, by column: [trips counted, what llvmpipe's 65,535 does to it, what it is]: 'cut'
 * (the count is wrong, and said), 'whole' (right, and nothing said), 'said' (right, and said cut:
 * the loop uses the limit up exactly, and a loop after it in a branch it does not take, which
 * llvmpipe runs masked, calls a function with a loop and is flagged when the spent limit stops
 * it; on the safe side). A nested loop's outer trips count against the limit too (300 × 300: 90,300).
 */
const SHAPES = /** @type {const} */ ([
  [65_534, 'whole', 'for, 65,534 trips'],
  [65_535, 'said', 'for, 65,535 trips: the limit exactly'],
  [65_536, 'cut', 'for, 65,536 trips'],
  [100_000, 'cut', 'for, 100,000 trips'],
  [90_000, 'cut', 'nested for, 300 x 300'],
  [100_000, 'cut', 'a function with a loop of 1,000, called in a loop of 100'],
  [100_000, 'cut', 'while, 100,000 trips'],
  [100_000, 'cut', 'do-while, 100,000 trips'],
  [40_000, 'whole', 'nested for, 200 x 200'],
  [60_000, 'whole', 'do-while, 60,000 trips'],
]);
const COLUMN = 8;
const WIDTH = SHAPES.length * COLUMN;
const HEIGHT = 8;

// One loop for the plain counts, first in the code: llvmpipe runs the loops of every branch, even
// where no pixel takes it (one trip each), and those trips count for the loops after them. Its
// bound is a variable: a condition that calls a function of the shader's own is taken to be cut
// when the limit stops the loop where that condition would have ended it (loop-guard.js).
// `zero` is 0 from a uniform (iTime; iSampleRate in the Sound tab, which has no iTime): no bound
// is a constant the compiler could fold.
const commonWith = (/** @type {string} */ zero) => `int innerTrips(int m) { int c = 0; for (int j = 0; j < m; j++) c++; return c; }
int trips(int k) {
  int z = ${zero};
  int n = 0;
  int bound = k == 0 ? 65534 + z : k == 1 ? 65535 + z : k == 2 ? 65536 + z : k == 3 ? 100000 + z : 0;
  for (int i = 0; i < bound; i++) n++;
  if (k == 4) { for (int i = 0; i < 300 + z; i++) for (int j = 0; j < 300 + z; j++) n++; }
  if (k == 5) { for (int i = 0; i < 100 + z; i++) n += innerTrips(1000 + z); }
  if (k == 6) { while (n < 100000 + z) n++; }
  if (k == 7) { do { n++; } while (n < 100000 + z); }
  if (k == 8) { for (int i = 0; i < 200 + z; i++) for (int j = 0; j < 200 + z; j++) n++; }
  if (k == 9) { do { n++; } while (n < 60000 + z); }
  return n;
}
vec4 encodeTrips(int n) { return vec4(float(n & 255), float((n >> 8) & 255), float(n >> 16), 255.0) / 255.0; }
`;
const COMMON = commonWith('int(iTime)');
const SHAPE_OF = `int(fragCoord.x) / ${COLUMN}`;

const IMAGE = `${COMMON}void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = encodeTrips(trips(${SHAPE_OF})); }\n`;

/** A Shadertoy export of `passes` (Image first), each {type, name, code, inputs, output id}. */
const exportOf = (passes) => ({
  Shader: {
    ver: '0.1',
    info: { id: 'loops', name: 'loop limit', description: 'written here' },
    renderpass: passes.map(({ type, name, code, inputs = [], id }) => ({
      inputs,
      outputs: [{ id, channel: 0 }],
      code,
      name,
      description: '',
      type,
    })),
  },
});
const sampler = { filter: 'nearest', wrap: 'clamp', vflip: 'false', srgb: 'false', internal: 'byte' };

/** Buffer A counts; the Image pass shows it texel for texel. */
const BUFFER = exportOf([
  {
    type: 'image',
    name: 'Image',
    id: '4dfGRr',
    code: 'void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(f), 0); }\n',
    inputs: [{ id: '4dXGR8', filepath: '/media/previz/buffer00.png', type: 'buffer', channel: 0, sampler, published: 1 }],
  },
  { type: 'buffer', name: 'Buffer A', id: '4dXGR8', code: IMAGE },
]);

/**
 * Cube A counts in the texels of its +X face at the picture's pixels (the rest of the map loops
 * not at all); the Image pass reads each along the ray to its texel's centre.
 */
const CUBE = exportOf([
  {
    type: 'image',
    name: 'Image',
    id: '4dfGRr',
    code: `void mainImage(out vec4 c, in vec2 f) {
  vec2 st = f / 1024.0 * 2.0 - 1.0;
  c = texture(iChannel0, vec3(1.0, -st.y, -st.x));
}\n`,
    inputs: [{ id: '4dX3Rr', filepath: '/media/previz/cubemap00.png', type: 'cubemap', channel: 0, sampler, published: 1 }],
  },
  {
    type: 'cubemap',
    name: 'Cube A',
    id: '4dX3Rr',
    code: `${COMMON}void mainCubemap(out vec4 fragColor, in vec2 fragCoord, in vec3 rayOri, in vec3 rayDir) {
  bool plusX = rayDir.x > abs(rayDir.y) && rayDir.x > abs(rayDir.z);
  fragColor = plusX && fragCoord.x < ${WIDTH}.0 && fragCoord.y < ${HEIGHT}.0 ? encodeTrips(trips(${SHAPE_OF})) : vec4(0.0);
}\n`,
  },
]);

/** The Sound tab counts in its first samples, 8 a shape: the count's low byte left, the rest right. */
const SOUND = exportOf([
  { type: 'image', name: 'Image', id: '4dfGRr', code: 'void mainImage(out vec4 c, in vec2 f) { c = vec4(0.0); }\n' },
  {
    type: 'sound',
    name: 'Sound',
    id: '4sXGRr',
    code: `${commonWith('int(iSampleRate) - 44100')}vec2 mainSound(int samp, float time) {
  int n = samp < ${WIDTH} ? trips(samp / ${COLUMN}) : 0;
  return vec2(float(n & 255) / 256.0, float(n >> 8) / 512.0);
}\n`,
  },
]);

let folder = '';
beforeAll(async () => {
  folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-loops-'));
  fs.writeFileSync(path.join(folder, 'image.glsl'), IMAGE);
  for (const [name, json] of Object.entries({ buffer: BUFFER, cube: CUBE, sound: SOUND }))
    fs.writeFileSync(path.join(folder, `${name}.json`), JSON.stringify(json));
  await builtPage();
});
afterAll(() => fs.rmSync(folder, { recursive: true, force: true }));

/** The command line in the folder, with no renderer in the environment unless `renderer`. */
const shaderproof = (/** @type {string[]} */ ...args) =>
  runShaderproof(args, { cwd: folder, timeout: 200_000, env: { SHADERPROOF_RENDERER: '' } });

/** The trips each column counted, read from a PNG's first row. @param {string} file */
function countsOfPicture(file) {
  const { data } = readPng(path.join(folder, file));
  return SHAPES.map((_, k) => {
    const at = k * COLUMN * 4;
    return data[at] + 256 * data[at + 1] + 65536 * data[at + 2];
  });
}

/** The trips each shape's first sample counted, read from a WAV (16-bit stereo after a 44-byte header). @param {string} file */
function countsOfSound(file) {
  const wav = fs.readFileSync(path.join(folder, file));
  return SHAPES.map((_, k) => {
    const at = 44 + k * COLUMN * 4;
    return Math.round(wav.readInt16LE(at) / 128) + 256 * Math.round(wav.readInt16LE(at + 2) / 64);
  });
}

const KINDS = /** @type {const} */ ([
  ['Image', 'image.glsl', 'png'],
  ['Buffer A', 'buffer.json', 'png'],
  ['Cube A', 'cube.json', 'png'],
  ['Sound', 'sound.json', 'wav'],
]);
const viewOf = (/** @type {string} */ format) => (format === 'wav' ? ['--duration', '0.002'] : ['--size', `${WIDTH}x${HEIGHT}`]);
const countsOf = (/** @type {string} */ file, /** @type {string} */ format) =>
  format === 'wav' ? countsOfSound(file) : countsOfPicture(file);
const expected = SHAPES.map(([trips]) => trips);

describe.runIf(findMesa().missing.length === 0)("llvmpipe's loop limit, in every pass kind", () => {
  test.each(KINDS)(
    '%s: the default renderer draws every count right, with SwiftShader where llvmpipe would cut',
    async (pass, file, format) => {
      const out = `default-${file}.${format}`;
      const run = await shaderproof('render', file, '-o', out, ...viewOf(format));
      expect(run.code, run.stderr).toBe(0);
      expect(countsOf(out, format)).toEqual(expected);
      expect(run.stderr.trim()).toBe(
        `note: ${file}: llvmpipe would cut a loop of its ${pass} pass short (it ends each pixel's loops after 65,535 trips in all): drawn with SwiftShader instead`,
      );
      expect(run.stdout).toMatch(/SwiftShader/);
    },
  );

  test.each(KINDS)('%s: --renderer llvmpipe fails, saying what it cut, and writes nothing', async (pass, file, format) => {
    const out = `llvmpipe-${file}.${format}`;
    const run = await shaderproof('render', file, '-o', out, ...viewOf(format), '--renderer', 'llvmpipe');
    expect(run.code).toBe(1);
    const first = format === 'wav' ? 'sample \\d+' : 'x \\d+, y \\d+ of frame 0';
    expect(run.stderr.trim().split('\n')).toEqual([
      expect.stringMatching(
        new RegExp(
          `^shaderproof render: ${file.replace('.', '\\.')}: llvmpipe cut a loop of the ${pass} pass short \\(the first pixel at ${first}\\): ` +
            "it ends each pixel's loops after 65,535 trips in all, so it cannot draw this shader; --renderer swiftshader draws it whole; nothing written$",
        ),
      ),
    ]);
    expect(fs.existsSync(path.join(folder, out))).toBe(false);
  });

  test('--renderer llvmpipe draws the loops it does not cut, counted in full, and says nothing', async () => {
    const uncut = SHAPES.map(([, fate], k) => (fate === 'cut' ? -1 : k));
    // the cut shapes' columns count none: each shape of the others in its own column, as above
    const code = IMAGE.replace(`trips(${SHAPE_OF})`, `trips(int[${SHAPES.length}](${uncut.join(', ')})[${SHAPE_OF}])`);
    fs.writeFileSync(path.join(folder, 'uncut.glsl'), code.replace(/\n {2}if \(k == 5\).*/, ''));
    const run = await shaderproof('render', 'uncut.glsl', '-o', 'uncut.png', '--size', `${WIDTH}x${HEIGHT}`, '--renderer', 'llvmpipe');
    expect(run.code, run.stderr).toBe(0);
    expect(run.stderr).toBe('');
    const counts = countsOfPicture('uncut.png');
    SHAPES.forEach(([trips, fate, what], k) => expect(counts[k], what).toBe(fate === 'cut' ? 0 : trips));
  });
});

describe.runIf(findMesa().missing.length === 0)('test: a case llvmpipe would cut fails, and writes no reference', () => {
  test('--update on the default renderer: the endless case fails at once, the other is written, with both reports', async () => {
    const cases = path.join(folder, 'cases');
    fs.mkdirSync(cases);
    fs.writeFileSync(
      path.join(cases, 'endless.glsl'),
      'void mainImage(out vec4 c, in vec2 f) { float x = 0.0; while (iResolution.x > 0.0) x += 1.0; c = vec4(x); }\n',
    );
    fs.writeFileSync(
      path.join(cases, 'plain.glsl'),
      'void mainImage(out vec4 c, in vec2 f) { c = vec4(f.x / iResolution.x, 0.5, 0.25, 1.0); }\n',
    );
    const run = await shaderproof('test', 'cases', '--update', '--out', 'out');
    expect(run.code, run.stderr).toBe(1);
    expect(run.stdout).toMatch(/^1 passed, 1 failed/m);
    expect(run.stdout).toMatch(/endless\.glsl.*llvmpipe cut a loop of the Image pass short.*--renderer swiftshader draws it whole/);
    expect(fs.readdirSync(path.join(cases, '__references__')).sort()).toEqual(['drawn-by.json', 'plain.glsl.png']);
    for (const report of ['junit.xml', 'index.html']) expect(fs.existsSync(path.join(folder, 'out', report)), report).toBe(true);
    expect(fs.readFileSync(path.join(folder, 'out', 'junit.xml'), 'utf8')).toMatch(/<failure[^>]*>[^<]*llvmpipe cut a loop/);
  });
});
