// Shadertoy's music and microphone texture, computed as a pure function of time: 512 × 2 bytes,
// row 0 the spectrum (AnalyserNode.getByteFrequencyData), row 1 the waveform
// (getByteTimeDomainData). The site's player (https://www.shadertoy.com/js/effect.js,
// EffectPass.NewTexture for "music"/"mic" and Paint_Image) creates its AnalyserNode with every
// default (fftSize 2048, so 1024 bins; smoothingTimeConstant 0.8; minDecibels -100, maxDecibels
// -30), reads both arrays once per frame into arrays of frequencyBinCount (music) or 512 (mic)
// bytes, and uploads their first 512 into a 512 × 2 single-channel byte texture (TEXFMT.C1I8: R8
// in WebGL2), linear and clamped: frequency on row 0 (y = 0), waveform on row 1.
//
// Here the same numbers come from the Web Audio spec's analyser algorithm
// (https://webaudio.github.io/web-audio-api/#AnalyserNode): the last fftSize samples before the
// frame, mixed to mono, times a Blackman window (alpha 0.16), a DFT scaled by 1/N, smoothed over
// frames (X̂ = τ·X̂prev + (1 − τ)·|X|), in dB, mapped from [minDecibels, maxDecibels] to 0..255
// (floor, clamped); the waveform byte is floor(128 · (1 + x)), clamped. An AnalyserNode on an
// OfflineAudioContext would not do: which render quantum it has reached when a frame asks is not
// fixed. The smoothing is the one thing that depends on earlier frames; it is taken as if the
// frames before had come at this frame's iTimeDelta (the sum of (1 − τ)·τ^j·|X(t − j·dt)| over
// the frames until τ^j < 1e-4), so a frame is the same whether or not the frames before it were
// drawn: `render --time 3` equals frame 3·fps of a recording. getByteTimeDomainData into an array
// shorter than fftSize keeps its first elements: row 1 is the oldest 512 samples of the window.

import { fft } from '../../shared/fft.js';

const FFT_SIZE = 2048;
const TEXTURE_WIDTH = 512;
const SMOOTHING = 0.8;
const MIN_DB = -100;
const MAX_DB = -30;
/** How many frames back the smoothing reaches: 0.8^42 < 1e-4. */
const SMOOTHING_FRAMES = Math.ceil(Math.log(1e-4) / Math.log(SMOOTHING));

/** The Blackman window of the spec, once. */
const WINDOW = Float64Array.from({ length: FFT_SIZE }, (_, n) => {
  const a = 0.16;
  const x = (2 * Math.PI * n) / FFT_SIZE;
  return (1 - a) / 2 - 0.5 * Math.cos(x) + (a / 2) * Math.cos(2 * x);
});

/**
 * |X[k]| for k < TEXTURE_WIDTH of the windowed block ending before sample `end` (samples before 0
 * are silence), by a radix-2 FFT.
 * @param {(i: number) => number} sampleAt the mono signal at sample i (i ≥ 0)
 * @param {number} end
 */
function magnitudes(sampleAt, end) {
  const re = new Float64Array(FFT_SIZE);
  const im = new Float64Array(FFT_SIZE);
  const start = end - FFT_SIZE;
  for (let n = 0; n < FFT_SIZE; n++) {
    const i = start + n;
    re[n] = i < 0 ? 0 : sampleAt(i) * WINDOW[n];
  }
  fft(re, im);
  const out = new Float64Array(TEXTURE_WIDTH);
  for (let k = 0; k < TEXTURE_WIDTH; k++) out[k] = Math.hypot(re[k], im[k]) / FFT_SIZE;
  return out;
}

/**
 * The 512 × 2 bytes of the texture for the frame at sample `end` (the frame's iTime times the
 * rate), frames `step` samples apart (iTimeDelta times the rate).
 * @param {(i: number) => number} sampleAt the mono signal at sample i ≥ 0
 * @param {number} end
 * @param {number} step
 * @param {Map<number, Float64Array>} [blocks] the blocks' magnitudes by end sample, kept between
 *   calls on one signal: frames a whole step apart (a recording) compute one new block each
 * @returns {Uint8Array} row 0 the spectrum, row 1 the waveform
 */
export function spectrumTexture(sampleAt, end, step, blocks = new Map()) {
  const smoothed = new Float64Array(TEXTURE_WIDTH);
  let weight = 1 - SMOOTHING;
  for (let j = 0; j < SMOOTHING_FRAMES; j++, weight *= SMOOTHING) {
    const at = Math.round(end - j * step);
    if (at <= 0) break; // before the first sample: silence, |X| = 0
    let block = blocks.get(at);
    if (!block) {
      block = magnitudes(sampleAt, at);
      blocks.set(at, block);
      if (blocks.size > 2 * SMOOTHING_FRAMES) blocks.delete(blocks.keys().next().value ?? at); // the oldest
    }
    for (let k = 0; k < TEXTURE_WIDTH; k++) smoothed[k] += weight * block[k];
  }
  const bytes = new Uint8Array(TEXTURE_WIDTH * 2);
  const scale = 255 / (MAX_DB - MIN_DB);
  for (let k = 0; k < TEXTURE_WIDTH; k++) {
    const db = 20 * Math.log10(smoothed[k]);
    bytes[k] = Math.max(0, Math.min(255, Math.floor(scale * (db - MIN_DB))));
  }
  const start = Math.round(end) - FFT_SIZE;
  for (let n = 0; n < TEXTURE_WIDTH; n++) {
    const i = start + n;
    const x = i < 0 ? 0 : sampleAt(i);
    bytes[TEXTURE_WIDTH + n] = Math.max(0, Math.min(255, Math.floor(128 * (1 + x))));
  }
  return bytes;
}
