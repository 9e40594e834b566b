// Smaller copies of a render: the half-size check's (halve: each pixel the mean of a 2×2 block)
// and the HTML report's thumbnail of a case that passed (thumbnail: a box filter to fit a size).

/** @typedef {{width: number, height: number, data: Uint8Array | Buffer}} Rgba */

/**
 * The image at half the size, each pixel the mean of a 2×2 block (sizes rounded down).
 * @param {Rgba} image
 * @returns {Rgba}
 */
export function halve({ width, height, data }) {
  const w = Math.floor(width / 2);
  const h = Math.floor(height / 2);
  const out = Buffer.alloc(w * h * 4);
  for (let y = 0; y < h; y++)
    for (let x = 0; x < w; x++)
      for (let c = 0; c < 4; c++) {
        const at = (dx, dy) => data[((2 * y + dy) * width + 2 * x + dx) * 4 + c];
        out[(y * w + x) * 4 + c] = Math.round((at(0, 0) + at(1, 0) + at(0, 1) + at(1, 1)) / 4);
      }
  return { width: w, height: h, data: out };
}

/** A thumbnail's box: a row of the report shows it beside the case's name. */
export const THUMBNAIL = Object.freeze({ width: 160, height: 90 });

/**
 * The image shrunk to fit THUMBNAIL (never enlarged), each pixel the mean of the source pixels
 * its box covers.
 * @param {Rgba} image
 * @returns {Rgba}
 */
export function thumbnail({ width, height, data }) {
  const scale = Math.min(1, THUMBNAIL.width / width, THUMBNAIL.height / height);
  const w = Math.max(1, Math.round(width * scale));
  const h = Math.max(1, Math.round(height * scale));
  const out = Buffer.alloc(w * h * 4);
  for (let y = 0; y < h; y++) {
    const [y0, y1] = [Math.floor((y * height) / h), Math.max(Math.floor((y * height) / h) + 1, Math.floor(((y + 1) * height) / h))];
    for (let x = 0; x < w; x++) {
      const [x0, x1] = [Math.floor((x * width) / w), Math.max(Math.floor((x * width) / w) + 1, Math.floor(((x + 1) * width) / w))];
      const sum = [0, 0, 0, 0];
      for (let sy = y0; sy < y1; sy++)
        for (let sx = x0; sx < x1; sx++) for (let c = 0; c < 4; c++) sum[c] += data[(sy * width + sx) * 4 + c];
      const n = (y1 - y0) * (x1 - x0);
      for (let c = 0; c < 4; c++) out[(y * w + x) * 4 + c] = Math.round(sum[c] / n);
    }
  }
  return { width: w, height: h, data: out };
}
