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
