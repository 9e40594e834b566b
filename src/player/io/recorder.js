// Recording: the running shader drawn frame by frame, off screen, at a fixed frame rate and size,
// into a WebM video (the browser's WebCodecs VideoEncoder, VP9 or VP8, muxed by mediabunny) or a
// .zip of numbered PNGs (fflate). A shader with a Sound tab gets an Opus track in the WebM
// (sound/sound-track.js); a zip of PNGs has no sound (`render -o OUT.wav` makes it). Frame i has
// iTime = i / fps, iTimeDelta = 1 / fps, iFrameRate = fps and iFrame = i, whatever the frame
// costs to draw, so a shader that takes seconds per frame still records smoothly. The live frame loop is paused meanwhile (and plays
// again after, if it was playing); iMouse is the page's, scaled to the recording's size.

import { fitGpu } from '../app/canvas-size.js';
import { addSoundTrack } from '../sound/sound-track.js';
import { hasSound, sampleRange, soundSamples } from '../sound/samples.js';

/** @typedef {import('../app/app.js').ShaderApp} ShaderApp */
/** @typedef {import('../gpu/protocol.js').FrameInputs} FrameInputs */

/**
 * What to record. `frames` wins over `duration` (seconds); width and height default to the canvas.
 * @typedef {object} RecordRequest
 * @property {'webm' | 'png'} [format]
 * @property {number} [frames]
 * @property {number} [duration]
 * @property {number} [fps]
 * @property {number} [width]
 * @property {number} [height]
 */

/**
 * A finished recording.
 * @typedef {object} Recording
 * @property {'webm' | 'png'} format
 * @property {number} frames
 * @property {number} fps
 * @property {number} width
 * @property {number} height
 * @property {string} mimeType
 * @property {string} codec the video codec ('vp9', 'vp8'), or 'png'
 * @property {'opus' | null} audio the WebM's audio track: the Sound tab in Opus, or none
 * @property {Uint8Array} bytes the file
 */

export const MAX_FRAMES = 36_000;
export const MAX_FPS = 120;

/** WebCodecs codec strings, best first, with mediabunny's names for them. */
const CODECS = [
  { webcodecs: 'vp09.00.10.08', name: /** @type {const} */ ('vp9') },
  { webcodecs: 'vp8', name: /** @type {const} */ ('vp8') },
];

/** The error a cancelled recording rejects with. */
export class RecordingCancelled extends Error {
  constructor() {
    super('recording cancelled');
    this.name = 'RecordingCancelled';
  }
}

/** Resolves in a later task: lets the page show progress and take a click on Cancel. */
const nextTask = () => new Promise((resolve) => setTimeout(resolve, 0));

/**
 * The request made whole and safe: format, whole frame count, fps, and a size the GPU can draw.
 * @param {RecordRequest} request
 * @param {{width: number, height: number}} canvas the default size
 * @param {number} maxSide the GPU's limit
 */
function recordSettings(request, canvas, maxSide) {
  /** @type {'webm' | 'png'} */
  const format = request.format === 'png' ? 'png' : 'webm';
  const number = (value, fallback) => (Number.isFinite(Number(value)) && Number(value) > 0 ? Number(value) : fallback);
  const fps = Math.min(MAX_FPS, number(request.fps, 30));
  const frames = Math.min(MAX_FRAMES, Math.max(1, Math.round(number(request.frames, number(request.duration, 2) * fps))));
  const wanted = {
    width: Math.max(1, Math.round(number(request.width, canvas.width))),
    height: Math.max(1, Math.round(number(request.height, canvas.height))),
  };
  const { width, height } = fitGpu(wanted, maxSide, 'recording size');
  return { format, frames, fps, width, height };
}

/** The first of VP9, VP8 that this browser's VideoEncoder encodes at this size. */
async function videoCodec(width, height, fps) {
  if (typeof VideoEncoder === 'undefined') throw new Error('this browser has no WebCodecs VideoEncoder: record a PNG sequence');
  for (const codec of CODECS) {
    const config = { codec: codec.webcodecs, width, height, framerate: fps, bitrate: Math.max(1e6, width * height * fps * 0.2) };
    const { supported } = await VideoEncoder.isConfigSupported(config).catch(() => ({ supported: false }));
    if (supported) return { ...codec, config };
  }
  throw new Error(`this browser encodes neither VP9 nor VP8 at ${width}×${height}: record a PNG sequence`);
}

/**
 * WebM: each frame into the VideoEncoder, each chunk it gives into mediabunny's WebM muxer; with
 * `sound` (a shader with a Sound tab), its samples for the frames' time as an Opus track.
 * @param {{width: number, height: number, fps: number, sound: (() => Promise<Uint16Array>) | null}} settings
 */
