// What each pass of a frame reads in iChannel0..3, for the renderer (renderer.js): a buffer, the
// keyboard, an image the page loaded, or black, with its iChannelResolution; and the WebGL
// sampler objects that give a buffer channel its own filter and wrap. Shadertoy sets those per
// channel, while a three.js texture has one of each: two passes, or two channels of one pass, may
// read one buffer differently, so a sampler object bound to the channel's texture unit for the
// pass's draws overrides the texture's own.

import * as THREE from 'three';

/** @typedef {import('../pass-compiler.js').Step} Step */

/**
 * A pass's own channel uniforms (each material has them; the rest of its uniforms are shared).
 * @param {THREE.Texture} black the 1×1 black texture
 */
export function ownChannelUniforms(black) {
  /** The Image pass's struct of a channel (header.js: iCh0 … iCh3); other passes declare none. */
  const struct = () => ({ value: { sampler: black, size: [0, 0, 0], time: 0, loaded: 0 } });
  return {
    iChannel0: { value: black },
    iChannel1: { value: black },
    iChannel2: { value: black },
    iChannel3: { value: black },
    iChannelResolution: { value: new Array(12).fill(0) },
    iChannelTime: { value: [0, 0, 0, 0] },
    iCh0: struct(),
    iCh1: struct(),
    iCh2: struct(),
    iCh3: struct(),
  };
}

/**
 * The key of a pass's channel among the media textures: one per pass and channel.
 * @param {string} passName
 * @param {number} channel
 */
export const mediaKey = (passName, channel) => `${passName}:${channel}`;

/**
 * Binds what a pass reads into its material's channel uniforms, for a frame of width × height.
 * @param {Step} step
 * @param {number} width
 * @param {number} height
 * @param {{buffers: import('./pass-buffers.js').PassBuffers, cube: import('./cube-buffer.js').CubeBuffer, keyboard: THREE.Texture,
 *   channels: Array<THREE.Texture | null>, black: THREE.Texture, media: Map<string, {texture: THREE.Texture, size: [number, number, number]}>}} sources
 *   media: the site's media each pass's channels name, by mediaKey (media-textures.js)
 */
export function bindChannels(step, width, height, sources) {
  const { buffers, cube, keyboard, channels, black } = sources;
  const uniforms = step.material.uniforms;
  const resolution = uniforms.iChannelResolution.value;
  const times = uniforms.iChannelTime.value;
  for (const binding of step.bindings) {
    const i = binding.channel;
    let texture = null;
    times[i] = 0;
    // the site's texIsLoaded (EffectPass.Paint_Image): the channel holds something, a buffer or
    // Cube A no pass writes included (its texture exists, never drawn into); not media this run lacks
    const kind = step.pass.channels[i]?.kind;
    let loaded = kind === 'buffer' || kind === 'cubebuffer' || kind === 'keyboard';
    let size = binding.resolution === 'canvas' ? [width, height, 1] : binding.resolution;
    if (binding.source === 'buffer') texture = buffers.read(/** @type {string} */ (binding.buffer));
    else if (binding.source === 'cubebuffer') texture = cube.read();
    else if (binding.source === 'keyboard') texture = keyboard;
    else if (binding.source === 'black' && sources.media.has(mediaKey(step.pass.name, i))) {
      const media = /** @type {import('./media-textures.js').ChannelTexture} */ (sources.media.get(mediaKey(step.pass.name, i)));
      texture = media.texture;
      size = media.size;
      times[i] = texture.userData.time ?? 0; // a video's or music's iChannelTime
      loaded = true;
    } else if (binding.source === 'none' && step.target === 'screen' && channels[i]) {
      texture = channels[i]; // an image the page put into this channel, or a moving one's frame
      size = [texture.image.width, texture.image.height, 1];
      times[i] = texture.userData.time ?? 0; // a video's or music's iChannelTime (media-input.js)
      loaded = true;
    } else if (binding.samplerType === '2D') texture = black;
    // else null: three.js binds an empty cube or 3D texture for a samplerCube / sampler3D
    uniforms[`iChannel${i}`].value = texture;
    resolution.splice(i * 3, 3, ...size);
    // the Image pass's iCh<i> (header.js): the same texture, iChannelResolution, iChannelTime
    Object.assign(uniforms[`iCh${i}`].value, { sampler: texture, size: [...size], time: times[i], loaded: loaded ? 1 : 0 });
  }
}

