// The media the media-library tests make and what they must read back, computed: a 2 x 2
// texture, a cubemap whose every quadrant has its own colour, volumes whose texels encode their
// coordinates, a grey-noise texture, a non-square cube; Shadertoy JSON shaders whose pixel i
// shows probe i; and the expected colour of each probe. Shared by media-library.test.js (the
// page) and media-library-cli.test.js (the command line). No file of the site's media is used.

import fs from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';
import { expect } from 'vitest';
import { mediaFiles, writeVolume } from '../../src/shadertoy/media.js';
import { pixel } from './page-helpers.js';
import { MUSIC_READER } from './music-fixture.js';
import { cubeLookup } from './cube-lookup.js';

/** 8-bit output of a value the GPU filtered (an average of texels): one step of rounding each way. */
const FILTERED = 1;

// ---- the media, made here ---------------------------------------------------------------------

/** A w × h PNG from a function of (x, y), y counted from the file's top row. */
function png(width, height, colourAt) {
  const out = new PNG({ width, height });
  for (let y = 0; y < height; y++) for (let x = 0; x < width; x++) out.data.set([...colourAt(x, y), 255], (y * width + x) * 4);
  return PNG.sync.write(out);
}

/** The 2 × 2 texture, by the file's rows (top first). */
export const TEXELS = [
  [
    [200, 0, 0],
    [0, 200, 0],
  ],
  [
    [0, 0, 200],
    [100, 100, 100],
  ],
];
const AVERAGE = [0, 1, 2].map((c) => TEXELS.flat().reduce((sum, t) => sum + t[c], 0) / 4);

/** Cube face `f`'s texel at the file's (row, col): every quadrant of every face its own colour. */
const faceTexel = (f, row, col) => [20 + 40 * f, 30 + 60 * (row * 2 + col), 77];

/** The volume of bytes, three channels: texel (x, y, z) is (40 + 100x, 40 + 100y, 40 + 100z). */
export const byteTexel = (x, y, z) => [40 + 100 * x, 40 + 100 * y, 40 + 100 * z];
/** The volume of float, one channel. */
const floatTexel = (x, y, z) => (1 + x + 2 * y + 4 * z) / 10;
export const CORNERS = [0, 1, 2, 3, 4, 5, 6, 7].map((i) => /** @type {[number, number, number]} */ ([i & 1, (i >> 1) & 1, (i >> 2) & 1]));

export function writeMedia(dir) {
  const a = path.join(dir, 'a');
  fs.mkdirSync(a, { recursive: true });
  fs.writeFileSync(
    path.join(a, 'tex.png'),
    png(2, 2, (x, y) => TEXELS[y][x]),
  );
  mediaFiles({ kind: 'cubemap', src: '/media/a/cube.png' }).forEach((file, f) =>
    fs.writeFileSync(
      path.join(dir, file),
      png(2, 2, (x, y) => faceTexel(f, y, x)),
    ),
  );
  const bytes = CORNERS.flatMap(([x, y, z]) => byteTexel(x, y, z));
  fs.writeFileSync(path.join(a, 'bytes.bin'), writeVolume({ width: 2, height: 2, depth: 2, channels: 3, data: Uint8Array.from(bytes) }));
  const floats = CORNERS.map(([x, y, z]) => floatTexel(x, y, z));
  fs.writeFileSync(
    path.join(a, 'floats.bin'),
    writeVolume({ width: 2, height: 2, depth: 2, channels: 1, format: 'float', data: Float32Array.from(floats) }),
  );
  fs.writeFileSync(
    path.join(a, 'noise.png'),
    png(2, 2, () => [200, 100, 50]),
  );
  // a cubemap whose third face is not square: said, not drawn black without a word
  mediaFiles({ kind: 'cubemap', src: '/media/a/odd.png' }).forEach((file, f) =>
    fs.writeFileSync(path.join(dir, file), f === 2 ? png(2, 4, () => [9, 9, 9]) : png(2, 2, () => [9, 9, 9])),
  );
}

// ---- the shaders: one probe a pixel, in one row ----------------------------------------------

