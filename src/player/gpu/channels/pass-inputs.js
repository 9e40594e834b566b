// What the passes read in their channels besides each other's buffers: the images the page puts
// into iChannel0..3, Shadertoy's keyboard texture, the moving channels' textures for the frame
// about to be drawn, and the site's media the passes' own channels name. The renderer holds one
// (renderer.js); channel-bindings.js binds a pass's channels from its `sources`.

import * as THREE from 'three';
import { imageTexture, setMedia } from './channel-bindings.js';
import { PassMedia } from './media-textures.js';

export class PassInputs {
  /**
   * @param {Record<string, {value: any}>} uniforms the uniforms every pass shares (uniforms.js),
   *   whose iChannel0..3 and iChannelResolution the page's images set
   * @param {{buffers: import('./pass-buffers.js').PassBuffers, cube: import('./cube-buffer.js').CubeBuffer}} passes
   */
  constructor(uniforms, { buffers, cube }) {
    this._uniforms = uniforms;
    /** The 1×1 black texture an empty 2D channel reads. @type {THREE.Texture} */
    this.black = uniforms.iChannel0.value;
    /** The textures loaded into iChannel0..3. @type {Array<THREE.Texture | null>} */
    this._channels = [null, null, null, null];
    /** The site's media the passes' channels name (media-textures.js). */
    this.passMedia = new PassMedia();
    /** Shadertoy's keyboard texture: 256 × 3 bytes, nearest (keyboard.js). */
    this._keyboardBytes = new Uint8Array(256 * 3);
    this.keyboard = new THREE.DataTexture(this._keyboardBytes, 256, 3, THREE.RedFormat, THREE.UnsignedByteType);
    this.keyboard.needsUpdate = true;
    /** What passes read in their channels (channel-bindings.js: bindChannels). */
    this.sources = {
      buffers,
      cube,
      keyboard: this.keyboard,
      channels: this._channels,
      black: this.black,
      media: this.passMedia.textures,
    };
  }

  /**
   * Puts an image into iChannel0..3 (null: back to the 1×1 black texture), sampled as Shadertoy
   * samples an image by default (channel-bindings.js: imageTexture).
   * @param {number} index 0..3
   * @param {ImageBitmap|null} image
   */
  setChannel(index, image) {
    this._channels[index]?.dispose();
    const texture = image ? imageTexture(image) : null;
    this._channels[index] = texture;
    this._uniforms[`iChannel${index}`].value = texture ?? this.black;
    const resolution = this._uniforms.iChannelResolution.value;
    resolution.splice(index * 3, 3, image?.width ?? 0, image?.height ?? 0, image ? 1 : 0);
  }

  /**
   * The moving channels' textures for the frame about to be drawn (channel-bindings.js setMedia).
   * @param {Array<import('../protocol.js').MediaFrame | null>} media
   */
  setMedia(media) {
    setMedia(this._channels, this._uniforms, media);
  }

  /** The keyboard texture's bytes for the next frame (Shadertoy's 256 × 3: keyboard.js). @param {Uint8Array} data */
  setKeyboard(data) {
    this._keyboardBytes.set(data); // the texture's own bytes
    this.keyboard.needsUpdate = true;
  }
}
