// The Theora decoding of the site's .ogv videos, without a browser (issue 45, item 3): the
// colour conversion against BT.601's published equations and Theora's chroma siting, computed
// here; the stream (ogv.js's demuxer and decoder, run under Node from node_modules) against the
// fixture's frames (theora-fixture.js), in and out of order; and what a file that cannot be
// played says. The page and the command line: media-theora.test.js.

import fs from 'node:fs';
import { createRequire } from 'node:module';
import { describe, expect, test } from 'vitest';
import { theoraToRgba } from '../../src/player/inputs/theora-colour.js';
import { TheoraStream } from '../../src/player/inputs/theora-stream.js';
import { COLOUR_TOLERANCE, DURATION, THEORA_FILE, VIDEO, frameAt, pixelOf } from '../support/fixtures/theora-fixture.js';

const require = createRequire(import.meta.url);
const OGV = require.resolve('ogv/dist/ogv-demuxer-ogg-wasm.js').replace(/ogv-demuxer-ogg-wasm\.js$/, '');
/** ogv.js's modules as the page makes them, on their WebAssembly from node_modules; `frames` counts the frames decoded. */
function modules() {
  const counts = { frames: 0 };
  const make = {
    demuxer: () => require(`${OGV}ogv-demuxer-ogg-wasm.js`)({ wasmBinary: fs.readFileSync(`${OGV}ogv-demuxer-ogg-wasm.wasm`) }),
    decoder: async () => {
      const decoder = await require(`${OGV}ogv-decoder-video-theora-wasm.js`)({
        wasmBinary: fs.readFileSync(`${OGV}ogv-decoder-video-theora-wasm.wasm`),
      });
      const processFrame = decoder.processFrame;
      decoder.processFrame = (data, done) => {
        counts.frames++;
        processFrame(data, done);
      };
      return decoder;
    },
  };
  return { make, counts };
}
/** A file's bytes as the page has them (Blob.arrayBuffer()): an ArrayBuffer of their own. */
const bytes = (/** @type {Buffer} */ buffer) => Uint8Array.from(buffer).buffer;

// ---- the colour conversion -------------------------------------------------------------------

/** BT.601's inverse in 8-bit video range as the standard's users print it (rounded coefficients). */
const bt601 = (y, cb, cr) =>
  [
    1.164 * (y - 16) + 1.596 * (cr - 128),
    1.164 * (y - 16) - 0.392 * (cb - 128) - 0.813 * (cr - 128),
    1.164 * (y - 16) + 2.017 * (cb - 128),
  ].map((c) => Math.min(255, Math.max(0, c)));
/** The printed coefficients' rounding: at most 0.8 of a step over the range, and the output's own rounding. */
const COEFFICIENTS = 1.3;

/** A frame of ogv.js's shape: planes from functions of (x, y), chroma `sub` times smaller. */
function yuvFrame({ width, height, sub = 1, crop = { left: 0, top: 0, width, height }, y, u, v }) {
  const plane = (w, h, at) => ({ bytes: Uint8Array.from({ length: w * h }, (_, i) => at(i % w, Math.floor(i / w))), stride: w });
  const [cw, ch] = [width / sub, height / sub];
  return {
    format: {
      width,
      height,
      chromaWidth: cw,
      chromaHeight: ch,
      cropLeft: crop.left,
      cropTop: crop.top,
      cropWidth: crop.width,
      cropHeight: crop.height,
      displayWidth: crop.width,
      displayHeight: crop.height,
    },
    y: plane(width, height, y),
    u: plane(cw, ch, u),
    v: plane(cw, ch, v),
  };
}
const rgbAt = (rgba, width, x, y) => [...rgba.slice((y * width + x) * 4, (y * width + x) * 4 + 3)];

describe('Theora pictures to RGBA', () => {
  test.each([
    ['black', 16, 128, 128],
    ['white', 235, 128, 128],
    ['mid grey', 126, 128, 128],
    ['BT.601 red', 81, 90, 240],
    ['BT.601 green', 145, 54, 34],
    ['BT.601 blue', 41, 240, 110],
    ['a skin tone', 150, 110, 160],
    ['below black: clamped', 0, 128, 128],
    ['above white: clamped', 255, 128, 128],
  ])('%s (Y′ %i, Cb %i, Cr %i) is BT.601 in video range', (_, y, cb, cr) => {
    const rgba = theoraToRgba(yuvFrame({ width: 2, height: 2, y: () => y, u: () => cb, v: () => cr }));
    const got = rgbAt(rgba, 2, 1, 1);
    bt601(y, cb, cr).forEach((expected, c) =>
      expect(Math.abs(got[c] - expected), `channel ${c}: ${got}`).toBeLessThanOrEqual(COEFFICIENTS),
    );
    expect(rgba[3]).toBe(255);
  });

  test('4:2:0 chroma sits centred between its luma samples and is mixed bilinearly; a picture never reads the frame’s padding', () => {
    // Cb steps from 128 to 228 between chroma columns 0 and 1 (and rows alike): luma columns 0..3 lie at chroma
    // columns -0.25, 0.25, 0.75, 1.25, so they take 0, 1/4, 3/4 and all of the step (clamped at the edges)
    const step = [0, 0.25, 0.75, 1];
    const frame = yuvFrame({ width: 4, height: 4, sub: 2, y: () => 126, u: (x, y) => (x === 1 && y === 1 ? 228 : 128), v: () => 128 });
    const rgba = theoraToRgba(frame);
    for (let y = 0; y < 4; y++)
      for (let x = 0; x < 4; x++) {
        const cb = 128 + 100 * step[x] * step[y];
        const blue = rgbAt(rgba, 4, x, y)[2];
        expect(Math.abs(blue - bt601(126, cb, 128)[2]), `(${x}, ${y}): blue ${blue}`).toBeLessThanOrEqual(COEFFICIENTS);
      }
    // a 2 × 2 picture at (2, 2) of that frame: its one chroma sample is (1, 1), whatever lies beside it
    const cropped = theoraToRgba({ ...frame, format: { ...frame.format, cropLeft: 2, cropTop: 2, cropWidth: 2, cropHeight: 2 } });
    expect(cropped.length).toBe(2 * 2 * 4);
    for (let i = 0; i < 4; i++) expect(Math.abs(cropped[i * 4 + 2] - bt601(126, 228, 128)[2])).toBeLessThanOrEqual(COEFFICIENTS);
    // and at (0, 0): chroma (0, 0) alone
    const corner = theoraToRgba({ ...frame, format: { ...frame.format, cropWidth: 2, cropHeight: 2 } });
    for (let i = 0; i < 4; i++) expect(Math.abs(corner[i * 4 + 2] - bt601(126, 128, 128)[2])).toBeLessThanOrEqual(COEFFICIENTS);
  });
});