async function webmWriter({ width, height, fps, sound }) {
  const codec = await videoCodec(width, height, fps);
  // loaded when first needed: mediabunny is a third of the page's script (measured below, README)
  const { BufferTarget, EncodedAudioPacketSource, EncodedPacket, EncodedVideoPacketSource, Output, WebMOutputFormat } =
    await import('mediabunny');
  const output = new Output({ format: new WebMOutputFormat(), target: new BufferTarget() });
  const source = new EncodedVideoPacketSource(codec.name);
  output.addVideoTrack(source, { frameRate: fps });
  const soundTrack = sound ? await addSoundTrack(output, { EncodedAudioPacketSource, EncodedPacket }) : null;
  await output.start();
  /** @type {Promise<void>} the packets handed to the muxer, in order */
  let muxed = Promise.resolve();
  /** @type {Error | null} */
  let failure = null;
  const encoder = new VideoEncoder({
    output: (chunk, meta) => {
      muxed = muxed.then(() => source.add(EncodedPacket.fromEncodedChunk(chunk), meta));
      muxed.catch((error) => (failure ??= error));
    },
    error: (error) => (failure ??= error),
  });
  encoder.configure(codec.config);
  const check = () => {
    if (failure) throw failure;
  };
  return {
    codec: codec.name,
    mimeType: 'video/webm',
    /** @param {Uint8Array} rgba rows top to bottom @param {number} i */
    async add(rgba, i) {
      check();
      const frame = new VideoFrame(rgba, {
        format: 'RGBA',
        codedWidth: width,
        codedHeight: height,
        timestamp: Math.round((i * 1e6) / fps),
        duration: Math.round(1e6 / fps),
      });
      try {
        encoder.encode(frame, { keyFrame: i % Math.max(1, Math.round(fps * 2)) === 0 });
      } finally {
        frame.close();
      }
      // backpressure: a software encoder may fall behind the (cheap) frames of a small shader
      while (encoder.encodeQueueSize > 2) await new Promise((resolve) => encoder.addEventListener('dequeue', resolve, { once: true }));
      await muxed;
      check();
    },
    async finish() {
      await encoder.flush();
      await muxed;
      check();
      encoder.close();
      if (soundTrack && sound) await soundTrack.write(await sound());
      await output.finalize();
      return new Uint8Array(/** @type {ArrayBuffer} */ (/** @type {import('mediabunny').BufferTarget} */ (output.target).buffer));
    },
    async cancel() {
      if (encoder.state !== 'closed') encoder.close();
      await output.cancel().catch(() => {});
    },
  };
}

/** RGBA rows top to bottom → PNG bytes. */
async function pngBytes(rgba, width, height) {
  const canvas = new OffscreenCanvas(width, height);
  const context = /** @type {OffscreenCanvasRenderingContext2D} */ (canvas.getContext('2d'));
  context.putImageData(new ImageData(new Uint8ClampedArray(rgba.buffer, rgba.byteOffset, rgba.byteLength), width, height), 0, 0);
  const blob = await canvas.convertToBlob({ type: 'image/png' });
  return new Uint8Array(await blob.arrayBuffer());
}

/** PNG sequence: frame-0000.png, frame-0001.png, ... in a .zip (stored: PNGs are compressed). */
function pngWriter({ width, height, frames }) {
  /** @type {Record<string, Uint8Array>} */
  const files = {};
  const digits = Math.max(4, String(frames - 1).length);
  return {
    codec: 'png',
    mimeType: 'application/zip',
    /** @param {Uint8Array} rgba @param {number} i */
    async add(rgba, i) {
      files[`frame-${String(i).padStart(digits, '0')}.png`] = await pngBytes(rgba, width, height);
    },
    async finish() {
      const { zipSync } = await import('fflate'); // loaded when first needed
      return zipSync(files, { level: 0 });
    },
    async cancel() {},
  };
}

/** One recording at a time, of one app; the toolbar's dialog and window.shaderEngine share it. */
export class Recorder {
  /** @param {ShaderApp} app */
  constructor(app) {
    this.app = app;
    /** @type {AbortController | null} */
    this._abort = null;
  }

  get busy() {
    return this._abort !== null;
  }

  /** Stops the recording under way: its promise rejects with RecordingCancelled, nothing is made. */
  cancel() {
    this._abort?.abort();
  }

