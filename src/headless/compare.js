// The one image comparison of the project (pixelmatch): the command line's `test` and the
// suite's goldens (tests/support/images.js gives it the suite's tolerance) both count differing
// pixels with it. An image is { width, height, data } with RGBA8 rows top to bottom.

import pixelmatch from 'pixelmatch';

/**
 * How many pixels differ beyond `threshold` (pixelmatch's YIQ distance, 0..1), and an image
 * that marks them.
 * @param {{width: number, height: number, data: Uint8Array}} actual
 * @param {{width: number, height: number, data: Uint8Array}} expected the same size
 * @param {{threshold: number, includeAA: boolean}} tolerance includeAA: anti-aliased pixels count too
 * @returns {{diffPixels: number, fraction: number, diff: {width: number, height: number, data: Buffer}}}
 */
export function compareImages(actual, expected, { threshold, includeAA }) {
  if (actual.width !== expected.width || actual.height !== expected.height)
    throw new Error(`cannot compare ${actual.width}x${actual.height} with ${expected.width}x${expected.height}`);
  const { width, height } = actual;
  const diff = Buffer.alloc(width * height * 4);
  const diffPixels = pixelmatch(actual.data, expected.data, diff, width, height, { threshold, includeAA });
  return { diffPixels, fraction: diffPixels / (width * height), diff: { width, height, data: diff } };
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
      failure: `the render is ${actual.width}x${actual.height}, the reference ${reference.width}x${reference.height}`,
    };
  const { diffPixels, diff } = compareImages(actual, reference, { threshold, includeAA: true });
  const ok = diffPixels <= maxDiffPixels;
  return { ok, diffPixels, diff, failure: ok ? null : `${diffPixels} pixels differ from the reference (at most ${maxDiffPixels} may)` };
}