// ---- the stream ------------------------------------------------------------------------------

/** The fixture's patches' middles and its last column, and what frame i holds there. */
const TEXELS = [
  [24, 8],
  [24, 40],
  [VIDEO.width - 1, 24],
];
function expectFrame(frame, index, where) {
  expect(frame.format).toMatchObject({ cropWidth: VIDEO.width, cropHeight: VIDEO.height });
  const rgba = theoraToRgba(frame);
  for (const [x, y] of TEXELS) {
    const got = rgbAt(rgba, VIDEO.width, x, y);
    const off = Math.max(...got.map((c, i) => Math.abs(c - pixelOf(index, x, y)[i])));
    expect(off, `${where}: frame ${index} at (${x}, ${y}) is ${got}`).toBeLessThanOrEqual(COLOUR_TOLERANCE);
  }
}

/** The pages of an Ogg file whose stream is the `n`th to begin (its serial number is that page's), as a file of their own. */
function oneStream(file, n) {
  const pages = [];
  for (let at = 0; at < file.length;) {
    const segments = file[at + 26];
    const length = 27 + segments + file.subarray(at + 27, at + 27 + segments).reduce((a, b) => a + b, 0);
    pages.push(file.subarray(at, at + length));
    at += length;
  }
  const serial = pages[n].readUInt32LE(14);
  return Buffer.concat(pages.filter((page) => page.readUInt32LE(14) === serial));
}

describe('an Ogg file’s Theora stream, decoded by ogv.js', () => {
  test('the fixture: its rate, length and keyframes; every frame at its time, in order and out of it, decoded from its keyframe or on from the last', async () => {
    const { make, counts } = modules();
    const stream = await TheoraStream.open(bytes(fs.readFileSync(THEORA_FILE)), make);
    expect(stream.rate).toBe(VIDEO.fps);
    expect(stream.duration).toBeCloseTo(DURATION, 9);
    expect(stream.packets.map((p) => p.key)).toEqual([0, 0, 0, 3, 3, 3]);
    for (const t of [0, 0.05, 0.1, 0.15, 0.3, 0.35, 0.5, 0.59]) expect(stream.indexAt(t), `iTime ${t}`).toBe(frameAt(t).index);
    expect(stream.timeOf(4)).toBeCloseTo(0.4, 9);
    // [frame, frames decoded to reach it]: on from the last where no keyframe lies between, else from the keyframe
    const steps = [
      [0, 0], // opening decoded it
      [1, 1],
      [2, 1],
      [4, 2], // 3 is a keyframe: 3, 4
      [5, 1],
      [1, 2], // back: 0, 1
      [1, 0], // the same frame again: the decoder's frame as it is
      [3, 1],
      [0, 1],
    ];
    for (const [index, decodes] of steps) {
      const before = counts.frames;
      expectFrame(stream.decode(index), index, `decode(${index})`);
      expect(counts.frames - before, `decode(${index}) after the last`).toBe(decodes);
    }
  });

  test('a duplicate frame (no packet of its own) shows the frame before it; the video ends with its last frame', () => {
    const packets = [0, 1, 3].map((offset) => ({ data: new ArrayBuffer(1), offset, key: 0 }));
    const stream = new TheoraStream(/** @type {any} */ ({}), packets, 10, 4);
    expect([0, 0.15, 0.2, 0.29, 0.3, 0.39].map((t) => stream.indexAt(t))).toEqual([0, 1, 1, 1, 2, 2]);
    expect(stream.duration).toBeCloseTo(0.4, 9);
  });

  test.each([
    ['an Ogg file of Vorbis sound alone', () => oneStream(fs.readFileSync(THEORA_FILE), 1), /^it has no Theora video track$/],
    [
      'a file cut short in its headers',
      () => fs.readFileSync(THEORA_FILE).subarray(0, 200),
      /^its Theora stream has 1 of its 3 headers \(the file is cut short or damaged\)$/,
    ],
    ['not an Ogg file', () => Buffer.from('not a video at all'), /^it has no Theora video track$/],
  ])('%s says why in one line', async (_, file, message) => {
    await expect(TheoraStream.open(bytes(file()), modules().make)).rejects.toThrow(message);
  });
});