  /**
   * Records the running shader.
   * @param {RecordRequest} request
   * @param {(done: number, total: number) => void} [onProgress] after each frame
   * @returns {Promise<Recording>}
   */
  async record(request, onProgress = () => {}) {
    return this._frames(request, async (app, settings) => {
      const multipass = app.isMultipass;
      // the Sound tab's samples for the frames' time, from sample 0 at frame 0 (sound-track.js)
      const { first, count } = sampleRange(0, settings.frames / settings.fps);
      const sound = hasSound(app) ? () => soundSamples(app, first, count) : null;
      const writer = settings.format === 'webm' ? await webmWriter({ ...settings, sound }) : pngWriter(settings);
      try {
        const frame = frameInputs(app, settings.fps);
        for (let i = 0; i < settings.frames; i++) {
          // RGBA8 with alpha 1, as the page shows it (the worker reads it back so)
          const rgba = await this._draw(frame(i), settings, multipass);
          await writer.add(rgba, i);
          onProgress(i + 1, settings.frames);
          await nextTask();
        }
        this._check();
        const bytes = await writer.finish();
        this._check();
        const audio = sound && settings.format === 'webm' ? /** @type {const} */ ('opus') : null;
        return { ...settings, codec: writer.codec, audio, mimeType: writer.mimeType, bytes };
      } catch (error) {
        await writer.cancel();
        throw error;
      }
    });
  }

  /**
   * Frame `frame` of the running shader as a recording would have it (iTime = frame / fps,
   * iFrame = frame), with no file made: a shader with buffers has frames 0 … frame-1 drawn first
   * and dropped (its state is what they left); a shader without any has no state a frame could
   * leave, so only that frame is drawn, with the same pixels. No frame cap but the clock's.
   * @param {{frame: number, fps?: number, width?: number, height?: number}} request
   * @param {(done: number, total: number) => void} [onProgress] after each frame drawn
   * @returns {Promise<{width: number, height: number, data: Uint8Array}>}
   */
  async frameAt({ frame: last, ...request }, onProgress = () => {}) {
    return this._frames({ ...request, frames: 1 }, async (app, settings) => {
      const multipass = app.isMultipass;
      const frame = frameInputs(app, settings.fps);
      const first = multipass ? 0 : last;
      /** @type {Uint8Array} */
      let rgba = new Uint8Array(0);
      for (let i = first; i <= last; i++) {
        rgba = await this._draw(frame(i), settings, multipass);
        onProgress(i - first + 1, last - first + 1);
        if ((i - first) % 16 === 15) await nextTask(); // Cancel and the progress poll get their turn
      }
      this._check();
      return { width: settings.width, height: settings.height, data: rgba };
    });
  }

  /**
   * Runs `work` with the live loop paused and this recorder busy, then puts the page back.
   * @template T
   * @param {RecordRequest} request
   * @param {(app: ShaderApp, settings: ReturnType<typeof recordSettings>) => Promise<T>} work
   * @returns {Promise<T>}
   */
  async _frames(request, work) {
    if (this.busy) throw new Error('a recording is already under way');
    const abort = new AbortController();
    this._abort = abort;
    const app = this.app;
    const wasPlaying = app.inputs.playing;
    try {
      await app.compiles.settled();
      if (!app.compiles.hasProgram || app.gpu.contextLost) throw new Error('nothing to record: no shader is running');
      const canvas = app.frames.size;
      // a multipass shader's buffers are the canvas's size: its frames are recorded at that size,
      // every pass drawn each frame, from cleared buffers (as iFrame starts at 0)
      const settings = recordSettings(app.isMultipass ? { ...request, ...canvas } : request, canvas, app.gpu.maxSize);
      if (wasPlaying) app.pause();
      if (app.isMultipass) app.gpu.tell('clearBuffers', {});
      return await work(app, settings);
    } finally {
      this._abort = null;
      if (wasPlaying && !app.inputs.playing) app.play();
    }
  }

  /** Throws when the recording was cancelled. */
  _check() {
    if (this._abort?.signal.aborted) throw new RecordingCancelled();
  }

  /**
   * One frame drawn off screen and read back (RGBA8, rows top to bottom).
   * @param {FrameInputs} inputs
   * @param {{width: number, height: number}} size
   * @param {boolean} allPasses
   */
  async _draw(inputs, { width, height }, allPasses) {
    this._check();
    if (this.app.gpu.contextLost) throw new Error('the GPU context was lost while recording');
    // a moving channel's texture at the frame's iTime: a video's frame for it, not the last one ready
    const withMedia = await this.app.channels.withMedia(inputs, null);
    this._check();
    return this.app.gpu.ask('capture', { inputs: withMedia, width, height, allPasses });
  }
}

/**
 * The inputs of recorded frame i: time from the frame number, the page's mouse, the date moving
 * on with iTime from the start (the page's fixed date, else the real one when the recording began).
 * @param {ShaderApp} app
 * @param {number} fps
 * @returns {(i: number) => FrameInputs}
 */
function frameInputs(app, fps) {
  const mouse = app.inputs.mouse();
  const { width, height } = app.frames.size;
  const start = Date.now();
  const inputs = app.inputs;
  return (i) => ({
    width,
    height,
    time: i / fps,
    delta: 1 / fps,
    frameRate: fps,
    frame: i,
    mouse,
    date: inputs.dateAt(i / fps, start + (i * 1000) / fps),
  });
}
