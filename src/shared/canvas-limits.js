// The largest drawing the page makes at once, a fact that the page (src/player/app/canvas-size.js:
// ?size= is clamped to it, with a note: src/shared/url-params.js) and the command line (--size
// past it is refused, and --tile offered) both state; and the resolution scale's range.

/** The largest side the page asks for, in device pixels: WebGL2 implementations allow 16384 at most in practice. */
export const MAX_SIZE = 16384;
/** Beyond 8K UHD a drawing buffer is not a view but a way to exhaust memory. */
export const MAX_PIXELS = 7680 * 4320;

/** The resolution scale's range (of the device pixels; the panel's slider, ?scale=). */
export const MIN_SCALE = 0.25;
export const MAX_SCALE = 1;

/** Scales a size down (keeping its aspect) so that it fits MAX_SIZE and MAX_PIXELS. */
export function clampSize({ width, height }, maxSide = MAX_SIZE, maxPixels = MAX_PIXELS) {
  let k = Math.min(1, maxSide / width, maxSide / height, Math.sqrt(maxPixels / (width * height)));
  if (k >= 1) return { width, height };
  const out = { width: Math.max(1, Math.floor(width * k)), height: Math.max(1, Math.floor(height * k)) };
  // floor may still leave the product a hair over
  while (out.width * out.height > maxPixels) {
    k *= 0.999;
    out.width = Math.max(1, Math.floor(width * k));
    out.height = Math.max(1, Math.floor(height * k));
  }
  return out;
}
