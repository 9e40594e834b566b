// The harness's pure parts (no browser): blank detection, the tolerance, failure images, log
// mapping, PNG I/O, finding Chromium.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { describe, expect, test } from 'vitest';
import { composeImageShader } from '../../src/shadertoy/header.js';
import { findChrome } from '../../src/headless/chrome-path.js';
import { OUTPUT_DIR } from '../support/config.js';
import {
  allowedDiffPixels,
  blankReason,
  compareImages,
  expectImagesMatch,
  makeImage as image,
  readPng,
  writePng,
} from '../support/images.js';
import { mapShaderLog } from '../support/raw-webgl/raw-webgl.js';
import { MAX_DIFF_FRACTION, PIXEL_THRESHOLD } from '../support/tables/views.js';
const gradient = (x, y) => [(x * 2) % 200, (y * 2) % 200, 128];

describe('blankReason', () => {
  test.each([
    ['uniform grey', image(32, 32, () => [90, 90, 90]), /single colour/],
    ['white (Shadertoy 1e20)', image(32, 32, (x) => (x === 0 ? [250, 251, 255] : [255, 255, 255])), /white/],
    ['black', image(32, 32, (x, y) => (x + y === 0 ? [5, 0, 0] : [0, 0, 0])), /black/],
    ['few colours', image(32, 32, (x) => [x % 4, 100, 100]), /only 4 colours/],
    ['empty', { width: 0, height: 0, data: Buffer.alloc(0) }, /empty/],
  ])('%s is blank', (_, img, reason) => {
    expect(blankReason(img)).toMatch(reason);
  });

  test('a gradient is a picture', () => {
    expect(blankReason(image(32, 32, gradient))).toBeNull();
  });

  test('transparent pixels are reported', () => {
    const img = image(32, 32, gradient);
    img.data[3] = 0;
    expect(blankReason(img)).toMatch(/not opaque/);
  });
});

describe('compareImages and the tolerance', () => {
  const w = 100;
  const h = 100;
  const base = image(w, h, gradient);

  test('identical images match', () => {
    expect(compareImages(base, image(w, h, gradient)).diffPixels).toBe(0);
  });

  test('a 2-level change everywhere (cross-build rounding) is under the per-pixel threshold', () => {
    const shifted = image(w, h, (x, y) => gradient(x, y).map((c) => Math.min(255, c + 2)));
    expect(compareImages(shifted, base).diffPixels).toBe(0);
  });

  test('a 40-level change in a 10x10 patch counts every pixel of it, edges included', () => {
    const patched = image(w, h, (x, y) =>
      x >= 40 && x < 50 && y >= 40 && y < 50 ? gradient(x, y).map((c) => (c + 40 > 255 ? c - 40 : c + 40)) : gradient(x, y),
    );
    const { diffPixels, diff } = compareImages(patched, base);
    expect(diffPixels).toBe(100);
    expect(diffPixels).toBeGreaterThan(allowedDiffPixels(w, h));
    expect(diff.data.length).toBe(w * h * 4);
  });

  test('allowed pixels follow MAX_DIFF_FRACTION', () => {
    expect(allowedDiffPixels(320, 180)).toBe(Math.floor(320 * 180 * MAX_DIFF_FRACTION));
    expect(PIXEL_THRESHOLD).toBeGreaterThan(0);
  });

  test('size mismatch throws', () => {
    expect(() => compareImages(base, image(10, 10, gradient))).toThrow(/cannot compare/);
  });
});

