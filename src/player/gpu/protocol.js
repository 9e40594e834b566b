// The render worker's messages, written once: both sides import this module, the page's client
// (app/render-client.js) to ask and listen, the worker (gpu/render-worker.js) to answer and tell,
// each typed against the tables below (after MapLibre's typed actor messages). Three kinds:
//
// - requests, page → worker, each answered exactly once by a reply with the same id, holding its
//   result or its error;
// - commands, page → worker, never answered;
// - events, worker → page, unprompted.
//
// A change (a compile that succeeds, a uniform, a channel) while a frame is being drawn starts
// that frame again from its first band: what the page shows next has the change throughout.

import { ShaderCompileError, WebGL2UnavailableError } from './errors.js';

/** @typedef {import('../../shadertoy/multipass.js').MultipassShader} MultipassShader */
/** @typedef {import('../../shadertoy/controls.js').Control} Control */

/**
 * The inputs of one drawn frame, for a drawing buffer of width × height (Shadertoy's uniforms,
 * as the page's clock, mouse and keyboard set them: app/shadertoy-inputs.js).
 * @typedef {object} FrameInputs
 * @property {number} width
 * @property {number} height
 * @property {number} time iTime
 * @property {number} delta iTimeDelta
 * @property {number} frameRate iFrameRate
 * @property {number} frame iFrame
 * @property {number[]} mouse iMouse: [x, y, z, w]
 * @property {number[]} date iDate: [year, month (0-based), day, seconds since midnight]
 * @property {Uint8Array} [keyboard] Shadertoy's keyboard texture (keyboard.js), for the passes that read it
 * @property {Array<MediaFrame | null>} [media] the moving channels' textures for this frame, by
 *   channel (null: not a moving one): src/player/inputs/media-input.js
 * @property {Array<{key: string, frame: MediaFrame}>} [passMedia] the textures of the videos and
 *   music the shader's own channels name, by channel-bindings.js mediaKey (inputs/media-library.js)
 */

/**
 * A moving channel's texture for one frame: a picture (video, webcam: RGBA, rows as uploaded) or
 * 512 × 2 bytes (music, microphone: the spectrum on row 0, the waveform on row 1), its size, and
 * its iChannelTime.
 * @typedef {{kind: 'video', image: ImageBitmap, width: number, height: number, time: number}
 *   | {kind: 'audio', bytes: Uint8Array, width: number, height: number, time: number}} MediaFrame
 */

/**
 * A frame the worker finished for the page.
 * @typedef {object} DrawnFrame
 * @property {ImageBitmap} bitmap the picture, for the page's canvas
 * @property {Uint8Array | null} pixels RGBA8, rows top to bottom, alpha 1, when asked for (readBack)
 * @property {number[]} gpuTimes GPU times (ms) of frames whose timer queries came in with this one
 *   (gpu-timer.js; empty where the browser does not measure them)
 * @property {number} program the `serial` of the compile it was drawn with
 */

/**
 * One pixel of the last frame drawn, as the probe (probe.js) read it, with that frame's inputs.
 * @typedef {import('./probe.js').ProbeResult & {inputs: FrameInputs}} ProbedPixel
 */

