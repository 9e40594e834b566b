// `test`'s comparison of a case's sound with its reference WAV (manifest.js "sound"): the RMS of
// the sample-by-sample difference, and the difference of their spectra, each against a
// tolerance. The spectrum is Welch's: the mean magnitude of Hann-windowed frames of SPECTRUM_SIZE
// samples, half overlapping, per channel; its difference is the summed absolute difference of
// the two spectra over the reference's sum (0: the same spectrum, 1: as far off as the whole of it).
// A spectrum check passes sound that is the same music a few samples late; the RMS one does not.

/** Samples a spectrum frame (a power of two: about 93 ms at 44,100 Hz). */
import { fft } from '../shared/fft.js';

const SPECTRUM_SIZE = 4096;

/** The default tolerances: a few 16-bit steps of RMS, 1% of the spectrum. */
export const DEFAULT_SOUND_TOLERANCE = Object.freeze({ rms: 1e-4, spectrum: 0.01 });

/**
 * The RMS of the difference of two interleaved 16-bit sounds, in full scale (1 = 32768); a
 * shorter one is taken as silence past its end.
 * @param {Int16Array} a
 * @param {Int16Array} b
 */
export function rmsDifference(a, b) {
  const n = Math.max(a.length, b.length);
  if (!n) return 0;
  let sum = 0;
  for (let i = 0; i < n; i++) {
    const d = ((a[i] ?? 0) - (b[i] ?? 0)) / 32768;
    sum += d * d;
  }
  return Math.sqrt(sum / n);
}

/**
 * How far the spectrum of `actual` is from the reference's (the larger of the two channels').
 * @param {Int16Array} actual interleaved stereo
 * @param {Int16Array} reference interleaved stereo
 */
export function spectrumDifference(actual, reference) {
  let worst = 0;
  for (const c of [0, 1]) {
    const a = spectrum(actual, c);
    const b = spectrum(reference, c);
    let diff = 0;
    let total = 0;
    for (let k = 0; k < b.length; k++) {
      diff += Math.abs(a[k] - b[k]);
      total += b[k];
    }
    worst = Math.max(worst, total > 0 ? diff / total : diff > 0 ? 1 : 0);
  }
  return worst;
}

/** The bands of an outline: from 20 Hz up, each a step of the same ratio (a log axis). */
const OUTLINE_BANDS = 48;

/**
 * The spectrum in OUTLINE_BANDS log-spaced bands from 20 Hz to half the sample rate, each the
 * band's mean magnitude in dB (0 dB: a full-scale sine), the two channels averaged: what the HTML
 * report draws of a case's sound beside its reference's.
 * @param {Int16Array} pcm interleaved stereo
 * @param {number} [sampleRate]
 * @returns {number[]}
 */
export function spectrumOutline(pcm, sampleRate = 44_100) {
  const [left, right] = [spectrum(pcm, 0), spectrum(pcm, 1)];
  const binHz = sampleRate / SPECTRUM_SIZE;
  const [low, high] = [20, sampleRate / 2];
  // a full-scale sine under the Hann window peaks at SPECTRUM_SIZE / 4
  const fullScale = SPECTRUM_SIZE / 4;
  const bands = [];
  for (let b = 0; b < OUTLINE_BANDS; b++) {
    const from = Math.floor((low * (high / low) ** (b / OUTLINE_BANDS)) / binHz);
    const to = Math.max(from + 1, Math.floor((low * (high / low) ** ((b + 1) / OUTLINE_BANDS)) / binHz));
    let sum = 0;
    for (let k = from; k < to && k < left.length; k++) sum += (left[k] + right[k]) / 2;
    const mean = sum / (to - from);
    bands.push(Math.max(-120, 20 * Math.log10(mean / fullScale + 1e-12)));
  }
  return bands;
}

/** Channel c's Welch spectrum: SPECTRUM_SIZE / 2 magnitudes. */
function spectrum(pcm, c) {
  const length = pcm.length / 2;
  const out = new Float64Array(SPECTRUM_SIZE / 2);
  const re = new Float64Array(SPECTRUM_SIZE);
  const im = new Float64Array(SPECTRUM_SIZE);
  let frames = 0;
  for (let start = 0; start === 0 || start + SPECTRUM_SIZE <= length; start += SPECTRUM_SIZE / 2) {
    for (let i = 0; i < SPECTRUM_SIZE; i++) {
      const hann = 0.5 - 0.5 * Math.cos((2 * Math.PI * i) / SPECTRUM_SIZE);
      re[i] = start + i < length ? (pcm[2 * (start + i) + c] / 32768) * hann : 0;
      im[i] = 0;
    }
    fft(re, im);
    for (let k = 0; k < out.length; k++) out[k] += Math.hypot(re[k], im[k]);
    frames++;
  }
  for (let k = 0; k < out.length; k++) out[k] /= frames;
  return out;
}
