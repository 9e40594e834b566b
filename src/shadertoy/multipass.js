// A multipass Shadertoy shader as data: the Common tab, Buffers A–D and the Image tab, each
// pass's four channels, and the schedule a renderer follows every frame. Pure: no WebGL here.
// The site's JSON format is read and written by multipass-json.js.
//
// How the site runs the passes (its own player, https://www.shadertoy.com/js/effect.js, read in
// Effect.prototype.Paint, EffectPass.prototype.Paint and Effect.prototype.ResizeBuffer):
// - every frame the buffer passes paint first, then the Cube A pass (cube-a.js), then the Image
//   pass (the Common tab is not a pass:
//   its text is prepended to every other pass's code, EffectPass.NewShader; the site also
//   compiles it alone with only iDate and iSampleRate declared, to report its errors:
//   composeCommonShader in header.js);
// - each buffer is two RGBA32F textures (TEXFMT.C4F32, created nearest/clamp) used in turn: a
//   pass renders into the one it did not render last, then flips `mLastRenderDone`; every input
//   reads `mTexture[mLastRenderDone]`. So a pass reading itself sees its previous frame, a pass
//   reading a buffer that has already painted this frame sees this frame's result, and one
//   reading a buffer that paints later sees last frame's;
// - on the first frame (Effect.mFrame == 0, also after Restart, Effect.ResetTime) both textures
//   of every buffer are cleared to vec4(0);
// - on a resize both textures are re-created at the new size and the old content copied texel
//   for texel into the lower-left min(old, new) rectangle (the rest is zero); no clear, and
//   iFrame goes on counting (the site also resets which texture counts as the last written, so
//   a pass reading itself may see a frame one older once after a resize: a quirk not copied);
// - a buffer's iChannelResolution is (width, height, 1) of the canvas; the keyboard's (256, 3, 1);
// - vertical flip is not offered for buffer and keyboard inputs (EffectPass.GetAcceptsVFlip),
//   only for textures (applied when the image is uploaded); a buffer read with the "mipmap"
//   filter gets its mipmaps regenerated after it paints.

import { CUBE_A_SIZE } from './cube-a.js';

/** The four buffers, in the order they paint. */
export const BUFFER_NAMES = Object.freeze(/** @type {const} */ (['A', 'B', 'C', 'D']));

/**
 * @typedef {'A' | 'B' | 'C' | 'D'} BufferName
 * @typedef {{filter: 'nearest' | 'linear' | 'mipmap', wrap: 'clamp' | 'repeat', vflip: boolean}} Sampler
 * @typedef {{kind: 'buffer', buffer: BufferName, sampler: Sampler, extra?: Record<string, any>}} BufferChannel
 * @typedef {{kind: 'keyboard', sampler: Sampler, extra?: Record<string, any>}} KeyboardChannel
 * @typedef {{kind: 'cubebuffer', sampler: Sampler, extra?: Record<string, any>}} CubeBufferChannel the
 *   Cube A pass's cube map (in the site's JSON an input of type "cubemap" with Cube A's id)
 * @typedef {{kind: 'texture' | 'cubemap' | 'volume' | 'video' | 'webcam' | 'music' | 'musicstream' | 'mic', src: string,
 *   supported: false, sampler: Sampler, extra?: Record<string, any>}} MediaChannel media the page cannot
 *   have: the renderer binds a black texture (of the sampler type the kind needs) and shows a note
 * @typedef {BufferChannel | KeyboardChannel | CubeBufferChannel | MediaChannel} Channel
 * @typedef {{name: string, code: string, channels: Array<Channel | null>, extra?: Record<string, any>}
 *   & ({kind: 'buffer', buffer: BufferName} | {kind: 'image' | 'sound' | 'cubemap', buffer: null})} Pass four channels, null = nothing bound;
 *   a buffer pass writes its buffer, the Image pass none; the Cube A pass (kind 'cubemap', at
 *   most one, named "Cube A") its cube map; the Sound tab (kind 'sound', at most one) is no part
 *   of a frame: sound.js renders it
 * @typedef {Pass & {kind: 'image' | 'buffer' | 'cubemap'}} FramePass a pass drawn every frame (not the Sound tab)
 * @typedef {{common: string | null, passes: Pass[], extra?: Record<string, any>}} MultipassShader
 */