/**
 * An image as Shadertoy samples one by default: mipmapped, repeating, uv (0,0) at the image's
 * bottom-left corner, no colour-space conversion. WebGL ignores its flip and premultiply flags
 * for an ImageBitmap, so the page decodes the bitmap with its rows already flipped and alpha not
 * premultiplied (shader-loader.js).
 * @param {ImageBitmap} image
 */
export function imageTexture(image) {
  const texture = new THREE.Texture(image);
  texture.flipY = false;
  texture.premultiplyAlpha = false;
  texture.wrapS = THREE.RepeatWrapping;
  texture.wrapT = THREE.RepeatWrapping;
  texture.minFilter = THREE.LinearMipmapLinearFilter;
  texture.magFilter = THREE.LinearFilter;
  texture.generateMipmaps = true;
  texture.colorSpace = THREE.NoColorSpace;
  texture.needsUpdate = true;
  return texture;
}

/**
 * The site's music and microphone texture (effect.js: CreateTexture 512 × 2, TEXFMT.C1I8, linear,
 * clamped; no mipmaps, no repeat and no flip offered for them, GetAcceptsMipmapping,
 * GetAcceptsWrapRepeat, GetAcceptsVFlip): R8, so .r is the byte / 255, .gba (0, 0, 1).
 */
function audioTexture() {
  const texture = new THREE.DataTexture(new Uint8Array(512 * 2), 512, 2, THREE.RedFormat, THREE.UnsignedByteType);
  texture.minFilter = THREE.LinearFilter;
  texture.magFilter = THREE.LinearFilter;
  texture.wrapS = THREE.ClampToEdgeWrapping;
  texture.wrapT = THREE.ClampToEdgeWrapping;
  texture.generateMipmaps = false;
  texture.unpackAlignment = 1;
  texture.colorSpace = THREE.NoColorSpace;
  texture.needsUpdate = true;
  return texture;
}

/**
 * The moving channels' textures for the frame about to be drawn (FrameInputs.media), into the
 * renderer's channel textures: a video's or the webcam's picture uploaded again (mipmapped and
 * repeating, as an image: imageTexture; its rows flipped by the page), the music's or
 * microphone's 512 × 2 bytes (audioTexture), and each one's iChannelTime, kept on the texture for
 * the passes that read it (bindChannels).
 * @param {Array<THREE.Texture | null>} channels the renderer's channel textures, changed here
 * @param {Record<string, {value: any}>} uniforms the shared uniforms
 * @param {Array<import('../protocol.js').MediaFrame | null>} media
 */
export function setMedia(channels, uniforms, media) {
  media.forEach((frame, index) => {
    if (!frame) return;
    const texture = movingTexture(channels[index], frame);
    if (texture !== channels[index]) {
      channels[index] = texture;
      uniforms[`iChannel${index}`].value = texture;
    }
    uniforms.iChannelResolution.value.splice(index * 3, 3, frame.width, frame.height, 1);
  });
}

/**
 * A moving channel's texture with a frame in it: `texture` itself, or a new one (the old one
 * disposed) when there was none or it held another kind. Its iChannelTime is kept on it
 * (userData.time) for the passes that read it (bindChannels).
 * @param {THREE.Texture | null} texture
 * @param {import('../protocol.js').MediaFrame} frame
 * @param {import('../../../shadertoy/multipass.js').Sampler} [sampler] a channel's own (a shader's
 *   JSON names the file); without: as the site samples an image, and music (audioTexture)
 */
export function movingTexture(texture, frame, sampler) {
  if (!texture || texture.userData.media !== frame.kind) {
    texture?.dispose();
    texture = frame.kind === 'audio' ? audioTexture() : imageTexture(frame.image);
    texture.userData.media = frame.kind;
    if (sampler) {
      const nearest = sampler.filter === 'nearest';
      texture.magFilter = nearest ? THREE.NearestFilter : THREE.LinearFilter;
      texture.minFilter = nearest
        ? THREE.NearestFilter
        : sampler.filter === 'linear' || frame.kind === 'audio'
          ? THREE.LinearFilter
          : THREE.LinearMipmapLinearFilter;
      texture.generateMipmaps = texture.minFilter === THREE.LinearMipmapLinearFilter;
      // music takes no repeat on the site (GetAcceptsWrapRepeat)
      texture.wrapS = texture.wrapT =
        sampler.wrap === 'repeat' && frame.kind !== 'audio' ? THREE.RepeatWrapping : THREE.ClampToEdgeWrapping;
    }
  }
  if (frame.kind === 'audio') texture.image.data.set(frame.bytes);
  else if (texture.image !== frame.image) {
    const old = texture.image;
    texture.image = frame.image;
    old?.close?.(); // this thread's copy of an earlier frame, uploaded already
  }
  texture.needsUpdate = true;
  texture.userData.time = frame.time;
  return texture;
}

