// The one FFT (src/shared/fft.js), which the page's spectrum texture (src/player/inputs/spectrum.js)
// and `test`'s sound outline (src/runner/sound-compare.js) share: checked against the DFT's
// definition on signals whose transform is known, and defined once under src/.

import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, test } from 'vitest';
import { fft } from '../../src/shared/fft.js';

/** Float64 round-off on a 64-point transform of values of at most 1: far below any real error. */
const TOLERANCE = 1e-9;
const N = 64;

/** The DFT by its definition, X[k] = Σ x[n]·e^{-2πikn/N}: magnitudes. @param {number[]} x */
const dftMagnitudes = (x) =>
  x.map((_, k) => {
    let re = 0;
    let im = 0;
    x.forEach((v, n) => {
      re += v * Math.cos((-2 * Math.PI * k * n) / x.length);
      im += v * Math.sin((-2 * Math.PI * k * n) / x.length);
    });
    return Math.hypot(re, im);
  });

describe('fft', () => {
  test.each([
    ['an impulse: flat', (n) => (n === 0 ? 1 : 0)],
    ['a cosine at bin 5', (n) => Math.cos((2 * Math.PI * 5 * n) / N)],
    ['a sine at bin 13 plus a constant', (n) => 0.25 + 0.5 * Math.sin((2 * Math.PI * 13 * n) / N)],
    ['noise', (n) => Math.sin(n * n * 0.7) * 0.9],
  ])('%s: as the DFT by its definition', (_, signal) => {
    const x = Array.from({ length: N }, (_, n) => signal(n));
    const re = Float64Array.from(x);
    const im = new Float64Array(N);
    fft(re, im);
    const expected = dftMagnitudes(x);
    for (let k = 0; k < N; k++) expect(Math.abs(Math.hypot(re[k], im[k]) - expected[k]), `bin ${k}`).toBeLessThan(TOLERANCE);
  });

  test('a length that is not a power of two is refused', () => {
    expect(() => fft(new Float64Array(48), new Float64Array(48))).toThrow(/not a power of two/);
  });

  test('is written once under src/', () => {
    const root = path.resolve(import.meta.dirname, '..', '..', 'src');
    const defining = fs
      .readdirSync(root, { recursive: true, encoding: 'utf8' })
      .filter((file) => file.endsWith('.js') && /function fft\s*\(/.test(fs.readFileSync(path.join(root, file), 'utf8')));
    expect(defining).toEqual([path.join('shared', 'fft.js')]);
  });
});
