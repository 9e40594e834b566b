// A music input from a file: decoded once, its 512 × 2 texture computed for each frame's iTime
// (spectrum.js), and heard while the page plays.
//
// On the site a music input is an <audio loop> element through an AnalyserNode; iChannelTime is
// the element's currentTime, iChannelResolution (512, 2, 1) (effect.js, Paint_Image). Here the
// file plays from iTime: it is decoded at a fixed rate (DECODE_RATE: on the site the rate is the
// machine's AudioContext's, mostly 48 kHz), so that bin k is k · 48000 / 2048 Hz everywhere, and
// sample i of the loop is sample i mod length; iChannelTime = iTime mod the file's duration.

import { spectrumTexture } from './spectrum.js';

/** The rate the file is decoded at, in Hz. */
const DECODE_RATE = 48_000;

export class AudioFile {
  /**
   * @param {AudioBuffer} buffer the decoded file
   */
  constructor(buffer) {
    this.buffer = buffer;
    /** The file mixed to mono, as an AnalyserNode down-mixes its input (the speakers' rule: the mean). */
    this.mono = new Float32Array(buffer.length);
    for (let c = 0; c < buffer.numberOfChannels; c++) {
      const data = buffer.getChannelData(c);
      for (let i = 0; i < data.length; i++) this.mono[i] += data[i] / buffer.numberOfChannels;
    }
    /** The analyser's blocks already computed, by end sample (spectrumTexture). @type {Map<number, Float64Array>} */
    this._blocks = new Map();
    /** @type {AudioContext | null} the page's playback, once it plays */
    this._context = null;
    /** @type {{node: AudioBufferSourceNode, startedAt: number, offset: number} | null} */
    this._playing = null;
  }

  /**
   * Decodes a file (any the browser decodes: WAV, MP3, Ogg, ...).
   * @param {Blob} blob
   * @param {string} name for the error
   */
  static async decode(blob, name) {
    const context = new OfflineAudioContext(1, 1, DECODE_RATE);
    try {
      return new AudioFile(await context.decodeAudioData(await blob.arrayBuffer()));
    } catch (error) {
      throw new Error(`cannot decode ${name} as audio: use a WAV, MP3 or Ogg file`, { cause: error });
    }
  }

  get duration() {
    return this.buffer.duration;
  }

  /**
   * The channel at iTime `time`, frames `delta` apart.
   * @param {number} time
   * @param {number} delta
   */
  frameAt(time, delta) {
    const length = this.mono.length;
    const mono = this.mono;
    // a still frame (no schedule: iTimeDelta 0) is smoothed as if frames came at 60 a second
    const step = (delta > 0 ? delta : 1 / 60) * DECODE_RATE;
    const bytes = spectrumTexture((i) => mono[i % length], time * DECODE_RATE, step, this._blocks);
    return { kind: /** @type {const} */ ('audio'), bytes, width: 512, height: 2, time: length ? time % this.duration : 0 };
  }

  /**
   * Plays the file from iTime while the clock runs at 1× (stopped otherwise), starting again
   * where iTime is when the two have drifted apart (a pause, a restart, a seek).
   * @param {number} time the frame's iTime
   * @param {boolean} running the clock plays at 1×
   */
  follow(time, running) {
    if (!running) return this.stop();
    if (typeof AudioContext === 'undefined') return;
    this._context ??= new AudioContext();
    const context = this._context;
    const playing = this._playing;
    const at = playing ? playing.offset + context.currentTime - playing.startedAt : NaN;
    // a context the browser holds suspended until a click does not advance: no restart loop then
    if (playing && (context.state !== 'running' || Math.abs(at - time) < 0.15)) return;
    this.stop();
    const node = context.createBufferSource();
    node.buffer = this.buffer;
    node.loop = true;
    node.connect(context.destination);
    const offset = time % this.duration;
    node.start(0, offset);
    this._playing = { node, startedAt: context.currentTime, offset: time };
    context.resume().catch(() => {});
  }

  stop() {
    this._playing?.node.stop();
    this._playing = null;
  }

  close() {
    this.stop();
    this._context?.close().catch(() => {});
    this._context = null;
  }
}
