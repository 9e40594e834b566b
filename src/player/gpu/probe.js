// The pixel inspector's GPU work, in the render worker (bands/band-scheduler.js runs it as a job between
// frames, so the buffers hold a whole frame): one pixel of the last frame drawn again, read in
// float before the 8-bit rounding, with the value of every buffer there; and, for a shader whose
// path probe the studio plugs in, that probe, a compile of the same file that writes the path of
// the pixel's ray into a float target. What the path probe writes, and how wide, is the page's
// to know (inspect/probe-program.js sends the width with the compile; inspect/inspector.js reads
// the records): the worker draws and reads, and imports nothing of the shader's side.
//
// The Image pass is drawn again with the material on screen, over the 2×2 quad of the pixel only
// (scissored: the quad is the one the frame drew, so screen-space derivatives, which the adaptive
// anti-aliasing reads, are the frame's) into an RGBA32F target with the frame's viewport:
// gl_FragCoord is a window coordinate, so the target reaches at least as far as the quad (it
// grows, in steps, as far as the pixels probed). Its colour is the shader's, unclamped, with the
// alpha the Image pass forces to 1.

import * as THREE from 'three';

/** @typedef {import('./pass-compiler.js').Step} Step */
/** @typedef {import('./renderer.js').ShaderRenderer} ShaderRenderer */

/** The float image target grows in steps of this many pixels a side. */
const GROWTH = 256;

/** @param {number} width @param {number} height */
function floatTarget(width, height) {
  return new THREE.WebGLRenderTarget(width, height, {
    type: THREE.FloatType,
    format: THREE.RGBAFormat,
    minFilter: THREE.NearestFilter,
    magFilter: THREE.NearestFilter,
    generateMipmaps: false,
    depthBuffer: false,
    stencilBuffer: false,
  });
}

/**
 * What a probe read at one pixel of the last frame.
 * @typedef {object} ProbeResult
 * @property {number[]} image the Image pass's colour there, RGBA32F (alpha as the pass writes it: 1)
 * @property {number[]} canvas the frame's RGBA8 bytes there, as the canvas shows them
 * @property {Record<string, number[]>} buffers each buffer's RGBA32F value there, by name ('A' … 'D')
 * @property {number[] | null} path what the path probe wrote (path-probe.js: readPath), null without one
 * @property {number[] | null} shown the pixel's RGBA8 in the shader's own view of the pixels with
 *   extra samples (the path probe's mode 1: extra-samples.js edgeKind reads it), null without a probe
 * @property {string | null} probeKey which path probe answered (the key it was compiled with)
 */

export class PixelProbe {
  /** @param {ShaderRenderer} renderer */
  constructor(renderer) {
    this.renderer = renderer;
    /** The probe's own uniforms (path-probe.js's prelude), in the path probe's material only. */
    this.uniforms = { probePixel: { value: [0, 0] }, probeOrigin: { value: [0, 0] }, probeMode: { value: 0 } };
    /** The path probe, compiled (an Image-pass step that is never shown); null while none is. @type {Step | null} */
    this.step = null;
    /** What the page compiled the path probe from (it compiles again when that changes). @type {string | null} */
    this.key = null;
    /** The width of the path probe's records, in texels (its compile says). */
    this.texels = 1;
    /** @type {THREE.WebGLRenderTarget | null} */
    this._image = null;
    this._records = floatTarget(this.texels, 1);
    this._quad = floatTarget(2, 2);
  }

  /** Whether `material` is the path probe's (the pass compiler never disposes it then). @param {THREE.Material} material */
  uses(material) {
    return this.step?.material === material;
  }

  /**
   * Compiles the path probe (an Image pass, never drawn on screen); the previous one stays until
   * this one has compiled. Rejects with a ShaderCompileError.
   * @param {import('../../shadertoy/multipass.js').MultipassShader} project
   * @param {string} hostBlock
   * @param {string} fileName
   * @param {string} key
   * @param {number} texels the width of what its mode 0 writes (path-probe.js PROBE_TEXELS)
   */
  async compile(project, hostBlock, fileName, key, texels) {
    const renderer = this.renderer;
    const steps = await renderer.compiler.compileSteps(project, hostBlock, fileName, () => ({
      ...renderer.passUniforms(),
      ...this.uniforms,
    }));
    this.step = steps[steps.length - 1];
    this.key = key;
    if (texels !== this.texels) {
      this._records.dispose();
      this._records = floatTarget(texels, 1);
      this.texels = texels;
    }
  }