/**
 * Requests: name → [what the page sends, what the reply holds].
 * @typedef {object} Requests
 * @property {[{project: MultipassShader, hostBlock: string, fileName: string, serial: number}, null]} compile every
 *   pass of a shader, with `hostBlock` after Shadertoy's header; a failure is a ShaderCompileError
 *   and the last shader that compiled keeps running; `serial` numbers the page's compiles (each
 *   drawn frame says which it was drawn with), and one that lands after a later one is not drawn
 * @property {[{inputs: FrameInputs, readBack: boolean, progressive: boolean}, DrawnFrame]} frame a
 *   frame for the page, drawn band by band; a newer frame replaces one that has not started;
 *   `progressive`: it is shown as it builds up (four times a second: a bitmap with a 'band'
 *   event), else only whole (app/frame-loop.js decides)
 * @property {[{}, Uint8Array]} readFrame the last frame drawn for the page, read back as it was
 *   drawn (its render target; nothing is drawn): RGBA8, rows top to bottom, alpha 1; rejects
 *   before the first frame and while a frame is under way (the page asks once its frame is done)
 * @property {[{inputs: FrameInputs, width: number, height: number, allPasses: boolean, program?: 'aa-pixels'}, Uint8Array]} capture
 *   the same frame at another size, off screen (allPasses: every pass, buffers included, at their
 *   size: a recorded frame); RGBA8, rows top to bottom, alpha 1; program 'aa-pixels': the path
 *   probe's mainImage (the shader's pixels with extra samples) instead of the Image pass
 * @property {[{inputs: FrameInputs, x: number, y: number, width: number, height: number, fullWidth: number, fullHeight: number}, Uint8Array]} captureTile
 *   the width × height tile at (x, y), from the bottom left, of the same frame drawn at fullWidth ×
 *   fullHeight (iResolution that size, fragCoord moved by (x, y): header.js TILE_OFFSET_UNIFORM),
 *   for a shader without buffers; RGBA8, rows top to bottom, alpha 1
 * @property {[{inputs: FrameInputs, width: number, height: number}, Float32Array]} captureFloat the
 *   same frame's Image pass in RGBA32F, its colours as the shader wrote them (unclamped), rows top
 *   to bottom
 * @property {[{project: MultipassShader, hostBlock: string, fileName: string, key: string, texels: number}, null]} compileProbe
 *   a shader's path probe (plugged in by the studio), never shown; `key` comes back with each probe
 * @property {[{x: number, y: number}, ProbedPixel]} probe pixel (x, y) of the last frame drawn (y
 *   from the bottom), read after the frames before it; rejects before the first frame
 * @property {[{first: number, count: number, date: number[]}, Uint16Array]} sound samples [first,
 *   first + count) of the Sound tab of the shader on screen, two 16-bit words a sample (left,
 *   right: src/shadertoy/sound.js); rejects for a shader without one
 * @property {[{inputs: FrameInputs, n: number}, number[]]} bench n whole frames back to back, each
 *   one draw waited for: their times in ms
 * @property {[{reset: boolean}, LoopReport]} loopCuts what llvmpipe's loop limit cut short since the
 *   last reset (loop-cuts.js), and the passes drawn unchecked; `enabled`: whether passes are
 *   guarded at all (on llvmpipe only)
 */

/**
 * @typedef {{enabled: boolean, limit: number, cuts: import('./loop-cuts.js').LoopCut[],
 *   unchecked: import('./loop-cuts.js').UncheckedPass[]}} LoopReport `limit`: llvmpipe's trips a pixel
 */

/**
 * Commands: name → what the page sends.
 * @typedef {object} Commands
 * @property {{}} init start: the worker answers with the `ready` or `failed` event
 * @property {{}} clearBuffers Restart: every buffer of a multipass shader to 0
 * @property {{controls: Control[], values: Record<string, unknown>}} controlUniforms the live
 *   controls as uniforms, with their values
 * @property {{name: string, value: unknown}} controlUniform one live control's new value
 * @property {{index: number, image: ImageBitmap | null}} channel an image into iChannel0..3 (null: black)
 * @property {{entries: Array<{key: string, payload: import('./channels/media-textures.js').MediaPayload,
 *   sampler: import('../../shadertoy/multipass.js').Sampler}>, moving: Array<{key: string,
 *   sampler: import('../../shadertoy/multipass.js').Sampler}>}} passMedia the site's media the
 *   shader's channels name, in place of what was there (key: channel-bindings.js mediaKey): the
 *   still ones, and the channels of the moving ones, whose frames come with each frame
 *   (FrameInputs.passMedia)
 * @property {{bitmaps: number}} settled the answer to `awaitingPaint`: the page has shown (or
 *   closed) and painted the first `bitmaps` ImageBitmaps the worker sent it
 * @property {{stopOnCut: boolean, guard: boolean}} loopGuard whether a frame in which llvmpipe's loop
 *   limit cut a loop stops at that band (its picture is thrown away: the command line draws it
 *   again with SwiftShader) or is drawn whole (the cut is said, the picture kept); `guard`: whether
 *   the passes compiled from now on are guarded on llvmpipe (false only to time the guard: the
 *   benchmark's SHADERPROOF_LOOP_GUARD=off)
 * @property {{}} loseContext WEBGL_lose_context, for tests of a lost context
 * @property {{}} restoreContext
 */