/** The sampler a new channel gets on the site for a buffer input (the site's own exports). */
export const DEFAULT_SAMPLER = Object.freeze({ filter: 'linear', wrap: 'clamp', vflip: true });

/** The tab name of a buffer pass, as the site shows it. */
export const bufferPassName = (/** @type {BufferName} */ buffer) => `Buffer ${buffer}`;

/**
 * A model of a plain single-pass shader: its text is the Image tab.
 * @param {string} code
 * @returns {MultipassShader}
 */
export function singlePass(code) {
  return { common: null, passes: [{ name: 'Image', kind: 'image', buffer: null, code, channels: [null, null, null, null] }] };
}

/** Thrown for a shader model or JSON the page cannot run; the message names the pass. */
export class MultipassError extends Error {
  constructor(message) {
    super(message);
    this.name = 'MultipassError';
  }
}

const FILTERS = ['nearest', 'linear', 'mipmap'];
const WRAPS = ['clamp', 'repeat'];
const MEDIA_KINDS = ['texture', 'cubemap', 'volume', 'video', 'webcam', 'music', 'musicstream', 'mic'];

/**
 * Checks a model: one Image pass, at most one pass per buffer, four channels each, channels of
 * known kinds and samplers (a channel may read a buffer no pass writes: black, as on the site,
 * and said: frameSchedule). Throws a MultipassError naming the pass; returns the model.
 * @param {MultipassShader} model
 */
export function validateModel(model) {
  if (!model || !Array.isArray(model.passes)) throw new MultipassError('a multipass shader needs a list of passes');
  if (model.common !== null && typeof model.common !== 'string') throw new MultipassError('Common: its code is not text');
  const images = model.passes.filter((p) => p.kind === 'image');
  if (images.length !== 1) throw new MultipassError(`a shader needs exactly one Image pass, this one has ${images.length}`);
  const seen = new Set();
  for (const pass of model.passes) {
    const where = pass.name || '(unnamed pass)';
    // as a file may have them: what the checks are for
    const { kind, buffer } = /** @type {{kind: string, buffer: string | null}} */ (pass);
    if (kind !== 'image' && kind !== 'buffer' && kind !== 'sound' && kind !== 'cubemap')
      throw new MultipassError(`${where}: unknown pass kind ${JSON.stringify(kind)}`);
    if (kind === 'sound' && (seen.has('sound') || buffer !== null))
      throw new MultipassError(`${where}: a shader has one Sound tab, which writes no buffer`);
    if (kind === 'cubemap' && (seen.has('cubemap') || buffer !== null))
      throw new MultipassError(`${where}: a shader has one Cube A pass, which writes no buffer A–D`);
    if (kind === 'sound' || kind === 'cubemap') seen.add(kind);
    if (typeof pass.code !== 'string') throw new MultipassError(`${where}: its code is not text`);
    if (pass.kind === 'buffer') {
      if (!BUFFER_NAMES.includes(pass.buffer)) throw new MultipassError(`${where}: writes no buffer A–D (${JSON.stringify(pass.buffer)})`);
      if (seen.has(pass.buffer)) throw new MultipassError(`${where}: Buffer ${pass.buffer} is written by two passes`);
      seen.add(pass.buffer);
    } else if (kind === 'image' && buffer !== null) {
      throw new MultipassError(`${where}: the Image pass writes the screen, not Buffer ${buffer}`);
    }
    if (!Array.isArray(pass.channels) || pass.channels.length !== 4) throw new MultipassError(`${where}: needs exactly four channels`);
    pass.channels.forEach((channel, i) => {
      if (channel === null) return;
      const at = `${where}, iChannel${i}`;
      if (!FILTERS.includes(channel.sampler?.filter)) throw new MultipassError(`${at}: filter must be one of ${FILTERS.join(', ')}`);
      if (!WRAPS.includes(channel.sampler.wrap)) throw new MultipassError(`${at}: wrap must be clamp or repeat`);
      if (typeof channel.sampler.vflip !== 'boolean') throw new MultipassError(`${at}: vflip must be true or false`);
      if (channel.kind === 'buffer' && !BUFFER_NAMES.includes(channel.buffer))
        throw new MultipassError(`${at}: no buffer ${JSON.stringify(channel.buffer)}`);
      if (!['buffer', 'keyboard', 'cubebuffer'].includes(channel.kind) && !MEDIA_KINDS.includes(channel.kind)) {
        throw new MultipassError(`${at}: unknown input kind ${JSON.stringify(channel.kind)}`);
      }
    });
  }
  return model;
}

