// The Sound tab as a recording's audio track: Opus through WebCodecs' AudioEncoder, its packets
// into the same mediabunny WebM muxer as the video's (io/recorder.js), as the video's go in.
// (mediabunny's own AudioSampleSource would drive the encoder too, but it pulls in its whole
// encoding layer: the recorder's chunk of it grew from 80 kB to 690 kB, for every recording.)
// Sample 0 is at timestamp 0, as frame 0 is (iTime 0), so sound and frames stay in step; the
// track holds the samples of the recording's frames' time, frames / fps seconds.

import { SAMPLE_RATE, toPlayed } from '../../shadertoy/sound.js';

/** Opus's bitrate: stereo music at a quality no one will hear the codec in. */
const OPUS_BITRATE = 160_000;
/** Samples handed to the encoder at once (about a second). */
const CHUNK = SAMPLE_RATE;

/**
 * Adds an Opus track to `output` (before it starts) and returns how to fill it.
 * @param {import('mediabunny').Output} output
 * @param {{EncodedAudioPacketSource: typeof import('mediabunny').EncodedAudioPacketSource, EncodedPacket: typeof import('mediabunny').EncodedPacket}} mediabunny
 */
export async function addSoundTrack(output, { EncodedAudioPacketSource, EncodedPacket }) {
  const config = { codec: 'opus', sampleRate: SAMPLE_RATE, numberOfChannels: 2, bitrate: OPUS_BITRATE };
  const { supported } =
    typeof AudioEncoder === 'undefined'
      ? { supported: false }
      : await AudioEncoder.isConfigSupported(config).catch(() => ({ supported: false }));
  if (!supported) throw new Error('this browser has no WebCodecs Opus AudioEncoder for the Sound tab: record a PNG sequence');
  const source = new EncodedAudioPacketSource('opus');
  output.addAudioTrack(source);
  return {
    /**
     * Encodes the samples (two 16-bit words a sample, sound.js) from timestamp 0, as played.
     * @param {Uint16Array} words
     */
    async write(words) {
      /** @type {Promise<void>} the packets handed to the muxer, in order */
      let muxed = Promise.resolve();
      /** @type {Error | null} */
      let failure = null;
      const encoder = new AudioEncoder({
        output: (chunk, meta) => {
          muxed = muxed.then(() => source.add(EncodedPacket.fromEncodedChunk(chunk), meta));
          muxed.catch((error) => (failure ??= error));
        },
        error: (error) => (failure ??= error),
      });
      encoder.configure(config);
      const [left, right] = toPlayed(words);
      for (let at = 0; at < left.length; at += CHUNK) {
        const n = Math.min(CHUNK, left.length - at);
        const planar = new Float32Array(2 * n);
        planar.set(left.subarray(at, at + n), 0);
        planar.set(right.subarray(at, at + n), n);
        const data = new AudioData({
          format: 'f32-planar',
          sampleRate: SAMPLE_RATE,
          numberOfFrames: n,
          numberOfChannels: 2,
          timestamp: Math.round((at * 1e6) / SAMPLE_RATE),
          data: planar,
        });
        encoder.encode(data);
        data.close();
      }
      await encoder.flush();
      encoder.close();
      await muxed;
      if (failure) throw failure;
      source.close();
    },
  };
}
