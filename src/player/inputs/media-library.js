// The site's media a shader's channels name (a texture, a cubemap, a volume, a video, music, by the site's paths
// `/media/a/<hash>.<ext>`), from a media folder the page is pointed at: `?media=URL` of a folder
// its own server serves, laid out as the site's paths (`<folder>/a/<hash>.<ext>`). The command
// line's `--media DIR` serves one there. Each channel's files are fetched and decoded here (the
// images flipped as its sampler's vflip says), then given to the render worker
// (gpu/channels/media-textures.js), which makes each channel's texture with its own sampler. A video or
// music is opened as the page's own channels open one (media-input.js), and gives its texture
// at each frame's iTime (withFrames), as a channel of the panel does.
//
// What could not be had is said: every channel the library could not fill keeps the page's note
// that it is black, with the file and why (no folder given, no such file, not an image).

import {
  LIBRARY_KINDS,
  MEDIA_WORDS,
  MOVING_LIBRARY_KINDS,
  cubeFaceOrder,
  isOneChannelTexture,
  mediaFiles,
  mediaUrlPath,
  parseVolume,
} from '../../shadertoy/media.js';
import { MediaInput } from './media-input.js';
import { unsupportedNote } from '../../shadertoy/multipass.js';
import { mediaKey } from '../gpu/channels/channel-bindings.js';

/** @typedef {import('../../shadertoy/multipass.js').MultipassShader} MultipassShader */
/** @typedef {import('../../shadertoy/multipass.js').MediaChannel} MediaChannel */
/** @typedef {import('../gpu/channels/media-textures.js').MediaPayload} MediaPayload */
/** @typedef {{key: string, payload: MediaPayload, sampler: import('../../shadertoy/multipass.js').Sampler}} MediaEntry */

/** The library's fetches: a file's bytes by URL, rejecting with a readable reason. @typedef {(url: string) => Promise<Blob>} FetchMedia */

/** Decoded as the site uploads: no colour-space conversion, no premultiplied alpha. */
const decoding = (/** @type {boolean} */ vflip) =>
  /** @type {ImageBitmapOptions} */ ({
    imageOrientation: vflip ? 'flipY' : 'from-image',
    colorSpaceConversion: 'none',
    premultiplyAlpha: 'none',
  });

export class MediaLibrary {
  /**
   * @param {{tell: (type: 'passMedia', params: import('../gpu/protocol.js').Commands['passMedia']) => void}} gpu the render worker
   * @param {FetchMedia} fetchFile
   */
  constructor(gpu, fetchFile) {
    this.gpu = gpu;
    this.fetchFile = fetchFile;
    /** The media folder's URL (ending in /), or null: none given. @type {string | null} */
    this.base = null;
    /** @type {string | null} */
    this.given = null;
    /** The entries the worker has, kept to give a new worker again. @type {MediaEntry[]} */
    this._entries = [];
    /** The videos and music of the shader's channels. @type {Array<{key: string, input: MediaInput, sampler: import('../../shadertoy/multipass.js').Sampler}>} */
    this._moving = [];
    /** The page's note on each channel the library filled, and the line that replaces the note of each it could not. @type {Map<string, string | null>} */
    this._lines = new Map();
    /** What the loaded (or loading) media are: the folder and each channel's kind, file and sampler. */
    this._signature = '';
    /** The load under way (resolves when the worker has its media). @type {Promise<void> | null} */
    this.pending = null;
    this._loads = 0;
  }

  /** @param {string | null} url the media folder, absolute or relative to the page (null: none) */
  setBase(url) {
    /** The folder as the page's URL gave it (a shared link carries it so). */
    this.given = url;
    this.base = url ? new URL(url.endsWith('/') ? url : `${url}/`, location.href).href : null;
  }

  /**
   * Loads the media a shader's channels name, in place of the last shader's; `pending` resolves
   * once the worker has them (a frame drawn before would draw the channels black).
   * @param {MultipassShader} project
   */
  load(project) {
    const load = ++this._loads;
    const wanted = project.passes.flatMap((pass) =>
      pass.channels.flatMap((channel, i) =>
        channel && (LIBRARY_KINDS.includes(channel.kind) || MOVING_LIBRARY_KINDS.includes(channel.kind))
          ? [{ pass: pass.name, index: i, channel: /** @type {MediaChannel} */ (channel) }]
          : [],
      ),
    );
    // an edit that names the same media in the same channels (most edits) keeps what is loaded
    const signature = JSON.stringify([
      this.base,
      wanted.map((w) => [w.pass, w.index, w.channel.kind, w.channel.src, w.channel.sampler, w.channel.extra?.id]),
    ]);
    if (signature === this._signature) return;
    this._signature = signature;
    if (!wanted.length && !this._entries.length && !this._moving.length) {
      this._lines = new Map();
      this.pending = null;
      return;
    }
    this.pending = (async () => {
      const results = await Promise.all(wanted.map((want) => this._channel(want.channel).then((payload) => ({ ...want, payload }))));
      if (load !== this._loads) {
        for (const { payload } of results) {
          if (payload instanceof MediaInput) payload.close();
          else if (typeof payload !== 'string') closeImages(payload);
        }
        return; // a newer shader came meanwhile
      }
      for (const { input } of this._moving) input.close();
      for (const { payload } of this._entries) closeImages(payload); // the worker has its own copies
      this._moving = results.flatMap(({ pass, index, channel, payload }) =>
        payload instanceof MediaInput ? [{ key: mediaKey(pass, index), input: payload, sampler: channel.sampler }] : [],
      );
      this._entries = results.flatMap(({ pass, index, channel, payload }) =>
        typeof payload === 'string' || payload instanceof MediaInput
          ? []
          : [{ key: mediaKey(pass, index), payload, sampler: channel.sampler }],
      );
      this._lines = new Map(
        results.map(({ pass, index, channel, payload }) => [
          unsupportedNote(pass, index, channel),
          typeof payload === 'string' ? `${pass}, iChannel${index}: ${payload}; the channel is black` : null,
        ]),
      );
      this.resend();
      this.pending = null;
    })();
  }

