// The buffers of a multipass shader (Buffer A–D), in the render worker: two float render targets
// each, drawn into in turn, as Shadertoy keeps them (https://www.shadertoy.com/js/effect.js,
// Effect.ResizeBuffers / EffectPass.Paint): a pass draws into the target it did not write last
// and then swaps, so every reader reads the target written last — this frame's output for a pass
// that comes after the buffer's, last frame's for the buffer itself and the passes before it.
//
// RGBA32F, as the site renders its buffers (EXT_color_buffer_float; linear filtering of them
// needs OES_texture_float_linear, which three.js turns on where there is one). A resize keeps
// what the buffers hold, texel for texel, in the lower left of the new size (the site copies its
// old buffers into the new ones); Restart clears them to 0.

import * as THREE from 'three';

/** @typedef {import('../../../shadertoy/multipass.js').Sampler} Sampler */

const FILTERS = {
  nearest: [THREE.NearestFilter, THREE.NearestFilter],
  linear: [THREE.LinearFilter, THREE.LinearFilter],
  mipmap: [THREE.LinearMipmapLinearFilter, THREE.LinearFilter],
};

/**
 * @param {number} width
 * @param {number} height
 * @param {Sampler} sampler
 */
function floatTarget(width, height, sampler) {
  const [minFilter, magFilter] = /** @type {[THREE.MinificationTextureFilter, THREE.MagnificationTextureFilter]} */ (
    FILTERS[sampler.filter] ?? FILTERS.linear
  );
  const wrap = sampler.wrap === 'repeat' ? THREE.RepeatWrapping : THREE.ClampToEdgeWrapping;
  return new THREE.WebGLRenderTarget(width, height, {
    type: THREE.FloatType,
    format: THREE.RGBAFormat,
    minFilter,
    magFilter,
    wrapS: wrap,
    wrapT: wrap,
    generateMipmaps: sampler.filter === 'mipmap',
    depthBuffer: false,
    stencilBuffer: false,
  });
}

/**
 * The buffers a frame's passes write, with the sampler their texture needs: the "mipmap" filter
 * where some reader asks for it (its mipmaps are made after each draw), else nearest.
 * @param {import('../pass-compiler.js').Step[]} steps
 * @returns {Map<string, Sampler>}
 */
export function buffersWanted(steps) {
  const wanted = new Map();
  for (const step of steps)
    if (step.target !== 'screen' && step.target !== 'cube') wanted.set(step.target, { filter: 'nearest', wrap: 'clamp', vflip: false });
  for (const step of steps)
    for (const binding of step.bindings)
      if (binding.source === 'buffer' && binding.sampler?.filter === 'mipmap')
        wanted.set(binding.buffer, { filter: 'mipmap', wrap: 'clamp', vflip: false });
  return wanted;
}

export class PassBuffers {
  /**
   * @param {THREE.WebGLRenderer} three
   * @param {(source: THREE.Texture, target: THREE.WebGLRenderTarget, width: number, height: number) => void} copy
   *   draws `source` into `target`, texel for texel, over width × height from the lower left
   */
  constructor(three, copy) {
    this.three = three;
    this.copy = copy;
    /** @type {Map<string, {targets: THREE.WebGLRenderTarget[], written: number, sampler: Sampler}>} */
    this.buffers = new Map();
    this.width = 1;
    this.height = 1;
  }

  /**
   * The buffers a shader uses (each channel reading one is sampled as it asks through a sampler
   * object: renderer.js; the texture's own sampler matters only for its mipmaps, made when some
   * reader asks for the mipmap filter). A buffer that is new, or whose mipmaps came or went,
   * starts cleared; the others keep what they hold.
   * @param {Map<string, Sampler>} wanted by buffer name
   */
  use(wanted) {
    for (const [name, buffer] of this.buffers) {
      const sampler = wanted.get(name);
      if (sampler && JSON.stringify(sampler) === JSON.stringify(buffer.sampler)) continue;
      for (const target of buffer.targets) target.dispose();
      this.buffers.delete(name);
    }
    for (const [name, sampler] of wanted) {
      if (this.buffers.has(name)) continue;
      const targets = [floatTarget(this.width, this.height, sampler), floatTarget(this.width, this.height, sampler)];
      this.buffers.set(name, { targets, written: 0, sampler });
      for (const target of targets) this._clear(target);
    }
  }

  /** The texture a pass reads for `name`: the one written last. @param {string} name */
  read(name) {
    const buffer = this.buffers.get(name);
    return buffer ? buffer.targets[buffer.written].texture : null;
  }

  /** The buffers in use, by name ('A' … 'D'). */
  names() {
    return [...this.buffers.keys()];
  }

  /** The target of `name` written last (what its readers read). @param {string} name */
  lastWritten(name) {
    const buffer = /** @type {{targets: THREE.WebGLRenderTarget[], written: number}} */ (this.buffers.get(name));
    return buffer.targets[buffer.written];
  }

  /** The target a pass of `name` draws into: the one not written last. @param {string} name */
  writeTarget(name) {
    const buffer = /** @type {{targets: THREE.WebGLRenderTarget[], written: number}} */ (this.buffers.get(name));
    return buffer.targets[1 - buffer.written];
  }

  /** The pass of `name` has drawn all of its rows. @param {string} name */
  swap(name) {
    const buffer = this.buffers.get(name);
    if (buffer) buffer.written = 1 - buffer.written;
  }

  /** Every buffer to 0 (Restart). */
  clear() {
    for (const buffer of this.buffers.values()) for (const target of buffer.targets) this._clear(target);
  }

  /**
   * A new size: new targets holding the old ones' texels in their lower left (the rest 0).
   * @param {number} width
   * @param {number} height
   */
  resize(width, height) {
    if (width === this.width && height === this.height) return;
    const keep = { width: Math.min(width, this.width), height: Math.min(height, this.height) };
    this.width = width;
    this.height = height;
    for (const buffer of this.buffers.values()) {
      const old = buffer.targets[buffer.written];
      const fresh = [floatTarget(width, height, buffer.sampler), floatTarget(width, height, buffer.sampler)];
      for (const target of fresh) this._clear(target);
      this.copy(old.texture, fresh[0], keep.width, keep.height);
      for (const target of buffer.targets) target.dispose();
      buffer.targets = fresh;
      buffer.written = 0;
    }
  }

  /** @param {THREE.WebGLRenderTarget} target */
  _clear(target) {
    const three = this.three;
    target.scissorTest = false; // a clear goes through the target's scissor: the last band's rows (cube-buffer.js clear)
    three.setRenderTarget(target);
    three.setClearColor(0x000000, 0);
    three.clear(true, false, false);
    three.setRenderTarget(null);
  }

  dispose() {
    for (const buffer of this.buffers.values()) for (const target of buffer.targets) target.dispose();
    this.buffers.clear();
  }
}
