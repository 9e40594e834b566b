// The Sound tab on the GPU, in the render worker: compiled with the shader's other passes, and
// drawn a block at a time into a 512 × 512 RGBA8 target that is read back and unpacked into
// 16-bit words (src/shadertoy/sound.js: the site's layout, offsets and packing). The page's
// playback, the command line's WAV, the recorder's Opus track and `test`'s comparison all take
// their samples from here.
//
// A room of its own (src/player/sound/), as inspect/ is: gpu/ and app/ hold twelve modules each
// already, and the sound's worker side and page side belong to one feature.

import * as THREE from 'three';
import { ShaderCompileError } from './errors.js';
import { formatCompileMessages, passCheck } from '../../shadertoy/pass-errors.js';
import { channelTypes, soundPass } from '../../shadertoy/multipass.js';
import { mediaKey } from './channels/channel-bindings.js';
import {
  BLOCK_SAMPLES,
  BLOCK_SIDE,
  SAMPLE_OFFSET_UNIFORM,
  SAMPLE_RATE,
  TIME_OFFSET_UNIFORM,
  composeSoundShader,
  soundBlocks,
  unpackBlock,
} from '../../shadertoy/sound.js';

/** Rendered blocks kept (a block is 1 MiB of words: about 6 s of sound). */
const BLOCKS_KEPT = 8;

export class SoundPass {
  /** @param {import('./renderer.js').ShaderRenderer} renderer */
  constructor(renderer) {
    this.renderer = renderer;
    /** The Sound tab's compiled material, or null for a shader without one. @type {THREE.RawShaderMaterial | null} */
    this.material = null;
    /** @type {THREE.WebGLRenderTarget | null} made on the first block */
    this.target = null;
    this.scene = new THREE.Scene();
    this.mesh = new THREE.Mesh(renderer.mesh.geometry);
    this.mesh.frustumCulled = false;
    this.scene.add(this.mesh);
    /** Blocks drawn since the last compile, by index. @type {Map<number, Uint16Array>} */
    this.blocks = new Map();
    /** iDate of the blocks kept. */
    this.date = [0, 0, 0, 0];
  }

  /**
   * Compiles the Sound tab of `project` (none: nothing to do, and no cost). Rejects with a
   * ShaderCompileError naming the Sound tab's lines; the previous Sound tab stays then.
   * @param {import('../../shadertoy/multipass.js').MultipassShader} project
   * @returns {Promise<THREE.RawShaderMaterial | null>}
   */
  async compile(project) {
    const pass = soundPass(project);
    if (!pass) return null;
    const composed = composeSoundShader(pass.code, { common: project.common, channelTypes: channelTypes(pass) });
    const check = passCheck(project, pass, composed);
    try {
      const material = await this.renderer.compiler.compileOne(composed, check, () => this.uniforms(), 'Sound');
      material.userData.channelTypes = channelTypes(pass); // what each channel is declared: bindMedia
      return material;
    } catch (error) {
      if (!error.messages) throw error;
      // said as the other tabs' errors are: "Sound:3: error: ..." with the line under it (a
      // shader with a Sound tab has two tabs at least: its messages name tabs, never the file)
      throw new ShaderCompileError(formatCompileMessages(error.messages, project, ''), error.messages);
    }
  }

  /** Installs what compile() gave (after the other passes compiled): the blocks drawn before go. */
  install(material) {
    this.material = material;
    this.blocks.clear();
  }

  /** The sound header's uniforms: the offsets, iDate, iSampleRate, black channels. */
  uniforms() {
    const black = this.renderer.black;
    return {
      [TIME_OFFSET_UNIFORM]: { value: 0 },
      [SAMPLE_OFFSET_UNIFORM]: { value: 0 },
      iDate: { value: new THREE.Vector4() },
      iSampleRate: { value: SAMPLE_RATE },
      iChannelTime: { value: [0, 0, 0, 0] },
      iChannelResolution: { value: new Array(12).fill(0) },
      iChannel0: { value: black },
      iChannel1: { value: black },
      iChannel2: { value: black },
      iChannel3: { value: black },
    };
  }