/** The sampler objects of the pass being drawn, bound around its draws. */
export class ChannelSamplers {
  /**
   * @param {WebGL2RenderingContext} gl
   * @param {THREE.WebGLRenderer} three
   */
  constructor(gl, three) {
    this.gl = gl;
    this.three = three;
    /** Sampler objects for the pass being drawn, by unit (use). @type {Array<{unit: number, sampler: WebGLSampler}>} */
    this._samplers = [];
    /** @type {Map<string, WebGLSampler>} */
    this._samplerObjects = new Map();
  }

  /** The pass drawn next. @param {Step} step */
  use(step) {
    this._samplers = this._samplersOf(step);
  }

  /** Binds the pass's sampler objects to their units (before its draw). */
  bind() {
    for (const { unit, sampler } of this._samplers) this.gl.bindSampler(unit, sampler);
  }

  /** Unbinds them again: a sampler left on a unit would override every texture drawn there later. */
  unbind() {
    for (const { unit } of this._samplers) this.gl.bindSampler(unit, null);
  }

  /**
   * The WebGL sampler objects a pass's buffer channels are read with, by texture unit. three.js
   * hands out units in the order of the program's active uniforms, samplers only
   * (WebGLUniforms.upload → allocateTextureUnit), so iChannel i's unit is its place among them.
   * @param {Step} step
   * @returns {Array<{unit: number, sampler: WebGLSampler}>}
   */
  _samplersOf(step) {
    const program = /** @type {{currentProgram?: {getUniforms: () => {seq: Array<{id: string, type: number}>}}}} */ (
      this.three.properties.get(step.material)
    ).currentProgram;
    if (!program) return [];
    const gl = this.gl;
    /** @type {number[]} */
    const samplerTypes = [gl.SAMPLER_2D, gl.SAMPLER_CUBE, gl.SAMPLER_3D, gl.SAMPLER_2D_ARRAY, gl.SAMPLER_2D_SHADOW];
    /** The units of each channel's samplers: iChannel i's and, in the Image pass, iCh<i>.sampler's. @type {Map<number, number[]>} */
    const units = new Map();
    let unit = 0;
    /** @param {Array<{id: string | number, type?: number, seq?: any[]}>} seq @param {string} [struct] */
    const visit = (seq, struct) => {
      for (const uniform of seq) {
        // a struct's members take their units in their order, where the struct is (StructuredUniform.setValue)
        if (uniform.seq) visit(uniform.seq, String(uniform.id));
        if (uniform.type === undefined || !samplerTypes.includes(uniform.type)) continue;
        const channel = struct ? /^iCh([0-3])$/.exec(struct) : /^iChannel([0-3])$/.exec(String(uniform.id));
        if (channel) units.set(Number(channel[1]), [...(units.get(Number(channel[1])) ?? []), unit]);
        unit++;
      }
    };
    visit(program.getUniforms().seq);
    return step.bindings
      .filter((binding) => ['buffer', 'keyboard', 'cubebuffer'].includes(binding.source) && binding.sampler && units.has(binding.channel))
      .flatMap((binding) =>
        (units.get(binding.channel) ?? []).map((at) => ({ unit: at, sampler: this._samplerObject(/** @type {any} */ (binding.sampler)) })),
      );
  }

  /** @param {import('../../../shadertoy/multipass.js').Sampler} sampler */
  _samplerObject({ filter, wrap }) {
    const key = `${filter} ${wrap}`;
    let object = this._samplerObjects.get(key);
    if (object) return object;
    const gl = this.gl;
    object = /** @type {WebGLSampler} */ (gl.createSampler());
    const min = { nearest: gl.NEAREST, linear: gl.LINEAR, mipmap: gl.LINEAR_MIPMAP_LINEAR }[filter] ?? gl.LINEAR;
    gl.samplerParameteri(object, gl.TEXTURE_MIN_FILTER, min);
    gl.samplerParameteri(object, gl.TEXTURE_MAG_FILTER, filter === 'nearest' ? gl.NEAREST : gl.LINEAR);
    const mode = wrap === 'repeat' ? gl.REPEAT : gl.CLAMP_TO_EDGE;
    gl.samplerParameteri(object, gl.TEXTURE_WRAP_S, mode);
    gl.samplerParameteri(object, gl.TEXTURE_WRAP_T, mode);
    this._samplerObjects.set(key, object);
    return object;
  }
}