/**
 * The Sound tab's pass, or null when the shader has none.
 * @param {MultipassShader} model
 */
export const soundPass = (model) => model.passes.find((p) => p.kind === 'sound') ?? null;

/**
 * The Cube A pass, or null when the shader has none.
 * @param {MultipassShader} model
 */
const cubemapPass = (model) => model.passes.find((p) => p.kind === 'cubemap') ?? null;

/**
 * The passes in the order they paint every frame: the buffers A, B, C, D (those present), the
 * Cube A pass, then Image. (The site paints the buffer passes in the order of its pass list,
 * Effect.Paint; A–D is the order its editor adds them in and the order this project fixes. Then
 * every "cubemap" pass, then "image".)
 * @param {MultipassShader} model
 * @returns {FramePass[]}
 */
export function renderOrder(model) {
  const buffers = BUFFER_NAMES.map((b) => model.passes.find((p) => p.kind === 'buffer' && p.buffer === b)).filter((p) => p !== undefined);
  const image = model.passes.find((p) => p.kind === 'image');
  if (!image) throw new MultipassError('a shader needs exactly one Image pass, this one has 0');
  const cube = cubemapPass(model);
  return /** @type {FramePass[]} */ ([...buffers, ...(cube ? [cube] : []), image]);
}

/**
 * What one channel of one pass reads in a frame. `source` is 'black' for media the page cannot
 * have. For a buffer, `frame` is the texture written this frame before this pass ('current') or
 * the one from last frame ('previous': the pass itself, or a buffer that paints after it).
 * @typedef {ChannelBindingBase & ({source: 'buffer', buffer: BufferName, frame: 'current' | 'previous', sampler: Sampler}
 *   | {source: 'cubebuffer', buffer?: undefined, frame: 'current' | 'previous', sampler: Sampler}
 *   | {source: 'keyboard' | 'black', buffer?: undefined, frame?: undefined, sampler: Sampler}
 *   | {source: 'none', buffer?: undefined, frame?: undefined, sampler?: undefined})} ChannelBinding
 */

/**
 * @typedef {object} ChannelBindingBase
 * @property {number} channel 0..3
 * @property {'2D' | 'Cube' | '3D'} samplerType the GLSL sampler the header declares
 * @property {[number, number, number] | 'canvas'} resolution iChannelResolution: 'canvas' for a
 *   buffer ((width, height, 1) of the canvas), (256, 3, 1) for the keyboard, (1024, 1024, 1) for
 *   Cube A (EffectPass.Paint_Image: its mResolution), 0 for nothing; a
 *   black stand-in texture is (1, 1, 1)
 * @property {string} [note] why a channel is black
 */

/**
 * The schedule: for each pass in render order, what each of its channels reads. A renderer
 * follows it literally: render `pass` into its buffer's texture not written last (or the canvas
 * for Image, the six faces of the cube map for Cube A), with channel i bound to `bindings[i]`;
 * after a buffer or Cube A pass, swap its textures.
 * @param {MultipassShader} model
 * @returns {Array<{pass: FramePass, target: BufferName | 'cube' | 'screen', bindings: ChannelBinding[]}>}
 */