  /** The context was restored: the probe's program and targets died with it. */
  forget() {
    this.step = null;
    this.key = null;
    this._image = null;
    this._records = floatTarget(this.texels, 1);
    this._quad = floatTarget(2, 2);
  }

  /**
   * Sets the path probe up to draw the shader's own mainImage (in its "Extra samples" view: the
   * pixels with extra samples) at gl_FragCoord + (x, y), and returns its step.
   * @param {number} x
   * @param {number} y
   */
  mainImageAt(x, y) {
    if (!this.step) throw new Error('the path probe has not compiled');
    this.uniforms.probeMode.value = 1;
    this.uniforms.probeOrigin.value = [x, y];
    return this.step;
  }

  /**
   * Draws what read() reads at pixel (x, y) (y from the bottom) of a frame of width × height; the
   * caller has written the frame's uniforms.
   * @param {number} x
   * @param {number} y
   * @param {number} width
   * @param {number} height
   * @param {boolean} [withPath] the path probe too, if it has compiled (else the colours only)
   */
  draw(x, y, width, height, withPath = true) {
    const renderer = this.renderer;
    const [qx, qy] = [x - (x % 2), y - (y % 2)];
    const image = this._imageTarget(Math.min(qx + 2, width), Math.min(qy + 2, height), width, height);
    image.viewport.set(0, 0, width, height);
    renderer.beginStep(renderer.steps[renderer.steps.length - 1], width, height);
    renderer.drawRegion(image, qx, qy, Math.min(2, width - qx), Math.min(2, height - qy));
    if (!this.step || !withPath) return;
    this.uniforms.probeMode.value = 0;
    this.uniforms.probePixel.value = [x, y];
    renderer.beginStep(this.step, width, height);
    renderer.drawRegion(this._records, 0, 0, this.texels, 1);
    renderer.beginStep(this.mainImageAt(qx, qy), width, height);
    renderer.drawRegion(this._quad, 0, 0, 2, 2);
  }

  /**
   * Reads what draw() drew, once the GPU has finished it.
   * @param {number} x
   * @param {number} y
   * @param {boolean} [withPath] as draw() was given it
   * @returns {ProbeResult}
   */
  read(x, y, withPath = true) {
    const renderer = this.renderer;
    const three = renderer.three;
    const floats = (target, px, py, w = 1) => {
      const out = new Float32Array(4 * w);
      three.readRenderTargetPixels(target, px, py, w, 1, out);
      return [...out];
    };
    const canvas = [...renderer.readTarget(renderer.frameTarget, x, y, 1, 1)];
    /** @type {Record<string, number[]>} */
    const buffers = {};
    for (const name of renderer.buffers.names()) buffers[name] = floats(renderer.buffers.lastWritten(name), x, y);
    const image = floats(this._image, x, y);
    if (!this.step || !withPath) return { image, canvas, buffers, path: null, shown: null, probeKey: null };
    const shown = floats(this._quad, x % 2, y % 2).map((v) => Math.round(Math.min(Math.max(v, 0), 1) * 255));
    return { image, canvas, buffers, path: floats(this._records, 0, 0, this.texels), shown, probeKey: this.key };
  }

  /** An RGBA32F target at least needWidth × needHeight (the frame's size at most), made or grown. */
  _imageTarget(needWidth, needHeight, width, height) {
    const old = this._image;
    if (old && old.width >= needWidth && old.height >= needHeight) return old;
    const grow = (need, have, most) => Math.max(have, Math.min(most, Math.ceil(need / GROWTH) * GROWTH));
    old?.dispose();
    this._image = floatTarget(grow(needWidth, old?.width ?? 0, width), grow(needHeight, old?.height ?? 0, height));
    return this._image;
  }
}
