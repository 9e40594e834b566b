// The music the tests make and what the site's analyser makes of it, computed: one sine at the
// centre of FFT bin 20, as a WAV, and the 512 x 2 texture (spectrum row, waveform row) a shader
// reads back at an iTime. Shared by media-inputs.test.js (a file in iChannel0) and
// media-library.test.js (a file a shader's JSON names).

import { expect } from 'vitest';
import { pixel } from './page-helpers.js';

// ---- the music: one sine at the centre of bin 20, 48 kHz, 16-bit, 480 whole periods ----------
// (1.024 s: it loops without a seam). The times read are past the analyser's smoothing's reach
// (42 frames at 1/60 s and a 2048-sample window), where a steady tone's smoothed value is its own.
export const RATE = 48_000;
const BIN_20 = 20;
const TONE = { frequency: (BIN_20 * RATE) / 2048, amplitude: 0.05, seconds: 1.024 };
export const toneSamples = () =>
  Int16Array.from({ length: Math.round(RATE * TONE.seconds) }, (_, i) =>
    Math.round(TONE.amplitude * Math.sin((2 * Math.PI * TONE.frequency * i) / RATE) * 32767),
  );
export function wav(samples) {
  const data = Buffer.from(samples.buffer);
  const header = Buffer.alloc(44);
  header.write('RIFF', 0);
  header.writeUInt32LE(36 + data.length, 4);
  header.write('WAVEfmt ', 8);
  header.writeUInt32LE(16, 16);
  header.writeUInt16LE(1, 20); // PCM
  header.writeUInt16LE(1, 22); // mono
  header.writeUInt32LE(RATE, 24);
  header.writeUInt32LE(RATE * 2, 28);
  header.writeUInt16LE(2, 32);
  header.writeUInt16LE(16, 34);
  header.write('data', 36);
  header.writeUInt32LE(data.length, 40);
  return Buffer.concat([header, data]);
}
/** texelFetch of the 512 × 2 texture in r (row 0 at the bottom), iChannelTime in g, width / 1024 in b. */
export const MUSIC_READER = `void mainImage(out vec4 c, in vec2 p) {
  c = vec4(texelFetch(iChannel0, ivec2(p), 0).r, iChannelTime[0], iChannelResolution[0].x / 1024.0, 1.0);
}\n`;
/**
 * What the site's analyser gives for the tone at iTime t, computed from the spec's formulas: a
 * sine of amplitude A at a bin's centre, Blackman-windowed and scaled by 1/N, is A · a0 / 2 in
 * that bin (a0 = 0.42), in dB mapped from [-100, -30] to 0..255; the waveform row is
 * floor(128 · (1 + x)) of the 512 oldest samples of the 2048 before t.
 */
function expectedMusic(samples, t) {
  const db = 20 * Math.log10((TONE.amplitude * 0.42) / 2);
  const peak = Math.floor((255 / 70) * (db + 100));
  const end = Math.round(t * RATE);
  const wave = Array.from({ length: 512 }, (_, n) => {
    const i = end - 2048 + n;
    const x = i < 0 ? 0 : samples[i % samples.length] / 32768;
    return Math.max(0, Math.min(255, Math.floor(128 * (1 + x))));
  });
  return { peak, wave, channelTime: t % TONE.seconds };
}

/** Rows of an RGBA image, as r bytes; row 0 of the texture is the picture's bottom row. */
const redRow = (image, y) => Array.from({ length: image.width }, (_, x) => image.data[(y * image.width + x) * 4]);

export function checkMusic(image, samples, t, where) {
  const { peak, wave, channelTime } = expectedMusic(samples, t);
  const spectrum = redRow(image, 1); // texture row 0: the picture's bottom row
  const waveform = redRow(image, 0);
  const top = spectrum.indexOf(Math.max(...spectrum));
  expect(top, `${where}: the spectrum's peak bin`).toBe(BIN_20);
  expect(Math.abs(spectrum[BIN_20] - peak), `${where}: the peak's byte ${spectrum[BIN_20]}, computed ${peak}`).toBeLessThanOrEqual(1);
  // one peak: the Blackman window's main lobe is 3 bins either side; beyond it, far below
  const beyond = spectrum.filter((_, k) => Math.abs(k - BIN_20) > 3);
  expect(Math.max(...beyond), `${where}: the spectrum away from the peak`).toBeLessThan(peak - 60);
  const off = waveform.map((v, n) => Math.abs(v - wave[n]));
  expect(Math.max(...off), `${where}: the waveform row against the samples`).toBeLessThanOrEqual(1);
  expect(Math.abs(pixel(image, 0, 1)[1] - channelTime * 255), `${where}: iChannelTime`).toBeLessThanOrEqual(1.5);
  expect(pixel(image, 0, 1)[2], `${where}: iChannelResolution.x 512`).toBe(128);
}
