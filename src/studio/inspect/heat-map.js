// The comparison's heat map (compare-view.js draws it): each pixel's error against float64, in
// units of 1/255 (one step of the 8-bit output), on a logarithmic scale from LOW to HIGH steps,
// coloured along matplotlib's "inferno" (dark for small errors, yellow to white over 2/255, so
// the pixels that matter stand out); below LOW the picture itself shows, dim and grey, so a
// person sees where in the scene the error is.

/** Errors below this many 1/255 steps show the picture instead (float32's own error at the
 * default view is about 0.002 steps: RMSE 1e-5). */
export const LOW = 0.001;
/** Errors of this many steps and more take the top colour. */
export const HIGH = 4;
/** The legend's ticks, in 1/255 steps. */
export const TICKS = [0.001, 0.01, 0.1, 1, 2, 4];

/** inferno at 0, 1/4, 1/2, 3/4, 1 (matplotlib's table, rounded). */
const STOPS = [
  [0, 0, 4],
  [87, 16, 110],
  [188, 55, 84],
  [249, 142, 9],
  [252, 255, 164],
];

/** Where an error of `steps` 1/255 steps lies on the scale, 0 .. 1. @param {number} steps */
export function scalePosition(steps) {
  return Math.min(1, Math.max(0, Math.log(steps / LOW) / Math.log(HIGH / LOW)));
}

/** The colour at `t` in 0 .. 1. @param {number} t @returns {number[]} */
function colorAt(t) {
  const x = Math.min(1, Math.max(0, t)) * (STOPS.length - 1);
  const i = Math.min(STOPS.length - 2, Math.floor(x));
  const f = x - i;
  return STOPS[i].map((v, c) => Math.round(v + f * (STOPS[i + 1][c] - v)));
}

/**
 * The heat map's RGBA pixels, rows top to bottom.
 * @param {Float32Array} error each pixel's error (display units, 0 .. 1)
 * @param {Uint8Array} picture the frame's RGBA8 pixels, for the pixels below LOW
 * @returns {Uint8ClampedArray<ArrayBuffer>}
 */
export function heatMapPixels(error, picture) {
  const out = new Uint8ClampedArray(error.length * 4);
  for (let p = 0; p < error.length; p++) {
    const steps = error[p] * 255;
    let rgb;
    if (Number.isNaN(steps))
      rgb = colorAt(1); // a NaN or an infinity: as wrong as can be
    else if (steps < LOW) {
      const grey = 0.3 * (0.299 * picture[4 * p] + 0.587 * picture[4 * p + 1] + 0.114 * picture[4 * p + 2]);
      rgb = [grey, grey, grey];
    } else rgb = colorAt(scalePosition(steps));
    out.set(rgb, 4 * p);
    out[4 * p + 3] = 255;
  }
  return out;
}

/** A CSS gradient of the scale, left to right. */
export function scaleGradient() {
  return `linear-gradient(to right, ${STOPS.map((c, i) => `rgb(${c.join(', ')}) ${(100 * i) / (STOPS.length - 1)}%`).join(', ')})`;
}
