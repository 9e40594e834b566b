// Image error against a reference: the one module the tests and the benchmark use.
//
// Report the tail, not only the mean: one flipped pixel (an error of ~0.8) matters more than a
// million errors of 1e-6, so besides RMSE and PSNR this gives the maximum and the fraction of
// pixels whose worst channel is off by more than 1/255 and 2/255 (one and two 8-bit steps).

/**
 * Reads an image into display values in [0, 1], 3 channels per pixel.
 * Accepts { rgb: Float32Array|Float64Array } (3 per pixel, already in [0, 1] scale) or
 * { data: Uint8Array|Uint8ClampedArray } (RGBA8, as readPixels and PNG decoders give it).
 */
function toRgb(image) {
  if (image.rgb) return image.rgb;
  const { data } = image;
  if (!data) throw new Error('error: image needs an rgb (float) or data (RGBA8) array');
  const n = data.length / 4;
  const rgb = new Float64Array(n * 3);
  for (let i = 0; i < n; i++) {
    rgb[i * 3] = data[i * 4] / 255;
    rgb[i * 3 + 1] = data[i * 4 + 1] / 255;
    rgb[i * 3 + 2] = data[i * 4 + 2] / 255;
  }
  return rgb;
}

/**
 * Compares a test image with a reference of the same size.
 * @returns {{pixels, rmse, psnr, maxAbs, over1, over2, nonFinite}} over1/over2 are fractions of
 *   pixels; nonFinite counts NaN or infinite values in the test image (they count as error 1)
 */
export function imageError(test, reference) {
  if (test.width !== reference.width || test.height !== reference.height) {
    throw new Error(`error: sizes differ (${test.width}x${test.height} vs ${reference.width}x${reference.height})`);
  }
  const a = toRgb(test);
  const b = toRgb(reference);
  const pixels = test.width * test.height;
  if (a.length !== pixels * 3 || b.length !== pixels * 3) throw new Error('error: image data does not match its size');
  let sumSquares = 0;
  let maxAbs = 0;
  let over1 = 0;
  let over2 = 0;
  let nonFinite = 0;
  for (let p = 0; p < pixels; p++) {
    let worst = 0;
    for (let c = 0; c < 3; c++) {
      const value = a[p * 3 + c];
      let diff;
      if (Number.isFinite(value)) diff = Math.abs(value - b[p * 3 + c]);
      else {
        nonFinite++;
        diff = 1;
      }
      sumSquares += diff * diff;
      if (diff > worst) worst = diff;
    }
    if (worst > maxAbs) maxAbs = worst;
    // 1/255 plus a hair, so that an exact one-step rounding difference is not counted as over.
    if (worst > 1 / 255 + 1e-9) over1++;
    if (worst > 2 / 255 + 1e-9) over2++;
  }
  const rmse = Math.sqrt(sumSquares / (pixels * 3));
  return {
    pixels,
    rmse,
    psnr: rmse === 0 ? Infinity : -20 * Math.log10(rmse),
    maxAbs,
    over1: over1 / pixels,
    over2: over2 / pixels,
    nonFinite,
  };
}

/** One line for a log or a table cell. */
export function formatImageError(e) {
  const pct = (f) => `${(100 * f).toFixed(3)}%`;
  return `RMSE ${e.rmse.toExponential(2)}, PSNR ${e.psnr.toFixed(1)} dB, max ${e.maxAbs.toFixed(4)}, >1/255 ${pct(e.over1)}, >2/255 ${pct(e.over2)}, NaN/Inf ${e.nonFinite}`;
}
