// Images, in plain Node: PNG files, the blank-image check, comparison with the suite's tolerance
// (tests/support/tables/views.js), and the one way a test says that two images must match: expectImagesMatch,
// which on a failure writes actual, expected and diff PNGs to tests/output/ and names them.
// An image is { width, height, data } with RGBA8 rows top to bottom.

import fs from 'node:fs';
import path from 'node:path';
import { readPng, writePng } from '../../src/headless/png.js';
import { compareImages as compareWith } from '../../src/headless/compare.js';
import { OUTPUT_DIR, rel } from './config.js';
import { INCLUDE_AA, MAX_DIFF_FRACTION, PIXEL_THRESHOLD } from './tables/views.js';

export { readPng, writePng };

/** An opaque image whose pixel (x, y) has the colour `colourAt(x, y)` ([r, g, b]). */
export function makeImage(width, height, colourAt) {
  const data = Buffer.alloc(width * height * 4);
  for (let i = 0; i < width * height; i++) data.set([...colourAt(i % width, Math.floor(i / width)), 255], i * 4);
  return { width, height, data };
}

/** Same size and the same bytes. */
export function sameImage(a, b) {
  return a.width === b.width && a.height === b.height && Buffer.compare(Buffer.from(a.data), Buffer.from(b.data)) === 0;
}

/**
 * The pixels (from row `fromRow` down) of which some channel differs by more than `levels`
 * between two images of the same size: { count, fraction } of those rows' pixels.
 */
export function differingPixels(a, b, levels, { fromRow = 0 } = {}) {
  let count = 0;
  let total = 0;
  for (let y = fromRow; y < a.height; y++) {
    for (let x = 0; x < a.width; x++) {
      const i = (y * a.width + x) * 4;
      total++;
      if ([0, 1, 2, 3].some((c) => Math.abs(a.data[i + c] - b.data[i + c]) > levels)) count++;
    }
  }
  return { count, fraction: count / total };
}

/**
 * Why an image is not a render, or null if it could be one: the tests reject uniform images
 * (nothing drawn), all-white ones (Shadertoy's colour when mainImage writes nothing) and
 * all-black ones (a dead context or an unlit scene).
 */
export function blankReason({ width, height, data }, { minColours = 16 } = {}) {
  const n = width * height;
  if (n === 0) return 'the image is empty (0 pixels)';
  const colours = new Set();
  let white = 0;
  let black = 0;
  let transparent = 0;
  for (let i = 0; i < n; i++) {
    const r = data[i * 4];
    const g = data[i * 4 + 1];
    const b = data[i * 4 + 2];
    if (data[i * 4 + 3] !== 255) transparent++;
    if (r >= 250 && g >= 250 && b >= 250) white++;
    if (r <= 5 && g <= 5 && b <= 5) black++;
    if (colours.size < 64) colours.add((r << 16) | (g << 8) | b);
  }
  if (colours.size === 1) return `the image is a single colour (rgb ${[...colours][0].toString(16).padStart(6, '0')})`;
  if (white / n > 0.98) return `the image is white (${((100 * white) / n).toFixed(1)}% of pixels)`;
  if (black / n > 0.98) return `the image is black (${((100 * black) / n).toFixed(1)}% of pixels)`;
  if (colours.size < minColours) return `the image has only ${colours.size} colours`;
  if (transparent) return `${transparent} pixels are not opaque (Shadertoy forces alpha to 1)`;
  return null;
}

/**
 * @param {any} image RGBA8 with width and height
 * @param {string} what
 * @param {{minColours?: number}} [options] a view of flat colours by design has fewer
 */
export function assertNotBlank(image, what, options) {
  const reason = blankReason(image, options);
  if (reason) throw new Error(`${what}: not a rendered scene: ${reason}`);
}

/** The engine's comparison (src/headless/compare.js) with the suite's tolerance: { diffPixels, fraction, diff }. */
export function compareImages(actual, expected, { threshold = PIXEL_THRESHOLD, includeAA = INCLUDE_AA } = {}) {
  return compareWith(actual, expected, { threshold, includeAA });
}

export function allowedDiffPixels(width, height, maxDiffFraction = MAX_DIFF_FRACTION) {
  return Math.floor(width * height * maxDiffFraction);
}

/** tests/output/<name>-actual.png, -expected.png and -diff.png, removed if an earlier run left them. */
function clearOutput(name) {
  const out = {
    actual: path.join(OUTPUT_DIR, `${name}-actual.png`),
    expected: path.join(OUTPUT_DIR, `${name}-expected.png`),
    diff: path.join(OUTPUT_DIR, `${name}-diff.png`),
  };
  for (const file of Object.values(out)) fs.rmSync(file, { force: true });
  return out;
}

/**
 * Fails unless `actual` matches `expected` within the tolerance: the same size, and at most
 * floor(maxDiffFraction x pixels) pixels further apart than `threshold` (pixelmatch). On a
 * failure it writes tests/output/<name>-actual.png, -expected.png and -diff.png (the diff when
 * the sizes agree) and throws an error that names them; stale ones of an earlier run are removed
 * first. `actualLabel` and `expectedLabel` say what the two images are, `hint` what to do next.
 * @returns {{diffPixels: number, fraction: number, allowed: number}}
 */
export function expectImagesMatch(
  name,
  actual,
  expected,
  {
    threshold = PIXEL_THRESHOLD,
    maxDiffFraction = MAX_DIFF_FRACTION,
    includeAA = INCLUDE_AA,
    actualLabel = 'actual',
    expectedLabel = 'the expected image',
    hint = '',
  } = {},
) {
  const out = clearOutput(name);
  const files = () =>
    `\n  actual:   ${rel(out.actual)}\n  expected: ${rel(out.expected)}` +
    (fs.existsSync(out.diff) ? `\n  diff:     ${rel(out.diff)}` : '');
  const more = hint ? `\n${hint}` : '';
  if (actual.width !== expected.width || actual.height !== expected.height) {
    writePng(out.actual, actual);
    writePng(out.expected, expected);
    throw new Error(
      `${name}: ${actualLabel} is ${actual.width}x${actual.height} but ${expectedLabel} is ${expected.width}x${expected.height}.${files()}${more}`,
    );
  }
  const { diffPixels, fraction, diff } = compareImages(actual, expected, { threshold, includeAA });
  const allowed = allowedDiffPixels(actual.width, actual.height, maxDiffFraction);
  if (diffPixels > allowed) {
    writePng(out.actual, actual);
    writePng(out.expected, expected);
    writePng(out.diff, diff);
    throw new Error(
      `${name}: ${diffPixels} pixels (${(100 * fraction).toFixed(2)}%) of ${actualLabel} differ from ${expectedLabel} by more than ` +
        `threshold ${threshold}; at most ${allowed} (${(100 * maxDiffFraction).toFixed(2)}%) may.${files()}${more}`,
    );
  }
  return { diffPixels, fraction, allowed };
}
