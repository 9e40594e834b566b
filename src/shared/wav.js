// A stereo 16-bit PCM WAV (RIFF, WAVE, "fmt " with format 1, "data"), written and read: the
// command line's `render -o OUT.wav` and `test`'s sound references. Plain bytes, no Node API,
// so the page could write one too.

/**
 * The WAV file of interleaved 16-bit samples.
 * @param {Int16Array} pcm interleaved, `channels` words a frame
 * @param {number} sampleRate
 * @param {number} [channels]
 * @returns {Uint8Array}
 */
export function encodeWav(pcm, sampleRate, channels = 2) {
  const bytes = new Uint8Array(44 + pcm.length * 2);
  const view = new DataView(bytes.buffer);
  const text = (at, s) => [...s].forEach((c, i) => view.setUint8(at + i, c.charCodeAt(0)));
  text(0, 'RIFF');
  view.setUint32(4, 36 + pcm.length * 2, true);
  text(8, 'WAVE');
  text(12, 'fmt ');
  view.setUint32(16, 16, true);
  view.setUint16(20, 1, true); // PCM
  view.setUint16(22, channels, true);
  view.setUint32(24, sampleRate, true);
  view.setUint32(28, sampleRate * channels * 2, true);
  view.setUint16(32, channels * 2, true);
  view.setUint16(34, 16, true);
  text(36, 'data');
  view.setUint32(40, pcm.length * 2, true);
  for (let i = 0; i < pcm.length; i++) view.setInt16(44 + 2 * i, pcm[i], true);
  return bytes;
}

/**
 * Reads a 16-bit PCM WAV (any chunk order; chunks it does not know are skipped).
 * @param {Uint8Array} bytes
 * @returns {{sampleRate: number, channels: number, pcm: Int16Array}} pcm interleaved
 */
export function decodeWav(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const tag = (at) => String.fromCharCode(...bytes.subarray(at, at + 4));
  if (bytes.length < 12 || tag(0) !== 'RIFF' || tag(8) !== 'WAVE') throw new Error('not a WAV file (no RIFF/WAVE header)');
  let format = null;
  let at = 12;
  while (at + 8 <= bytes.length) {
    const id = tag(at);
    const size = view.getUint32(at + 4, true);
    if (id === 'fmt ') {
      format = { code: view.getUint16(at + 8, true), channels: view.getUint16(at + 10, true), sampleRate: view.getUint32(at + 12, true) };
      if (format.code !== 1 || view.getUint16(at + 22, true) !== 16) throw new Error('not a 16-bit PCM WAV file');
    } else if (id === 'data') {
      if (!format) throw new Error('a WAV file whose data comes before its format');
      const count = Math.min(size, bytes.length - at - 8) >> 1;
      const pcm = new Int16Array(count);
      for (let i = 0; i < count; i++) pcm[i] = view.getInt16(at + 8 + 2 * i, true);
      return { sampleRate: format.sampleRate, channels: format.channels, pcm };
    }
    at += 8 + size + (size & 1);
  }
  throw new Error('a WAV file with no data chunk');
}
