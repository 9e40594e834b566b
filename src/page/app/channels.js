// The images in iChannel0..3, as the page loaded them: the one owner of each channel's image
// (kept to give a new render worker again), its size (the panel shows it) and the URL it came
// from (a shared link carries it). The worker gets a copy of each image. Fetching and decoding
// an image is the page's edge (io/shader-loader.js's loadImage), given to it.

/** @typedef {import('./render-client.js').RenderClient} RenderClient */
/** @typedef {(source: string | Blob) => Promise<ImageBitmap>} ImageLoader */

const CHANNEL_COUNT = 4;

export class Channels {
  /**
   * @param {RenderClient} gpu
   * @param {ImageLoader} loadImage an image (a URL, a File or Blob) fetched and decoded, rows flipped as Shadertoy uploads them
   */
  constructor(gpu, loadImage) {
    this.gpu = gpu;
    this.loadImage = loadImage;
    /** The image in each channel, as loaded (null: black). @type {Array<ImageBitmap | null>} */
    this.images = Array(CHANNEL_COUNT).fill(null);
    /** The URL of each channel's image, when it came from one. @type {Array<string | null>} */
    this.urls = Array(CHANNEL_COUNT).fill(null);
  }

  /**
   * Loads an image (URL, File or Blob) into a channel; null empties it. Rejects with a readable
   * reason (the loader's) and leaves the channel as it was.
   * @param {number} index
   * @param {string | Blob | null} source
   */
  async set(index, source) {
    if (!(Number.isInteger(index) && index >= 0 && index < CHANNEL_COUNT)) throw new Error(`no channel ${index}: iChannel0..3`);
    const image = source === null ? null : await this.loadImage(source);
    this.images[index] = image;
    this.urls[index] = typeof source === 'string' ? source : null;
    await this._send(index);
  }

  /** Gives the worker every image again (a new worker, a restored context). */
  resend() {
    this.images.forEach((image, i) => image && this._send(i));
  }

  /** The worker gets a copy: the page keeps the original, to give a new worker. @param {number} index */
  async _send(index) {
    const image = this.images[index];
    const copy = image ? await createImageBitmap(image, { premultiplyAlpha: 'none', colorSpaceConversion: 'none' }) : null;
    this.gpu.tell('channel', { index, image: copy });
  }

  /** Whether a channel holds an image (not the black default). @param {number} index */
  inUse(index) {
    return this.images[index] !== null;
  }

  /** [width, height] of the image in each channel (0, 0 when empty). */
  sizes() {
    return this.images.map((image) => (image ? [image.width, image.height] : [0, 0]));
  }
}
