// The Cube A pass's cube map, in the render worker: two half-float cube maps of 1024 × 1024 a
// face, drawn into in turn as the buffers are (pass-buffers.js), and the drawing of the pass
// face by face. The site's own facts are in src/shadertoy/cube-a.js.
//
// The pass is drawn as one tall picture of six faces stacked, 1024 wide and 6 × 1024 high, so the
// render worker cuts it in bands of rows as it cuts every pass (a band never crosses a face: each
// face is a framebuffer of its own, with its own unCorners). The faces keep their texels when the
// canvas is resized (their size is fixed); Restart and a new shader clear them to 0.

import * as THREE from 'three';
import { CUBE_A_SIZE, faceCorners } from '../../../shadertoy/cube-a.js';

/** @typedef {import('../../../shadertoy/multipass.js').Sampler} Sampler */

/** The height of the stacked picture the render worker cuts in bands. */
const STACKED_HEIGHT = 6 * CUBE_A_SIZE;

/**
 * One cube map as Effect.ResizeCubemapBuffer makes it: RGBA16F (TEXFMT.C4F16), linear, clamped;
 * with its mipmap levels when some reader asks for the "mipmap" filter. Those are made once the
 * six faces are drawn (generateMipmaps below), not by three.js after every band.
 * @param {boolean} mipmaps
 */
function cubeTarget(mipmaps) {
  const target = new THREE.WebGLCubeRenderTarget(CUBE_A_SIZE, {
    type: THREE.HalfFloatType,
    format: THREE.RGBAFormat,
    minFilter: mipmaps ? THREE.LinearMipmapLinearFilter : THREE.LinearFilter,
    magFilter: THREE.LinearFilter,
    generateMipmaps: mipmaps,
    depthBuffer: false,
    stencilBuffer: false,
  });
  target.texture.mipmapsAutoUpdate = false;
  return target;
}

export class CubeBuffer {
  /** @param {THREE.WebGLRenderer} three */
  constructor(three) {
    this.three = three;
    /** The two cube maps, or none while the shader has no Cube A pass. @type {THREE.WebGLCubeRenderTarget[]} */
    this.targets = [];
    /** Which of them was drawn last (the one readers read). */
    this.written = 0;
    this.mipmaps = false;
  }

  /**
   * The cube maps a frame's passes need: none without a Cube A pass, with mipmap levels when
   * some reader samples it with the "mipmap" filter. New cube maps start cleared; the same need
   * keeps the ones there (a recompile is not a Restart).
   * @param {import('../pass-compiler.js').Step[]} steps
   */
  use(steps) {
    const present = steps.some((step) => step.target === 'cube');
    const mipmaps = steps.some((step) => step.bindings.some((b) => b.source === 'cubebuffer' && b.sampler.filter === 'mipmap'));
    if (this.targets.length && (!present || mipmaps !== this.mipmaps)) this.dispose();
    if (!present || this.targets.length) return;
    this.mipmaps = mipmaps;
    this.targets = [cubeTarget(mipmaps), cubeTarget(mipmaps)];
    this.written = 0;
    this.clear();
  }

  /** The cube map a reader samples: the one drawn last (none without a Cube A pass). */
  read() {
    return this.targets[this.written]?.texture ?? null;
  }

  /** The cube map the pass draws into: the one not drawn last. */
  writeTarget() {
    return this.targets[1 - this.written];
  }

  /** The pass has drawn all six faces: its readers read them now. */
  swap() {
    if (!this.targets.length) return;
    this.written = 1 - this.written;
    if (this.mipmaps) this._generateMipmaps(this.targets[this.written]);
  }

  /** Both cube maps, every face, to vec4(0) (frame 0: Effect.Paint). */
  clear() {
    const three = this.three;
    three.setClearColor(0x000000, 0);
    for (const target of this.targets) {
      // a clear goes through the target's scissor, which the last band drawn into it left on its
      // rows (renderer.js drawRegion): Restart cleared only those, and the counter went on
      target.scissorTest = false;
      for (let face = 0; face < 6; face++) {
        three.setRenderTarget(target, face);
        three.clear(true, false, false);
      }
      if (this.mipmaps) this._generateMipmaps(target);
    }
    three.setRenderTarget(null);
  }

  /**
   * The picture a pass draws, as the render worker cuts it in bands: the frame's width × height,
   * or the Cube A pass's six faces stacked.
   * @param {import('../pass-compiler.js').Step | undefined} step (none: a band ended after a new
   *   shader with fewer passes came)
   * @param {number} width
   * @param {number} height
   */
  static extent(step, width, height) {
    return step?.target === 'cube' ? { width: CUBE_A_SIZE, height: STACKED_HEIGHT } : { width, height };
  }

  /**
   * Points the pass's material at the face of row y0 of the stacked picture
   * (EffectPass.Paint_Cubemap: unCorners, and the viewport [0, 0, 1024, 1024] as unViewport), and
   * says where rows [y0, y1) land: that face, its rows from the face's bottom, cut at its top.
   * @param {THREE.RawShaderMaterial} material
   * @param {number} y0
   * @param {number} y1
   */
  static aim(material, y0, y1) {
    const face = Math.floor(y0 / CUBE_A_SIZE);
    const y = y0 - face * CUBE_A_SIZE;
    material.uniforms.unCorners.value = faceCorners(face);
    material.uniforms.unViewport.value = [0, 0, CUBE_A_SIZE, CUBE_A_SIZE];
    material.uniformsNeedUpdate = true;
    return { face, y, rows: Math.min(y1 - y0, CUBE_A_SIZE - y) };
  }

  /**
   * The uniforms of the pass's own that the others do not have: unCorners, unViewport, and its
   * iResolution, (1024, 1024, 1) whatever the canvas (EffectPass.Paint passes the cube's size).
   */
  static ownUniforms() {
    return {
      unCorners: { value: faceCorners(0) },
      unViewport: { value: [0, 0, CUBE_A_SIZE, CUBE_A_SIZE] },
      iResolution: { value: [CUBE_A_SIZE, CUBE_A_SIZE, 1] },
    };
  }

  /** @param {THREE.WebGLCubeRenderTarget} target */
  _generateMipmaps(target) {
    const gl = /** @type {WebGL2RenderingContext} */ (this.three.getContext());
    const texture = /** @type {{__webglTexture?: WebGLTexture}} */ (this.three.properties.get(target.texture)).__webglTexture;
    if (!texture) return;
    this.three.state.bindTexture(gl.TEXTURE_CUBE_MAP, texture);
    gl.generateMipmap(gl.TEXTURE_CUBE_MAP);
    this.three.state.unbindTexture();
  }

  dispose() {
    for (const target of this.targets) target.dispose();
    this.targets = [];
  }
}
