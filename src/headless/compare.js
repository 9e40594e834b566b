// The one image comparison of the project (pixelmatch): the command line's `test` and the
// suite's goldens (tests/support/images.js gives it the suite's tolerance) both count differing
// pixels with it. An image is { width, height, data } with RGBA8 rows top to bottom.

import pixelmatch from 'pixelmatch';
import { differLine } from '../shared/differences.js';

/** The colour pixelmatch paints a counted pixel in the diff image; every other pixel is grey or yellow. */
const DIFF_COLOUR = /** @type {[number, number, number]} */ ([255, 0, 0]);
/** How many differing pixels are carried with their values (the first, row by row). */
const FIRST = 5;

/**
 * Where the counted pixels are: their bounding box (edges included) and the first few, row by
 * row, with each image's RGBA there.
 * @typedef {{box: {left: number, top: number, right: number, bottom: number},
 *   first: {x: number, y: number, reference: number[], actual: number[]}[]}} Where
 */

/**
 * How many pixels differ beyond `threshold` (pixelmatch's YIQ distance, 0..1), an image that
 * marks them, and where they are (null when none differs).
 * @param {{width: number, height: number, data: Uint8Array}} actual
 * @param {{width: number, height: number, data: Uint8Array}} expected the same size
 * @param {{threshold: number, includeAA: boolean}} tolerance includeAA: anti-aliased pixels count too
 * @returns {{diffPixels: number, fraction: number, diff: {width: number, height: number, data: Buffer}, where: Where | null}}
 */
export function compareImages(actual, expected, { threshold, includeAA }) {
  if (actual.width !== expected.width || actual.height !== expected.height)
    throw new Error(`cannot compare ${actual.width}x${actual.height} with ${expected.width}x${expected.height}`);
  const { width, height } = actual;
  const diff = Buffer.alloc(width * height * 4);
  const diffPixels = pixelmatch(actual.data, expected.data, diff, width, height, { threshold, includeAA, diffColor: DIFF_COLOUR });
  const where = diffPixels ? locate(diff, actual, expected) : null;
  return { diffPixels, fraction: diffPixels / (width * height), diff: { width, height, data: diff }, where };
}

/**
 * The counted pixels of a diff image (those in DIFF_COLOUR: the grey of an equal pixel has
 * r = g = b, the yellow of an anti-aliased one g = 255).
 * @param {Buffer} diff
 * @param {{width: number, height: number, data: Uint8Array}} actual
 * @param {{data: Uint8Array}} expected
 * @returns {Where}
 */
function locate(diff, actual, expected) {
  const { width } = actual;
  const box = { left: Infinity, top: Infinity, right: -1, bottom: -1 };
  /** @type {Where['first']} */
  const first = [];
  const [r, g, b] = DIFF_COLOUR;
  for (let i = 0; i < diff.length; i += 4) {
    if (diff[i] !== r || diff[i + 1] !== g || diff[i + 2] !== b) continue;
    const x = (i / 4) % width;
    const y = Math.floor(i / 4 / width);
    box.left = Math.min(box.left, x);
    box.right = Math.max(box.right, x);
    box.top = Math.min(box.top, y);
    box.bottom = Math.max(box.bottom, y);
    if (first.length < FIRST)
      first.push({ x, y, reference: [...expected.data.subarray(i, i + 4)], actual: [...actual.data.subarray(i, i + 4)] });
  }
  return { box, first };
}

/**
 * The runner's verdict on a render against its reference (src/runner/case.js, and the Node API's
 * compare): pixelmatch at `threshold`, anti-aliased pixels counted, and at most `maxDiffPixels`
 * pixels may differ. `failure` says why it fails, in the report's words; `diffPixels` and `diff`
 * are null when the sizes differ.
 * @param {{width: number, height: number, data: Uint8Array}} actual
 * @param {{width: number, height: number, data: Uint8Array}} reference
 * @param {{threshold: number, maxDiffPixels: number}} tolerance
 */
export function judgeImage(actual, reference, { threshold, maxDiffPixels }) {
  if (reference.width !== actual.width || reference.height !== actual.height)
    return {
      ok: false,
      diffPixels: null,
      diff: null,
      where: null,
      failure: `the render is ${actual.width}x${actual.height}, the reference ${reference.width}x${reference.height}`,
    };
  const { diffPixels, diff, where } = compareImages(actual, reference, { threshold, includeAA: true });
  const ok = diffPixels <= maxDiffPixels;
  return { ok, diffPixels, diff, where, failure: ok ? null : differLine(diffPixels, maxDiffPixels, where) };
}