/**
 * Events: name → what the worker sends.
 * @typedef {object} Events
 * @property {{maxSize: number, info: Record<string, string>}} ready the worker has a WebGL2
 *   context: its largest side, and what GPU and driver it runs on
 * @property {{name: string, message: string}} failed no context (name 'WebGL2UnavailableError')
 * @property {{lost: boolean}} context the context was lost (true) or restored (false); a restored
 *   context has no shader: the page compiles again
 * @property {{}} awaitingPaint a new program's first draw waits until the page has painted the
 *   bitmaps it was sent (bands/paint-gate.js): the page answers with `settled`
 * @property {{compiling: boolean}} bandStarted a band went to the GPU (`compiling`: a new
 *   program's first draw, one quad, in which SwiftShader compiles it: bands/band-scheduler.js's pump)
 * @property {{kind: 'frame' | 'capture' | 'probe' | 'compile', y: number, height: number, bitmap: ImageBitmap | null}} band
 *   the GPU finished a band of a frame or a capture (or a probe's draws, or a compiling band),
 *   `y` rows of `height` done (the last band too); now and then with a bitmap of a progressive
 *   frame as far as it got
 */

/**
 * A message on the wire.
 * @typedef {{kind: 'request', id: number, type: keyof Requests, params: any}
 *   | {kind: 'command', type: keyof Commands, params: any}
 *   | {kind: 'event', type: keyof Events, params: any}
 *   | {kind: 'reply', id: number, result?: any, error?: WireError}} Message
 */

/** An error as it crosses: enough to make it again on the other side. @typedef {{name: string, message: string, report?: string, messages?: any[]}} WireError */

/** @param {any} error @returns {WireError} */
function toWire(error) {
  return { name: error?.name ?? 'Error', message: error?.message ?? String(error), report: error?.report, messages: error?.messages };
}

/** The error a reply carries, as it was thrown. @param {WireError} wire @returns {Error} */
export function fromWire(wire) {
  if (wire.messages) return new ShaderCompileError(wire.report, wire.messages);
  if (wire.name === 'WebGL2UnavailableError') return new WebGL2UnavailableError();
  return new Error(wire.message);
}

/**
 * What in a message's parameters moves to the other side instead of being copied: bitmaps and
 * the buffers of typed arrays, at the top level of `params`.
 * @param {unknown} params
 * @returns {Transferable[]}
 */
export function transferables(params) {
  const values = ArrayBuffer.isView(params) ? [params] : params && typeof params === 'object' ? Object.values(params) : [];
  /** @type {Set<Transferable>} */
  const out = new Set();
  for (const value of values) {
    if (typeof ImageBitmap !== 'undefined' && value instanceof ImageBitmap) out.add(value);
    else if (ArrayBuffer.isView(value) && value.byteLength && value.buffer instanceof ArrayBuffer) out.add(value.buffer);
  }
  return [...out];
}

/**
 * The worker's side: answers requests with `requests` (a result or a promise of one), carries
 * out `commands`, and returns how to send events.
 * @param {{postMessage: (message: Message, transfer: Transferable[]) => void, onmessage: any}} scope the worker's global scope
 * @param {{[K in keyof Requests]: (params: Requests[K][0]) => Requests[K][1] | Promise<Requests[K][1]>}} requests
 * @param {{[K in keyof Commands]: (params: Commands[K]) => void}} commands
 */
export function serve(scope, requests, commands) {
  scope.onmessage = async ({ data }) => {
    const message = /** @type {Message} */ (data);
    if (message.kind === 'command') {
      const command = commands[message.type];
      if (!command) throw new Error(`render worker: no command ${message.type}`);
      command(message.params);
      return;
    }
    if (message.kind !== 'request') throw new Error(`render worker: a ${message.kind} message from the page`);
    const request = /** @type {(params: any) => any} */ (requests[message.type]);
    try {
      if (!request) throw new Error(`render worker: no request ${message.type}`);
      const result = await request(message.params);
      scope.postMessage({ kind: 'reply', id: message.id, result }, transferables(result));
    } catch (error) {
      scope.postMessage({ kind: 'reply', id: message.id, error: toWire(error) }, []);
    }
  };
  /**
   * Sends an event to the page.
   * @template {keyof Events} K
   * @param {K} type
   * @param {Events[K]} params
   */
  return (type, params) => scope.postMessage({ kind: 'event', type, params }, transferables(params));
}