/** @param {number} channel @param {string} type @param {string} file @param {{filter?: string, wrap?: string, vflip?: boolean, id?: string}} [sampler] */
export const input = (channel, type, file, { filter = 'nearest', wrap = 'clamp', vflip = true, id = undefined } = {}) => ({
  channel,
  type,
  ...(id ? { id } : {}),
  filepath: file,
  previewfilepath: file,
  sampler: { filter, wrap, vflip: String(vflip), srgb: 'false', internal: 'byte' },
  published: 1,
});
export const shaderJson = (inputs, code) =>
  JSON.stringify({
    Shader: {
      ver: '0.1',
      info: { name: 'media probe' },
      renderpass: [{ inputs, outputs: [{ id: '4dfGRr', channel: 0 }], code, name: 'Image', description: '', type: 'image' }],
    },
  });
/** A shader whose pixel i shows `probes[i]` (GLSL expressions of a vec4). */
export const probeCode = (probes) =>
  `void mainImage(out vec4 c, in vec2 p) {\n  int i = int(p.x);\n  c = vec4(0.0, 0.0, 0.0, 1.0);\n${probes
    .map((probe, i) => `  if (i == ${i}) c = ${probe};`)
    .join('\n')}\n}\n`;
export const glslVec = (v) => `vec${v.length}(${v.map((x) => x.toFixed(4)).join(', ')})`;

/** The texture through four samplers: [probe, expected RGB, tolerance, what]. */
const TEXTURE_CASES = [
  ['texture(iChannel0, vec2(0.25, 0.75))', TEXELS[0][0], 0, 'vflip: v = 0.75 is the top row'],
  ['texture(iChannel0, vec2(0.75, 0.25))', TEXELS[1][1], 0, 'vflip: v = 0.25 is the bottom row'],
  ['texture(iChannel1, vec2(0.25, 0.75))', TEXELS[1][0], 0, 'no vflip: v = 0.75 is the file’s second row'],
  ['texture(iChannel1, vec2(1.25, 0.25))', TEXELS[0][0], 0, 'repeat: u = 1.25 is u = 0.25'],
  ['texture(iChannel0, vec2(1.25, 0.75))', TEXELS[0][1], 0, 'clamp: u = 1.25 is the right column'],
  ['texture(iChannel2, vec2(0.5))', AVERAGE, FILTERED, 'linear: the middle is the four texels’ mean'],
  ['texture(iChannel2, vec2(0.25, 0.75))', TEXELS[0][0], 0, 'linear at a texel’s centre is that texel'],
  ['textureLod(iChannel3, vec2(0.25), 1.0)', AVERAGE, FILTERED, 'mipmap: level 1 is the mean'],
  ['textureLod(iChannel0, vec2(0.25, 0.75), 1.0)', TEXELS[0][0], 0, 'nearest has no mipmaps: level 0'],
];
const TEXTURE_SHADER = shaderJson(
  [
    input(0, 'texture', '/media/a/tex.png', { filter: 'nearest', wrap: 'clamp', vflip: true }),
    input(1, 'texture', '/media/a/tex.png', { filter: 'nearest', wrap: 'repeat', vflip: false }),
    input(2, 'texture', '/media/a/tex.png', { filter: 'linear', wrap: 'clamp', vflip: true }),
    input(3, 'texture', '/media/a/tex.png', { filter: 'mipmap', wrap: 'repeat', vflip: true }),
  ],
  probeCode(TEXTURE_CASES.map(([probe]) => probe)),
);

/** The 24 directions into a cube's quadrants: major axis k >> 2 (+X, −X, +Y, −Y, +Z, −Z), the others ±0.5. */
export const CUBE_DIRECTIONS = Array.from({ length: 24 }, (_, k) => {
  const axis = k >> 2;
  const d = [0, 0, 0];
  d[axis >> 1] = axis & 1 ? -1 : 1;
  const others = [0, 1, 2].filter((c) => c !== axis >> 1);
  d[others[0]] = k & 1 ? 0.5 : -0.5;
  d[others[1]] = k & 2 ? 0.5 : -0.5;
  return d;
});

/**
 * The texel a direction reads, computed: the ES 3.0 table gives the face and (s, t), t = 0 the
 * first row uploaded; the site's upload gives which file and row that is.
 * @param {number[]} direction
 * @param {boolean} vflip
 */