describe('expectImagesMatch', () => {
  const base = image(100, 100, gradient);
  const name = `image-utils-${process.pid}`;
  const files = ['actual', 'expected', 'diff'].map((kind) => path.join(OUTPUT_DIR, `${name}-${kind}.png`));
  const removeFiles = () => files.forEach((file) => fs.rmSync(file, { force: true }));

  test('passes within the tolerance and writes nothing', () => {
    const shifted = image(100, 100, (x, y) => gradient(x, y).map((c) => c + 2));
    expect(expectImagesMatch(name, shifted, base).diffPixels).toBe(0);
    expect(files.filter((file) => fs.existsSync(file))).toEqual([]);
  });

  test('a failure writes actual, expected and diff PNGs and names them', () => {
    const patched = image(100, 100, (x, y) => (x < 20 && y < 20 ? [255, 0, 0] : gradient(x, y)));
    try {
      expect(() => expectImagesMatch(name, patched, base, { hint: 'what to do' })).toThrow(
        new RegExp(`400 pixels[\\s\\S]*${name}-actual\\.png[\\s\\S]*${name}-expected\\.png[\\s\\S]*${name}-diff\\.png\\nwhat to do$`),
      );
      expect(files.filter((file) => fs.existsSync(file))).toEqual(files);
      expect(readPng(files[0]).data.equals(patched.data)).toBe(true);
    } finally {
      removeFiles();
    }
  });

  test('images of different sizes fail with both written', () => {
    try {
      expect(() => expectImagesMatch(name, image(10, 10, gradient), base)).toThrow(/is 10x10 but the expected image is 100x100/);
      expect(files.filter((file) => fs.existsSync(file))).toEqual(files.slice(0, 2));
    } finally {
      removeFiles();
    }
  });
});

describe('PNG round trip', () => {
  test('writePng then readPng gives the same pixels', () => {
    const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'png-'));
    try {
      const img = image(17, 9, gradient);
      const file = path.join(dir, 'sub', 'x.png');
      writePng(file, img);
      const back = readPng(file);
      expect([back.width, back.height]).toEqual([17, 9]);
      expect(Buffer.compare(back.data, img.data)).toBe(0);
    } finally {
      fs.rmSync(dir, { recursive: true, force: true });
    }
  });
});

// The harness reports a raw page's compiler log as the page does (src/shadertoy/shader-errors.js).
describe('mapShaderLog', () => {
  const source = 'void mainImage(out vec4 c, in vec2 f) {\n    c = vec4(undefinedThing);\n}\n';
  const { code, firstSourceLine } = composeImageShader(source);
  test.each([
    [
      `ERROR: 0:${firstSourceLine + 1}: 'undefinedThing' : undeclared identifier`,
      /^shaders\/raytrace\.glsl:2: error: 'undefinedThing'.*\n\s+c = vec4\(undefinedThing\);$/,
    ],
    [`ERROR: 0:3: 'x' : bad`, /^error: 'x' : bad$/], // a line of Shadertoy's header: no line of the file
    [`ERROR: 0:${firstSourceLine + 10}: 'y' : bad`, /^error: 'y' : bad$/], // Shadertoy's main, after the file
    ['ERROR: 1 compilation errors.  No code generated.', /^$/], // the summary line is dropped
  ])('%s', (log, expected) => {
    expect(mapShaderLog(log, { code, firstSourceLine, source, fileName: 'shaders/raytrace.glsl' })).toMatch(expected);
  });
});

describe('findChrome', () => {
  const exists = (set) => (p) => set.includes(p);
  test.each([
    ['CHROME_PATH wins', { CHROME_PATH: '/x/chrome' }, ['/usr/bin/chromium'], ['/x/chrome', '/usr/bin/chromium'], '/x/chrome'],
    ['first existing candidate', {}, ['/a', '/b', '/c'], ['/b', '/c'], '/b'],
  ])('%s', (_, env, candidates, present, expected) => {
    expect(findChrome(env, candidates, exists(present))).toBe(expected);
  });

  test.each([
    ['none installed', {}, ['/a'], []],
    ['CHROME_PATH missing', { CHROME_PATH: '/nope' }, ['/a'], ['/a']],
  ])('%s fails with install instructions', (_, env, candidates, present) => {
    expect(() => findChrome(env, candidates, exists(present))).toThrow(/apt-get install -y chromium.*CHROME_PATH/);
  });
});
