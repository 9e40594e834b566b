// The discrete Fourier transform, once: an in-place iterative radix-2 FFT, for the page's
// spectrum texture (src/player/inputs/spectrum.js: iChannel's FFT row) and for `shaderproof
// test`'s sound outline (src/runner/sound-compare.js). The formula is the textbook one
// (Cooley–Tukey, bit-reversed order first, then butterflies of growing size).

/**
 * Transforms re + i·im in place: X[k] = Σ x[n]·e^{-2πikn/N}. The length must be a power of two.
 * @param {Float64Array} re
 * @param {Float64Array} im
 */
export function fft(re, im) {
  const n = re.length;
  if (n & (n - 1) || im.length !== n) throw new Error(`fft: the length ${n} is not a power of two, or re and im differ`);
  for (let i = 1, j = 0; i < n; i++) {
    let bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) {
      [re[i], re[j]] = [re[j], re[i]];
      [im[i], im[j]] = [im[j], im[i]];
    }
  }
  for (let size = 2; size <= n; size *= 2) {
    const step = (-2 * Math.PI) / size;
    for (let s = 0; s < n; s += size) {
      for (let k = 0; k < size / 2; k++) {
        const c = Math.cos(step * k);
        const d = Math.sin(step * k);
        const a = s + k;
        const b = a + size / 2;
        const tr = re[b] * c - im[b] * d;
        const ti = re[b] * d + im[b] * c;
        re[b] = re[a] - tr;
        im[b] = im[a] - ti;
        re[a] += tr;
        im[a] += ti;
      }
    }
  }
}
