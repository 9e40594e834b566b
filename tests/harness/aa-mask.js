// Reading the shader's "Show pixels with extra samples" view (SHOW_AA_PIXELS in
// shaders/raytrace.glsl): the pixels that took extra samples are pure magenta, every other pixel
// is grey. Used by the benchmark (what fraction took them) and by the same-ray reference (which
// pixels to sample as the shader did).

/**
 * One byte a pixel, rows top to bottom as the image's: 1 where the pixel took extra samples.
 * @param {{width: number, height: number, data: Uint8Array}} image RGBA8, rows top to bottom
 */
export function extraSampleMask({ width, height, data }) {
  const mask = new Uint8Array(width * height);
  for (let i = 0; i < mask.length; i++) mask[i] = data[i * 4] === 255 && data[i * 4 + 1] === 0 && data[i * 4 + 2] === 255 ? 1 : 0;
  return mask;
}

/** How many pixels of the view took extra samples. */
export function countExtraSamplePixels(image) {
  return extraSampleMask(image).reduce((n, v) => n + v, 0);
}