  /**
   * Samples [first, first + count) of the Sound tab as 16-bit words, two a sample (left,
   * right), drawn in the site's whole blocks (so each sample's `time` is the site's to the bit).
   * @param {number} first
   * @param {number} count
   * @param {number[]} date iDate (the site's is the date when the tab compiled)
   * @returns {Uint16Array}
   */
  render(first, count, date) {
    if (!this.material) throw new Error('this shader has no Sound tab');
    if (date.some((v, i) => v !== this.date[i])) {
      this.blocks.clear();
      this.date = [...date];
    }
    const words = new Uint16Array(count * 2);
    for (const index of soundBlocks(first, count)) {
      const block = this._block(index);
      const start = index * BLOCK_SAMPLES;
      const from = Math.max(first, start);
      const to = Math.min(first + count, start + BLOCK_SAMPLES);
      words.set(block.subarray((from - start) * 2, (to - start) * 2), (from - first) * 2);
    }
    return words;
  }

  /**
   * The site's media the Sound tab's channels name (media-textures.js PassMedia, by the pass's
   * name), else black for a 2D channel and nothing for a cube or 3D one (three.js binds an empty
   * texture of the declared type: a 2D texture there would fail the draw).
   * @param {THREE.RawShaderMaterial} material
   */
  _bindMedia(material) {
    const types = material.userData.channelTypes ?? ['2D', '2D', '2D', '2D'];
    const resolution = material.uniforms.iChannelResolution.value;
    for (let i = 0; i < 4; i++) {
      const media = this.renderer.passMedia.textures.get(mediaKey('Sound', i));
      material.uniforms[`iChannel${i}`].value = media?.texture ?? (types[i] === '2D' ? this.renderer.black : null);
      resolution.splice(i * 3, 3, ...(media?.size ?? [0, 0, 0]));
    }
  }

  /** Block `index`, drawn and read back (or kept from before). */
  _block(index) {
    const kept = this.blocks.get(index);
    if (kept) return kept;
    const material = /** @type {THREE.RawShaderMaterial} */ (this.material);
    this.target ??= new THREE.WebGLRenderTarget(BLOCK_SIDE, BLOCK_SIDE, {
      format: THREE.RGBAFormat,
      type: THREE.UnsignedByteType,
      minFilter: THREE.NearestFilter,
      magFilter: THREE.NearestFilter,
      depthBuffer: false,
      generateMipmaps: false,
    });
    const offset = index * BLOCK_SAMPLES;
    material.uniforms[SAMPLE_OFFSET_UNIFORM].value = offset;
    material.uniforms[TIME_OFFSET_UNIFORM].value = offset / SAMPLE_RATE;
    material.uniforms.iDate.value.fromArray(this.date);
    this._bindMedia(material);
    this.mesh.material = material;
    const three = this.renderer.three;
    three.setRenderTarget(this.target);
    const whole = { x: 0, y: 0, width: BLOCK_SIDE, height: BLOCK_SIDE, targetWidth: BLOCK_SIDE, targetHeight: BLOCK_SIDE };
    try {
      this.renderer.loopCuts.around(material, { ...whole, pass: 'Sound', frame: index, samples: offset }, () =>
        three.render(this.scene, this.renderer.camera),
      );
    } finally {
      three.setRenderTarget(null);
    }
    const words = unpackBlock(this.renderer.readTarget(this.target));
    this.renderer.loopCuts.collect(); // what llvmpipe's loop limit cut in the block (loop-cuts.js)
    this.blocks.set(index, words);
    for (const old of this.blocks.keys()) if (this.blocks.size > BLOCKS_KEPT) this.blocks.delete(old);
    return words;
  }
}
