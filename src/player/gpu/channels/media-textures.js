// The site's media in the render worker: a texture, a cubemap or a volume a pass's channel names
// (src/player/inputs/media-library.js fetched and decoded it), made into a three.js texture with
// that channel's own sampler, as the site's player uploads it (src/shadertoy/media.js says how).
// A channel's texture is its own: two passes that read one file with two samplers get two.

import * as THREE from 'three';
import { movingTexture } from './channel-bindings.js';

/**
 * What the page sends for one channel: decoded, rows already in upload order (the page flips
 * images as vflip says: WebGL ignores UNPACK_FLIP_Y_WEBGL for an ImageBitmap).
 * @typedef {{kind: 'texture', image: ImageBitmap, oneChannel: boolean}
 *   | {kind: 'cubemap', faces: ImageBitmap[]}
 *   | {kind: 'volume', volume: import('../../../shadertoy/media.js').Volume}} MediaPayload
 */

/** Filters by the site's names (piLibs.js: NONE nearest, LINEAR, MIPMAP trilinear with mipmaps). */
const FILTERS = {
  nearest: { min: THREE.NearestFilter, mag: THREE.NearestFilter, mipmaps: false },
  linear: { min: THREE.LinearFilter, mag: THREE.LinearFilter, mipmaps: false },
  mipmap: { min: THREE.LinearMipmapLinearFilter, mag: THREE.LinearFilter, mipmaps: true },
};

const VOLUME_FORMATS = /** @type {const} */ ([THREE.RedFormat, THREE.RGFormat, THREE.RGBAFormat, THREE.RGBAFormat]);

/** @typedef {{texture: THREE.Texture, size: [number, number, number]}} ChannelTexture size: its iChannelResolution */

/** The site's media of the shader's channels, by channel-bindings.js mediaKey, as bindChannels reads them. */
export class PassMedia {
  constructor() {
    /** The textures (one map for good: bindChannels's sources hold it). @type {Map<string, ChannelTexture>} */
    this.textures = new Map();
    /** The samplers of the channels that hold a video or music. @type {Map<string, import('../../../shadertoy/multipass.js').Sampler>} */
    this._movingSamplers = new Map();
  }

  /**
   * The shader's media, in place of what was there.
   * @param {import('../protocol.js').Commands['passMedia']} media
   */
  set({ entries, moving }) {
    for (const { texture } of this.textures.values()) {
      texture.dispose();
      // this thread's copies of the images, uploaded already (three.js closes none)
      for (const image of [texture.image].flat()) image?.close?.();
    }
    this.textures.clear();
    for (const { key, payload, sampler } of entries) this.textures.set(key, mediaTexture(payload, sampler));
    this._movingSamplers = new Map(moving.map(({ key, sampler }) => [key, sampler]));
  }

  /**
   * The frames of the videos and music the shader's channels name, for the frame about to be
   * drawn (inputs/media-library.js), each into its channel's texture.
   * @param {Array<{key: string, frame: import('../protocol.js').MediaFrame}>} frames
   */
  setFrames(frames) {
    for (const { key, frame } of frames) {
      const texture = movingTexture(this.textures.get(key)?.texture ?? null, frame, this._movingSamplers.get(key));
      this.textures.set(key, { texture, size: [frame.width, frame.height, 1] });
    }
  }
}

/**
 * A three.js texture of a channel's media, with the channel's sampler.
 * @param {MediaPayload} payload
 * @param {import('../../../shadertoy/multipass.js').Sampler} sampler
 * @returns {ChannelTexture}
 */
function mediaTexture(payload, sampler) {
  /** @type {THREE.Texture} */
  let texture;
  /** @type {[number, number, number]} */
  let size;
  if (payload.kind === 'texture') {
    texture = new THREE.Texture(payload.image);
    if (payload.oneChannel) texture.format = THREE.RedFormat;
    size = [payload.image.width, payload.image.height, 1];
  } else if (payload.kind === 'cubemap') {
    texture = new THREE.CubeTexture(payload.faces);
    size = [payload.faces[0].width, payload.faces[0].height, 1];
  } else {
    const { width, height, depth, channels, format, data } = payload.volume;
    texture = new THREE.Data3DTexture(withAlpha(data, channels), width, height, depth);
    texture.format = VOLUME_FORMATS[channels - 1];
    texture.type = format === 'float' ? THREE.FloatType : THREE.UnsignedByteType;
    texture.unpackAlignment = 1;
    size = [width, height, depth];
  }
  const filter = FILTERS[sampler.filter];
  texture.minFilter = filter.min;
  texture.magFilter = filter.mag;
  texture.generateMipmaps = filter.mipmaps;
  // the site sets no wrap on a cubemap (a cube's faces meet: WebGL 2 samples across their seams)
  const wrap = sampler.wrap === 'repeat' ? THREE.RepeatWrapping : THREE.ClampToEdgeWrapping;
  texture.wrapS = wrap;
  texture.wrapT = wrap;
  if (texture instanceof THREE.Data3DTexture) texture.wrapR = wrap;
  texture.flipY = false;
  texture.premultiplyAlpha = false;
  texture.colorSpace = THREE.NoColorSpace;
  texture.needsUpdate = true;
  return { texture, size };
}

/**
 * Three-channel texels as four, alpha 1: the site uploads RGB8 / RGB32F, which read alpha 1 as
 * these do, and three.js has no RGB format for a 3D texture.
 * @param {Uint8Array | Float32Array} data
 * @param {number} channels
 */
function withAlpha(data, channels) {
  if (channels !== 3) return data;
  const out = new /** @type {any} */ (data.constructor)((data.length / 3) * 4);
  const one = data instanceof Float32Array ? 1 : 255;
  for (let i = 0, j = 0; i < data.length; i += 3, j += 4) {
    out[j] = data[i];
    out[j + 1] = data[i + 1];
    out[j + 2] = data[i + 2];
    out[j + 3] = one;
  }
  return out;
}
