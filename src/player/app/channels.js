// What is in iChannel0..3, as the page loaded it: the one owner of each channel's image (kept to
// give a new render worker again) or moving input (a video or music file, the webcam, the
// microphone: src/player/inputs/), its size (the panel shows it) and the URL it came from (a shared
// link carries it). The worker gets a copy of each image, and each frame the moving inputs'
// textures at that frame's iTime (withMedia). Fetching a file is the page's edge
// (io/shader-loader.js's loadChannel), given to it.

import { MediaInput } from '../inputs/media-input.js';

/** @typedef {import('./render-client.js').RenderClient} RenderClient */
/** @typedef {import('../gpu/protocol.js').FrameInputs} FrameInputs */
/** @typedef {{kind: 'video' | 'music', blob: Blob, name: string}} MediaFile */
/** @typedef {(source: string | Blob) => Promise<ImageBitmap | MediaFile>} ChannelLoader */

const CHANNEL_COUNT = 4;
/** The sources that are a device, not a file: setChannel(i, 'webcam:') and setChannel(i, 'mic:'). */
const DEVICES = { 'webcam:': /** @type {const} */ ('webcam'), 'mic:': /** @type {const} */ ('mic') };

export class Channels {
  /**
   * @param {RenderClient} gpu
   * @param {ChannelLoader} load a file (a URL, a File or Blob) fetched: an image decoded (rows
   *   flipped as Shadertoy uploads them), or a video or music file's bytes
   */
  constructor(gpu, load) {
    this.gpu = gpu;
    this.load = load;
    /** The image in each channel, as loaded (null: black or a moving input). @type {Array<ImageBitmap | null>} */
    this.images = Array(CHANNEL_COUNT).fill(null);
    /** The moving input in each channel. @type {Array<MediaInput | null>} */
    this.media = Array(CHANNEL_COUNT).fill(null);
    /** The size of each moving input's last frame. @type {Array<[number, number]>} */
    this._mediaSizes = Array.from({ length: CHANNEL_COUNT }, () => /** @type {[number, number]} */ ([0, 0]));
    /** The URL of each channel's file, when it came from one. @type {Array<string | null>} */
    this.urls = Array(CHANNEL_COUNT).fill(null);
    /** Why each channel's last file could not be had, for the page's note (null: it was). @type {Array<string | null>} */
    this.failures = Array(CHANNEL_COUNT).fill(null);
  }

  /**
   * Loads a file (URL, File or Blob: an image, a video, music) into a channel, or the webcam
   * ('webcam:') or the microphone ('mic:'); null empties it. Rejects with a readable reason and
   * leaves the channel as it was.
   * @param {number} index
   * @param {string | Blob | null} source
   */
  async set(index, source) {
    if (!(Number.isInteger(index) && index >= 0 && index < CHANNEL_COUNT)) throw new Error(`no channel ${index}: iChannel0..3`);
    let image = null;
    let media = null;
    const device = typeof source === 'string' ? DEVICES[/** @type {keyof typeof DEVICES} */ (source)] : undefined;
    if (device) media = await MediaInput.open(device, null, device);
    else if (source !== null) {
      try {
        const loaded = await this.load(source);
        if (loaded instanceof ImageBitmap) image = loaded;
        else media = await MediaInput.open(loaded.kind, loaded.blob, loaded.name);
      } catch (error) {
        const name = typeof source === 'string' ? fileName(source) : 'the file';
        const why = error.message.includes(name) ? error.message : `${name}: ${error.message}`;
        this.failures[index] = `iChannel${index}: ${why}; the channel is black`;
        throw error;
      }
    }
    this.failures[index] = null;
    this.media[index]?.close();
    this.images[index] = image;
    this.media[index] = media;
    this._mediaSizes[index] = [0, 0];
    this.urls[index] = typeof source === 'string' && !device ? source : null; // a link cannot carry a device
    await this._send(index);
  }

  /** Gives the worker every image again (a new worker, a restored context). */
  resend() {
    this.images.forEach((image, i) => image && this._send(i));
  }

  /**
   * A frame's inputs with its moving channels' textures at its iTime (none: the same inputs).
   * @param {FrameInputs} frame
   * @param {boolean | null} running the live page's clock plays at 1× (music is heard), null for
   *   a frame drawn apart from it (a recording, a capture)
   * @returns {FrameInputs | Promise<FrameInputs>} the same inputs at once when no channel moves
   */
  withMedia(frame, running) {
    if (!this.media.some(Boolean)) return frame;
    return this._withMedia(frame, running);
  }

  /** @param {FrameInputs} frame @param {boolean | null} running @returns {Promise<FrameInputs>} */
  async _withMedia(frame, running) {
    const media = await Promise.all(
      this.media.map(async (input, i) => {
        if (!input) return null;
        if (running !== null) input.follow(frame.time, running);
        // a file's picture upright as Shadertoy uploads one by default (vflip true), as images are
        const texture = await input.frameAt(frame.time, frame.delta, true);
        this._mediaSizes[i] = [texture.width, texture.height];
        return texture;
      }),
    );
    return { ...frame, media };
  }

  /** Stops the music, when the page's clock stops. */
  silence() {
    for (const input of this.media) input?.follow(0, false);
  }

  /** The worker gets a copy: the page keeps the original, to give a new worker. @param {number} index */
  async _send(index) {
    const image = this.images[index];
    const copy = image ? await createImageBitmap(image, { premultiplyAlpha: 'none', colorSpaceConversion: 'none' }) : null;
    this.gpu.tell('channel', { index, image: copy });
  }

  /** Whether a channel holds an image or a moving input (not the black default). @param {number} index */
  inUse(index) {
    return this.images[index] !== null || this.media[index] !== null;
  }

  /** [width, height] of what is in each channel (0, 0 when empty, or before a moving one's first frame). */
  sizes() {
    return this.images.map((image, i) => (image ? [image.width, image.height] : this._mediaSizes[i]));
  }
}

/** A URL's file name as a person would say it (its last segment, decoded where it can be). @param {string} url */
function fileName(url) {
  const last = url.split(/[?#]/)[0].split('/').pop() || url;
  try {
    return decodeURIComponent(last);
  } catch {
    return last; // a stray "%"
  }
}
