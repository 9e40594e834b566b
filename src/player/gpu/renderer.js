// Draws a Shadertoy Image pass: one fullscreen triangle with a RawShaderMaterial on a three.js
// WebGLRenderer (WebGL2), inside the render worker (render-worker.js) on an OffscreenCanvas of
// its own. Compiling is done off to the side, so a shader that fails to compile never replaces
// the last one that worked.
//
// Frames are drawn into a render target that keeps them (the frame target), in bands of rows
// (drawRows: one scissored draw each, so a heavy frame is many short draws), and copied to the
// canvas only to be shown (present: the canvas's drawing buffer is handed to the page as an
// ImageBitmap, which leaves the canvas blank).
//
// Compiling every pass, with its errors mapped to the user's lines and the material cache, is
// pass-compiler.js's; what each pass reads in its channels, and the sampler objects it reads
// buffers with, channel-bindings.js's; the page's images, the keyboard and the media,
// pass-inputs.js's; which band is drawn when, bands/band-scheduler.js's.

import * as THREE from 'three';
import { GpuTimer } from './gpu-timer.js';
import { blackTexture, shadertoyUniforms } from './uniforms.js';
import { PassBuffers, buffersWanted } from './channels/pass-buffers.js';
import { CubeBuffer } from './channels/cube-buffer.js';
import { WebGL2UnavailableError } from './errors.js';
import { PassCompiler } from './pass-compiler.js';
import { copyScene, fullscreenTriangle } from './frame-copy.js';
import { PassInputs } from './channels/pass-inputs.js';
import { ChannelSamplers, bindChannels, ownChannelUniforms } from './channels/channel-bindings.js';
import { PixelProbe } from './probe.js';
import { SoundPass } from './sound-pass.js';
import { sendVerbatimSources } from './verbatim-source.js';
import { flipRows } from '../../shared/pixels.js';
import { TILE_OFFSET_UNIFORM } from '../../shadertoy/header.js';
import { LoopCuts } from './loop-cuts.js';

/** @typedef {import('./pass-compiler.js').Step} Step */

export class ShaderRenderer {
  /** @param {OffscreenCanvas} canvas the worker's own canvas */
  constructor(canvas) {
    /** @type {WebGLContextAttributes} */
    const attributes = {
      alpha: false,
      antialias: false,
      depth: false,
      stencil: false,
      preserveDrawingBuffer: false,
      powerPreference: 'high-performance',
    };
    const gl = canvas.getContext('webgl2', attributes);
    if (!gl) throw new WebGL2UnavailableError();
    // each pass's text compiles as composed, not as three.js would rewrite it (verbatim-source.js)
    sendVerbatimSources(gl);
    this.gl = gl;
    /** The GPU time of each frame drawn, where the browser measures it (gpu-timer.js). */
    this.gpuTimer = new GpuTimer(gl);
    this.canvas = canvas;

    this.three = new THREE.WebGLRenderer({ canvas, context: gl, ...attributes });
    this.three.setPixelRatio(1); // we size the drawing buffer in device pixels ourselves
    this.three.autoClear = false; // the triangle covers every pixel

    /** Shadertoy's uniforms plus the live control uniforms; shared by every material we build. */
    this.uniforms = shadertoyUniforms(blackTexture());

    const geometry = fullscreenTriangle();
    this.camera = new THREE.OrthographicCamera(); // required by render(); the shader ignores it
    this.scene = new THREE.Scene();
    // drawn with the material of the pass being drawn (beginStep); until the first, with none:
    // three.js's stand-in MeshBasicMaterial is never drawn (nothing is before a shader compiled)
    this.mesh = new THREE.Mesh(geometry);
    this.mesh.frustumCulled = false;
    this.scene.add(this.mesh);
    /** What llvmpipe's loop limit cut short (loop-cuts.js): on llvmpipe, passes are drawn guarded. */
    this.loopCuts = new LoopCuts(gl);
    /** Compiles the passes (pass-compiler.js); keeps compiled materials, never disposing one on screen. */
    this.compiler = new PassCompiler(
      this.three,
      geometry,
      this.camera,
      (material) =>
        this.steps.some((step) => step.material === material) ||
        this.probe.uses(material) ||
        this.tiledStep?.material === material ||
        this.sound.material === material,
      this.loopCuts,
    );

    /** Where frames are drawn and kept (RGBA8, as the page's canvas): the page shows copies of it. */
    this.frameTarget = this.makeTarget(1, 1);
    const copy = copyScene(geometry, this.frameTarget.texture);
    this.copyScene = copy.scene;
    this._copySource = copy.source;

    /** The passes of a frame, in order, with their compiled materials (the last is Image). @type {Step[]} */
    this.steps = [];
    /** Buffer A–D of a multipass shader. */
    this.buffers = new PassBuffers(this.three, (source, target, width, height) => this._copy(source, target, width, height));
    /** The Cube A pass's cube maps. */
    this.cube = new CubeBuffer(this.three);
    /** The page's images, the keyboard and the media the passes read (pass-inputs.js). */
    this.inputs = new PassInputs(this.uniforms, { buffers: this.buffers, cube: this.cube });
    /** The 1×1 black texture an empty 2D channel reads. */
    this.black = this.inputs.black;
    /** The site's media the passes' channels name (media-textures.js). */
    this.passMedia = this.inputs.passMedia;
    /** The sampler objects of the pass being drawn (channel-bindings.js). */
    this.samplers = new ChannelSamplers(gl, this.three);

    /** Which compile is on screen: the page's number for it (compile()'s `serial`), 0 before any. */
    this.installed = 0;
    /** What the shader on screen was compiled from (for its tiled form). @type {{project: any, hostBlock: string, fileName: string} | null} */
    this._onScreen = null;
    /** Its Image pass as a tile (tiled()), once asked for. @type {Step | null} */
    this.tiledStep = null;
    /** The pixel inspector's reads, and the path probe (probe.js). */
    this.probe = new PixelProbe(this);
    /** The Sound tab (sound-pass.js). */
    this.sound = new SoundPass(this);
    /** The pass beginStep began, by its name ('Image', 'Buffer A', …): what a loop cut is said of. */
    this._passName = 'Image';
  }

