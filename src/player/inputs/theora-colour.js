// A decoded Theora picture (three planes of Y'CbCr bytes) as RGBA.
//
// The Theora I specification (its chapter on colour spaces and pixel formats) defines one
// conversion for every colour space a file may declare (Rec. 470M, Rec. 470BG, unspecified): the
// luma and chroma of BT.601 (Kr = 0.299, Kb = 0.114) in video range, Y' from 16 (black) to 235
// (white) and Cb, Cr from 16 to 240 about 128, as ffmpeg converts RGB by default. Where
// the chroma planes are smaller (4:2:0, 4:2:2) their samples sit centred between the luma samples
// they cover (the specification's siting), and a pixel's chroma is the bilinear mix of the four
// nearest, as a GPU sampling a chroma plane linearly gives it. Only the picture region (the
// frame's crop) is converted, and chroma is never read from outside it (the decoder pads it grey).

/** A plane of ogv.js's frame buffer. @typedef {{bytes: Uint8Array, stride: number}} Plane */
/**
 * ogv.js's decoded frame (OGVDecoderVideoTheora's frameBuffer): the frame's size and its chroma
 * planes' (whole macroblocks), the picture inside it (crop) and its size on screen (display:
 * the crop with the file's pixel aspect ratio applied).
 * @typedef {{format: {width: number, height: number, chromaWidth: number, chromaHeight: number,
 *   cropLeft: number, cropTop: number, cropWidth: number, cropHeight: number,
 *   displayWidth: number, displayHeight: number}, y: Plane, u: Plane, v: Plane}} YuvFrame
 */

/** BT.601's weights of red and blue in luma. */
const KR = 0.299;
const KB = 0.114;
const KG = 1 - KR - KB;
/** R' = Y' + 2(1 − Kr)·Cr, B' = Y' + 2(1 − Kb)·Cb, and G' what luma's definition leaves. */
const R_CR = 2 * (1 - KR);
const B_CB = 2 * (1 - KB);
const G_CB = (2 * KB * (1 - KB)) / KG;
const G_CR = (2 * KR * (1 - KR)) / KG;
/** Video range: the byte steps of luma's and chroma's full swing. */
const LUMA_SCALE = 255 / 219;
const CHROMA_SCALE = 255 / 224;

/**
 * For each picture column (or row) `i` of a plane subsampled by `scale`, the two chroma samples
 * it mixes and the weight of the second, clamped to the picture's own chroma samples.
 * @param {number} start the picture's first luma column (row) in the frame
 * @param {number} count the picture's columns (rows)
 * @param {number} scale chroma samples per luma sample (1 or 0.5)
 */
function taps(start, count, scale) {
  const first = Math.floor(start * scale);
  const last = Math.max(first, Math.ceil((start + count) * scale) - 1);
  const lower = new Int32Array(count);
  const upper = new Int32Array(count);
  const weight = new Float64Array(count);
  for (let i = 0; i < count; i++) {
    // the luma sample's centre in chroma samples, whose centres are at integers
    const at = (start + i + 0.5) * scale - 0.5;
    const below = Math.floor(at);
    lower[i] = Math.min(last, Math.max(first, below));
    upper[i] = Math.min(last, Math.max(first, below + 1));
    weight[i] = at - below;
  }
  return { lower, upper, weight };
}

/**
 * A chroma plane's row mixed from rows `top` and `bottom` (weight `down` on the second), into `out`.
 * @param {Plane} plane @param {number} top @param {number} bottom @param {number} down
 * @param {Float64Array} out
 */
function mixRows({ bytes, stride }, top, bottom, down, out) {
  const upper = top * stride;
  const lower = bottom * stride;
  for (let i = 0; i < out.length; i++) out[i] = bytes[upper + i] + (bytes[lower + i] - bytes[upper + i]) * down;
}

/**
 * The picture of `frame` as RGBA bytes, rows top first, alpha 255.
 * @param {YuvFrame} frame
 * @returns {Uint8ClampedArray<ArrayBuffer>} cropWidth × cropHeight × 4 bytes
 */
export function theoraToRgba(frame) {
  const { width, height, chromaWidth, chromaHeight, cropLeft, cropTop, cropWidth, cropHeight } = frame.format;
  const { lower: left, upper: right, weight: across } = taps(cropLeft, cropWidth, chromaWidth / width);
  const rows = taps(cropTop, cropHeight, chromaHeight / height);
  const out = new Uint8ClampedArray(cropWidth * cropHeight * 4);
  const { y, u, v } = frame;
  const luma = y.bytes;
  // a row's chroma: its two chroma rows mixed, then across, as what each adds to R', G' and B'
  const uRow = new Float64Array(chromaWidth);
  const vRow = new Float64Array(chromaWidth);
  const red = new Float64Array(cropWidth);
  const green = new Float64Array(cropWidth);
  const blue = new Float64Array(cropWidth);
  let o = 0;
  for (let row = 0; row < cropHeight; row++) {
    mixRows(u, rows.lower[row], rows.upper[row], rows.weight[row], uRow);
    mixRows(v, rows.lower[row], rows.upper[row], rows.weight[row], vRow);
    for (let i = 0; i < cropWidth; i++) {
      const cb = (uRow[left[i]] + (uRow[right[i]] - uRow[left[i]]) * across[i] - 128) * CHROMA_SCALE;
      const cr = (vRow[left[i]] + (vRow[right[i]] - vRow[left[i]]) * across[i] - 128) * CHROMA_SCALE;
      red[i] = R_CR * cr;
      green[i] = -G_CB * cb - G_CR * cr;
      blue[i] = B_CB * cb;
    }
    const lumaRow = (cropTop + row) * y.stride + cropLeft;
    for (let i = 0; i < cropWidth; i++, o += 4) {
      const l = (luma[lumaRow + i] - 16) * LUMA_SCALE;
      out[o] = l + red[i];
      out[o + 1] = l + green[i];
      out[o + 2] = l + blue[i];
      out[o + 3] = 255;
    }
  }
  return out;
}