  /**
   * A frame's inputs with the textures of the shader's videos and music at its iTime (none: the
   * same inputs at once).
   * @param {import('../gpu/protocol.js').FrameInputs} frame
   * @param {boolean | null} running the live page's clock plays at 1× (music is heard), null
   *   for a frame drawn apart from it (a recording, a capture)
   */
  withFrames(frame, running) {
    if (!this._moving.length) return frame;
    return Promise.all(
      this._moving.map(async ({ key, input, sampler }) => {
        if (running !== null) input.follow(frame.time, running);
        return { key, frame: await input.frameAt(frame.time, frame.delta, sampler.vflip) };
      }),
    ).then((passMedia) => ({ ...frame, passMedia }));
  }

  /**
   * A frame's inputs once the shader's media are in the worker, with its videos' and music's
   * textures at its iTime; `inputs` gives the frame's other inputs (the page's channels') after
   * the wait: what the frame loop asks for each frame (app.js).
   * @param {() => import('../gpu/protocol.js').FrameInputs | Promise<import('../gpu/protocol.js').FrameInputs>} inputs
   * @param {boolean | null} running as for withFrames
   */
  frameInputs(inputs, running) {
    const withOwn = () => {
      const given = inputs();
      return given instanceof Promise ? given.then((frame) => this.withFrames(frame, running)) : this.withFrames(given, running);
    };
    return this.pending ? this.ready().then(withOwn) : withOwn();
  }

  /** Stops the music, when the page's clock stops. */
  silence() {
    for (const { input } of this._moving) input.follow(0, false);
  }

  /** Resolves once the media of the latest shader are in the worker (a load that a newer one replaced is waited past). */
  async ready() {
    while (this.pending) await this.pending;
  }

  /** Gives the worker the media again (a new worker, a restored context). */
  resend() {
    this.gpu.tell('passMedia', { entries: this._entries, moving: this._moving.map(({ key, sampler }) => ({ key, sampler })) });
  }

  /**
   * The lines of the page's note on what the shader goes without, with those of the channels the
   * library filled taken out and those it could not fill said with why.
   * @param {string[]} lines
   */
  adjust(lines) {
    return lines.flatMap((line) => {
      if (!this._lines.has(line)) return [line];
      const instead = this._lines.get(line);
      return instead ? [instead] : [];
    });
  }

  /**
   * One channel's media decoded, or why it could not be (a string).
   * @param {MediaChannel} channel
   * @returns {Promise<MediaPayload | MediaInput | string>}
   */
  async _channel(channel) {
    const files = mediaFiles(channel);
    const what = `the site's ${channel.kind} ${channel.src || '(no file)'}`;
    if (!files.length) return `${what} is not a path of the site's media (/media/…)`;
    if (!this.base) return `${what} ${MEDIA_WORDS.noFolder}`;
    const base = this.base;
    const fetched = await Promise.allSettled(files.map((file) => this.fetchFile(new URL(mediaUrlPath(file), base).href)));
    const failed = fetched.findIndex((result) => result.status === 'rejected');
    if (failed >= 0) {
      const { message } = /** @type {PromiseRejectedResult} */ (fetched[failed]).reason;
      return /HTTP 404/.test(message)
        ? `${what}: ${files[failed]} ${MEDIA_WORDS.notInFolder}`
        : `${what}: could not fetch ${files[failed]} from the media folder (${message})`;
    }
    const blobs = fetched.map((result) => /** @type {PromiseFulfilledResult<Blob>} */ (result).value);
    const vflip = channel.sampler.vflip;
    try {
      if (channel.kind === 'video' || channel.kind === 'music') return await MediaInput.open(channel.kind, blobs[0], files[0]);
      if (channel.kind === 'volume') return { kind: 'volume', volume: parseVolume(await blobs[0].arrayBuffer()) };
      const images = await Promise.all(blobs.map((blob) => createImageBitmap(blob, decoding(vflip))));
      if (channel.kind === 'cubemap') {
        // WebGL takes a cube's faces only square and of one size (else the cube reads black)
        const odd = images.findIndex((image) => image.width !== image.height || image.width !== images[0].width);
        if (odd >= 0) {
          const size = (/** @type {ImageBitmap} */ image) => `${image.width}x${image.height}`;
          const why = `${what}: a cubemap's faces are square and of one size, and ${files[odd]} is ${size(images[odd])} where ${files[0]} is ${size(images[0])}`;
          for (const image of images) image.close();
          return why;
        }
        return { kind: 'cubemap', faces: cubeFaceOrder(images, vflip) };
      }
      return { kind: 'texture', image: images[0], oneChannel: isOneChannelTexture(channel.extra?.id) };
    } catch (error) {
      return `${what} cannot be read (${error.message})`;
    }
  }
}

/** Closes a payload's images (the page's copies; structured cloning gave the worker its own). @param {MediaPayload} payload */
function closeImages(payload) {
  if (payload.kind === 'texture') payload.image.close();
  else if (payload.kind === 'cubemap') for (const face of payload.faces) face.close();
}