  /** True once some shader has compiled (render() draws nothing before). */
  get hasProgram() {
    return this.steps.length > 0;
  }

  /**
   * Compiles every pass of `project` (a Shadertoy shader: Common, buffers, Image) with
   * `hostBlock` between header and Common. Resolves once all are compiled: then they become the
   * drawn shader; if any fails it rejects with a ShaderCompileError naming each message's tab
   * (for a plain file: its lines), and the previous shader stays.
   * @param {import('../../shadertoy/multipass.js').MultipassShader} project
   * @param {string} hostBlock
   * @param {string} [fileName]
   * @param {number} [serial] the page's number for this compile (it grows with each one asked
   *   for): a compile that finishes after a newer one is not drawn
   */
  async compile(project, hostBlock, fileName = 'shader', serial = this.installed + 1) {
    const steps = await this.compiler.compileSteps(project, hostBlock, fileName, () => this.passUniforms());
    if (serial < this.installed) return; // a newer compile got in first
    this.installed = serial;
    this.steps = steps;
    this._onScreen = { project, hostBlock, fileName };
    this.tiledStep = null;
    this.mesh.material = steps[steps.length - 1].material;
    this.buffers.use(buffersWanted(steps));
    this.cube.use(steps);
  }

  /**
   * The Image pass of the shader on screen as a tile of a larger picture (header.js:
   * TILE_OFFSET_UNIFORM), compiled the first time a tile is asked for; rejects for a shader with
   * buffers.
   * @returns {Promise<Step>}
   */
  async tiled() {
    if (this.tiledStep) return this.tiledStep;
    if (!this._onScreen) throw new Error('no shader has compiled');
    const { project, hostBlock, fileName } = this._onScreen;
    const uniforms = () => ({ ...this.passUniforms(), [TILE_OFFSET_UNIFORM]: { value: [0, 0] } });
    const [step] = await this.compiler.compileSteps(project, hostBlock, fileName, uniforms, { tiled: true });
    if (this._onScreen?.project === project && this._onScreen.hostBlock === hostBlock) this.tiledStep = step;
    return step;
  }

  /**
   * A pass's uniforms: Shadertoy's and the controls', shared by every pass (one write reaches them
   * all), but its own channels and their resolutions.
   */
  passUniforms() {
    return { ...this.uniforms, ...ownChannelUniforms(this.black) };
  }