export function cubeExpected(direction, vflip) {
  const { face, s, t } = cubeLookup(direction);
  const col = s < 0.5 ? 0 : 1;
  const uploadedRow = t < 0.5 ? 0 : 1;
  const file = vflip && (face === 2 || face === 3) ? 5 - face : face; // the site's trade of +Y and −Y

  return faceTexel(file, vflip ? 1 - uploadedRow : uploadedRow, col);
}
export const CUBE_SHADER = shaderJson(
  [input(0, 'cubemap', '/media/a/cube.png', { vflip: false }), input(1, 'cubemap', '/media/a/cube.png', { vflip: true })],
  probeCode([0, 1].flatMap((ch) => CUBE_DIRECTIONS.map((d) => `texture(iChannel${ch}, ${glslVec(d)})`))),
);
export const cubeCases = () => [false, true].flatMap((vflip) => CUBE_DIRECTIONS.map((d) => cubeExpected(d, vflip)));

/** Every texel of both volumes (at texel centres), their alpha, sizes, and the one-channel texture. */
export const centre = (v) => glslVec(v.map((c) => (c + 0.5) / 2));
const VOLUME_CASES = [
  ...CORNERS.map((v) => [`texture(iChannel0, ${centre(v)})`, byteTexel(...v), 0]),
  ...CORNERS.map((v) => [
    `vec4(texture(iChannel1, ${centre(v)}).r, texture(iChannel1, ${centre(v)}).g + texture(iChannel1, ${centre(v)}).b, texture(iChannel1, ${centre(v)}).a, 1.0)`,
    [floatTexel(...v) * 255, 0, 255],
    FILTERED,
  ]),
  ['vec4(vec3(texture(iChannel0, vec3(0.25)).a), 1.0)', [255, 255, 255], 0],
  ['vec4(iChannelResolution[0] * 10.0 / 255.0, 1.0)', [20, 20, 20], 0],
  ['texture(iChannel2, vec2(0.5))', [200, 0, 0], 0],
  ['vec4(vec3(texture(iChannel2, vec2(0.5)).a), 1.0)', [255, 255, 255], 0],
  ['vec4(iChannelResolution[2] * 10.0 / 255.0, 1.0)', [20, 20, 10], 0],
];
const VOLUME_SHADER = shaderJson(
  [
    input(0, 'volume', '/media/a/bytes.bin'),
    input(1, 'volume', '/media/a/floats.bin'),
    input(2, 'texture', '/media/a/noise.png', { id: 'Xdf3zn' }),
  ],
  probeCode(VOLUME_CASES.map(([probe]) => probe)),
);

/**
 * Music a Buffer A pass names (not the Image pass: every pass's channels read the library), copied
 * to the screen by the Image pass: the 512 x 2 texture and iChannelTime as music-fixture.js reads them.
 */
export const MUSIC_TIME = 1.9;
export const MUSIC_SHADER = JSON.stringify({
  Shader: {
    ver: '0.1',
    info: { name: 'music in a buffer' },
    renderpass: [
      {
        inputs: [input(0, 'music', '/media/a/tone.wav', { filter: 'linear', vflip: false })],
        outputs: [{ id: '4dXGR8', channel: 0 }],
        code: MUSIC_READER,
        name: 'Buffer A',
        description: '',
        type: 'buffer',
      },
      {
        inputs: [{ ...input(0, 'buffer', '/media/previz/buffer00.png'), id: '4dXGR8' }],
        outputs: [{ id: '4dfGRr', channel: 0 }],
        code: 'void mainImage(out vec4 c, in vec2 p) { c = texelFetch(iChannel0, ivec2(p), 0); }\n',
        name: 'Image',
        description: '',
        type: 'image',
      },
    ],
  },
});

/** Checks one row of probes against [expected RGB, tolerance] each. */
export function checkRow(image, cases, where) {
  cases.forEach(([expected, tolerance, what], i) => {
    const got = pixel(image, i, 0);
    const off = Math.max(...got.map((v, c) => Math.abs(v - expected[c])));
    expect(off, `${where}, probe ${i}${what ? ` (${what})` : ''}: got ${got}, expected ${expected.map(Math.round)}`).toBeLessThanOrEqual(
      tolerance + 0.5,
    );
  });
}

/** @type {Array<[string, string, () => any[]]>} */
export const SHADERS = [
  ['texture.json', TEXTURE_SHADER, () => TEXTURE_CASES.map(([, e, t, what]) => [e, t, what])],
  ['cube.json', CUBE_SHADER, () => cubeCases().map((e, i) => [e, 0, `direction ${CUBE_DIRECTIONS[i % 24]}, vflip ${i >= 24}`])],
  ['volume.json', VOLUME_SHADER, () => VOLUME_CASES.map(([, e, t]) => [e, t])],
];