export function frameSchedule(model) {
  const order = renderOrder(model);
  // where in the order buffer b is written (-1: no pass writes it)
  const written = (/** @type {BufferName} */ b) => order.findIndex((p) => p.buffer === b);
  const cubeAt = order.findIndex((p) => p.kind === 'cubemap');
  return order.map((pass, index) => ({
    pass,
    target: pass.kind === 'buffer' ? pass.buffer : pass.kind === 'cubemap' ? 'cube' : 'screen',
    bindings: pass.channels.map((channel, i) => {
      /** @type {ChannelBinding} */
      if (channel === null) return { channel: i, source: 'none', samplerType: '2D', resolution: [0, 0, 0] };
      // a buffer or Cube A no pass writes: the site binds its texture all the same, never drawn
      // into (effect.js creates the four buffers and the cube map up front): black, and said here
      const unwritten =
        (channel.kind === 'buffer' && written(channel.buffer) < 0) || (channel.kind === 'cubebuffer' && cubeAt < 0)
          ? `${pass.name}, iChannel${i}: reads ${channel.kind === 'buffer' ? `Buffer ${channel.buffer}` : 'Cube A'}, which no pass writes; the channel is black, as on the site`
          : null;
      if (unwritten)
        return {
          channel: i,
          source: 'black',
          samplerType: samplerTypeOf(channel),
          sampler: { ...channel.sampler, vflip: false },
          // the site resizes all four buffers with the canvas (Effect.ResizeBuffers), Cube A only with its pass
          resolution: channel.kind === 'buffer' ? 'canvas' : [0, 0, 0],
          note: unwritten,
        };
      if (channel.kind === 'buffer') {
        const at = written(channel.buffer);
        const earlier = at >= 0 && at < index;
        return {
          channel: i,
          source: 'buffer',
          buffer: channel.buffer,
          frame: earlier ? 'current' : 'previous',
          samplerType: '2D',
          sampler: { ...channel.sampler, vflip: false },
          resolution: 'canvas',
        };
      }
      if (channel.kind === 'cubebuffer') {
        return {
          channel: i,
          source: 'cubebuffer',
          frame: cubeAt >= 0 && cubeAt < index ? 'current' : 'previous',
          samplerType: 'Cube',
          sampler: { ...channel.sampler, vflip: false },
          resolution: [CUBE_A_SIZE, CUBE_A_SIZE, 1],
        };
      }
      if (channel.kind === 'keyboard') {
        return {
          channel: i,
          source: 'keyboard',
          samplerType: '2D',
          sampler: { filter: 'nearest', wrap: 'clamp', vflip: false },
          resolution: [256, 3, 1],
        };
      }
      return {
        channel: i,
        source: 'black',
        samplerType: samplerTypeOf(channel),
        sampler: channel.sampler,
        resolution: [1, 1, 1],
        note: unsupportedNote(pass.name, i, channel),
      };
    }),
  }));
}

/**
 * The buffers some pass reads with the "mipmap" filter: the renderer regenerates their mipmaps
 * after they paint (Effect.Paint's `needMipMaps`). RGBA32F is filterable (linear, mipmap) only
 * where the context offers OES_texture_float_linear.
 * @param {MultipassShader} model
 * @returns {Set<BufferName>}
 */
export function buffersNeedingMipmaps(model) {
  const out = new Set();
  for (const pass of model.passes)
    for (const c of pass.channels) if (c?.kind === 'buffer' && c.sampler.filter === 'mipmap') out.add(c.buffer);
  return out;
}

/**
 * The GLSL sampler type the site declares for a channel (EffectPass.MakeHeader_*: samplerCube
 * for a cubemap input, Cube A's included, sampler3D for a volume, sampler2D for everything else
 * and for nothing).
 * @param {Channel | null} channel
 * @returns {'2D' | 'Cube' | '3D'}
 */
function samplerTypeOf(channel) {
  if (channel?.kind === 'cubemap' || channel?.kind === 'cubebuffer') return 'Cube';
  if (channel?.kind === 'volume') return '3D';
  return '2D';
}

/**
 * The sampler types of a pass's four channels, for composePassShader's channelTypes.
 * @param {Pass} pass
 */
export const channelTypes = (pass) => pass.channels.map(samplerTypeOf);

/**
 * The note the page shows for a channel it binds to black.
 * @param {string} passName
 * @param {number} index
 * @param {MediaChannel} channel
 */
export function unsupportedNote(passName, index, channel) {
  const what = channel.kind === 'texture' ? `the site's texture ${channel.src || '(no file)'}` : `a ${channel.kind} input`;
  return `${passName}, iChannel${index}: ${what} is not available here; the channel is black`;
}

/**
 * Whether two models hold the same shader (the round-trip tests use it): a deep comparison.
 * @param {unknown} a
 * @param {unknown} b
 */
export function sameModel(a, b) {
  return JSON.stringify(canonical(a)) === JSON.stringify(canonical(b));
}

function canonical(value) {
  if (Array.isArray(value)) return value.map(canonical);
  if (value && typeof value === 'object') {
    return Object.fromEntries(
      Object.keys(value)
        .filter((k) => value[k] !== undefined)
        .sort()
        .map((k) => [k, canonical(value[k])]),
    );
  }
  return value;
}