  /**
   * Binds what a pass reads, for a frame of width × height, and returns where it draws: a
   * buffer's target, or null for the Image pass (the caller's target).
   * @param {Step} step
   * @param {number} width
   * @param {number} height
   */
  beginStep(step, width, height) {
    this._passName = step.pass?.name ?? 'Image';
    const uniforms = step.material.uniforms;
    for (const name of Object.keys(this.uniforms)) if (!(name in uniforms)) uniforms[name] = this.uniforms[name]; // controls added later
    bindChannels(step, width, height, this.inputs.sources);
    this.mesh.material = step.material;
    step.material.uniformsNeedUpdate = true; // the same material drawn again may read other textures
    this.samplers.use(step);
    if (step.target === 'cube') return this.cube.writeTarget();
    return step.target === 'screen' ? null : this.buffers.writeTarget(step.target);
  }

  /** A pass has drawn all of its rows. @param {Step} step */
  endStep(step) {
    if (step.target === 'cube') this.cube.swap();
    else if (step.target !== 'screen') this.buffers.swap(step.target);
  }

  /** Forgets the compiled materials but the ones on screen (their programs died with a lost context), and the path probe. */
  forgetCompiled() {
    this.probe.forget();
    this.compiler.forgetCompiled();
  }

  /** True between webglcontextlost and webglcontextrestored. */
  get contextLost() {
    return this.gl.isContextLost();
  }

  /**
   * The largest drawing buffer or render target side this context takes, in device pixels.
   * Zero while the context is lost (the caller keeps its last size then).
   */
  get maxSize() {
    const gl = this.gl;
    if (gl.isContextLost()) return 0;
    const dims = gl.getParameter(gl.MAX_VIEWPORT_DIMS);
    return Math.min(gl.getParameter(gl.MAX_RENDERBUFFER_SIZE), gl.getParameter(gl.MAX_TEXTURE_SIZE), dims[0], dims[1]);
  }

  /**
   * An RGBA8 render target, as the page's canvas: the frame target, and one of its own for a
   * frame drawn at another size (a screenshot, a recording); RGBA32F with `float`.
   * @param {number} width
   * @param {number} height
   * @param {boolean} [float]
   */
  makeTarget(width, height, float = false) {
    const type = float ? THREE.FloatType : THREE.UnsignedByteType;
    return new THREE.WebGLRenderTarget(width, height, { type, depthBuffer: false, stencilBuffer: false, generateMipmaps: false });
  }

  /** Sizes the frame target and the canvas, in device pixels; what is in the target is lost on a change. */
  setSize(width, height) {
    if (this.frameTarget.width === width && this.frameTarget.height === height) return;
    this.frameTarget.setSize(width, height);
    this.three.setSize(width, height, false);
    this.buffers.resize(width, height);
  }

  /**
   * Draws `source` into `target` texel for texel over width × height from the lower left.
   * @param {THREE.Texture} source
   * @param {THREE.WebGLRenderTarget} target
   * @param {number} width
   * @param {number} height
   */
  _copy(source, target, width, height) {
    this._copySource.value = source;
    target.scissor.set(0, 0, width, height);
    target.scissorTest = true;
    this.three.setRenderTarget(target);
    try {
      this.three.render(this.copyScene, this.camera);
    } finally {
      this.three.setRenderTarget(null);
      this._copySource.value = this.frameTarget.texture;
    }
  }

  get width() {
    return this.frameTarget.width;
  }

  get height() {
    return this.frameTarget.height;
  }

  /**
   * Draws rows [y0, y1) of the current shader into `target` (default: the frame target): one
   * draw, scissored to those rows; into a cube map, the rows of the six faces stacked, up to the
   * top of the face of y0. The caller writes the uniforms first.
   * @param {number} y0 first row, from the bottom
   * @param {number} y1 one past the last row
   * @param {THREE.WebGLRenderTarget} [target]
   * @returns {number} the rows drawn (0 before any shader compiled)
   */
  drawRows(y0, y1, target = this.frameTarget) {
    if (!this.hasProgram) return 0;
    if (!(target instanceof THREE.WebGLCubeRenderTarget)) {
      this.drawRegion(target, 0, y0, target.width, y1 - y0);
      return y1 - y0;
    }
    const { face, y, rows } = CubeBuffer.aim(/** @type {THREE.RawShaderMaterial} */ (this.mesh.material), y0, y1);
    this.drawRegion(target, 0, y, target.width, rows, face);
    return rows;
  }

  /**
   * Draws the material of the last beginStep() into `target`, scissored to width × height from
   * (x, y), through the target's viewport. The caller writes the uniforms first.
   * @param {THREE.WebGLRenderTarget} target
   * @param {number} x
   * @param {number} y
   * @param {number} width
   * @param {number} height
   * @param {number} [face] the face of a cube map drawn into
   */
  drawRegion(target, x, y, width, height, face = 0) {
    target.scissor.set(x, y, width, height);
    target.scissorTest = x > 0 || y > 0 || width < target.width || height < target.height;
    this.three.setRenderTarget(target, face);
    this.samplers.bind();
    try {
      const region = { x, y, width, height, targetWidth: target.width, targetHeight: target.height };
      const drawing = { pass: this._passName, frame: this.uniforms.iFrame.value };
      this.loopCuts.around(/** @type {THREE.Material} */ (this.mesh.material), { ...region, ...drawing }, () =>
        this.three.render(this.scene, this.camera),
      );
    } finally {
      this.samplers.unbind(); // a sampler left on a unit would override every texture drawn there later
      this.three.setRenderTarget(null);
    }
  }

  /** Draws the whole frame at once, each pass in one draw (the benchmark's way). */
  render() {
    for (const step of this.steps) {
      const target = this.beginStep(step, this.width, this.height) ?? this.frameTarget;
      const { height } = CubeBuffer.extent(step, this.width, this.height);
      for (let y = 0; y < height;) y += this.drawRows(y, height, target);
      this.endStep(step);
    }
    return this.hasProgram;
  }

  /**
   * The frame target as the page shows it: copied to the canvas, whose drawing buffer is handed
   * over as an ImageBitmap (the canvas starts blank after).
   * @returns {ImageBitmap}
   */
  present() {
    this.three.setRenderTarget(null);
    this.three.render(this.copyScene, this.camera);
    return /** @type {OffscreenCanvas} */ (this.canvas).transferToImageBitmap();
  }

  /**
   * Reads a render target (default: the frame target): RGBA8, rows bottom to top. It waits for
   * the GPU: call it once the draws are done (bands/band-scheduler.js polls a fence first).
   */
  readTarget(target = this.frameTarget, x = 0, y = 0, width = target.width, height = target.height) {
    const pixels = new Uint8Array(width * height * 4);
    this.three.readRenderTargetPixels(target, x, y, width, height, pixels);
    return pixels;
  }

  /**
   * A target's pixels as the page shows them: RGBA8, rows top to bottom, alpha 1 (the page's
   * canvas has none).
   * @param {THREE.WebGLRenderTarget} target
   * @param {number} width
   * @param {number} height
   */
  readOpaque(target, width, height) {
    const pixels = flipRows(this.readTarget(target), width, height);
    for (let i = 3; i < pixels.length; i += 4) pixels[i] = 255;
    return pixels;
  }

  /**
   * A float target's pixels, RGBA32F, rows top to bottom.
   * @param {THREE.WebGLRenderTarget} target
   * @param {number} width
   * @param {number} height
   */
  readFloat(target, width, height) {
    const pixels = new Float32Array(width * height * 4);
    this.three.readRenderTargetPixels(target, 0, 0, width, height, pixels);
    const row = width * 4;
    const out = new Float32Array(pixels.length);
    for (let y = 0; y < height; y++) out.set(pixels.subarray((height - 1 - y) * row, (height - y) * row), y * row);
    return out;
  }

  /** What GPU and driver we run on. */
  info() {
    const gl = this.gl;
    const debug = gl.getExtension('WEBGL_debug_renderer_info');
    return {
      renderer: gl.getParameter(debug ? debug.UNMASKED_RENDERER_WEBGL : gl.RENDERER),
      vendor: gl.getParameter(debug ? debug.UNMASKED_VENDOR_WEBGL : gl.VENDOR),
      version: gl.getParameter(gl.VERSION),
      shadingLanguage: gl.getParameter(gl.SHADING_LANGUAGE_VERSION),
    };
  }
}
