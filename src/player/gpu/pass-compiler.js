// Compiles the passes of a Shadertoy shader into three.js RawShaderMaterials for the renderer
// (renderer.js), off to the side: each material is compiled on a staging scene of its own, so a
// shader that fails to compile never replaces the last one that worked. A failure's driver log is
// mapped back to the user's tabs and lines (three.js's onShaderError hook → ShaderCompileError).
// Each pass's text reaches WebGL as composed, none of three.js's preprocessing applied to it
// (verbatim-source.js). Compiled materials are kept by their code (the material cache): the page
// switches between a shader's uniform form and its constant form (app.js), and switching back
// must not wait for a compile.

import * as THREE from 'three';
import { composePassShader } from '../../shadertoy/header.js';
import { parseShaderLog, userLineOffset } from '../../shadertoy/shader-errors.js';
import { formatCompileMessages, passCheck, passMessages } from '../../shadertoy/pass-errors.js';
import { channelTypes, frameSchedule } from '../../shadertoy/multipass.js';
import { ShaderCompileError } from './errors.js';
import { verbatimStandIn } from './verbatim-source.js';
import { CubeBuffer } from './channels/cube-buffer.js';
import { guardLoops } from '../../shadertoy/loop-guard.js';

/**
 * Compiled materials kept for switching back without a compile: a uniform form, a constant form,
 * and one spare, for each of up to five passes; twice that on llvmpipe, where a pass with loops
 * has its guarded form beside it.
 */
const MATERIALS_KEPT = 15;

/** @typedef {ReturnType<typeof frameSchedule>[number] & {material: THREE.RawShaderMaterial}} Step */
/**
 * A program three.js is checking: the user's text, the composed code WebGL compiled and the line
 * of it where the user's text starts, and the error _onShaderError found in it.
 * @typedef {{userText: string, sections: PassSection[] | null, code: string, firstSourceLine: number, error: ShaderCompileError | null}} ProgramCheck
 * @typedef {import('../../shadertoy/header.js').PassSection} PassSection
 */

export const VERTEX_SHADER = `
in vec3 position;
void main() {
    gl_Position = vec4(position.xy, 0.0, 1.0);
}
`;

export class PassCompiler {
  /**
   * @param {THREE.WebGLRenderer} three
   * @param {THREE.BufferGeometry} geometry the fullscreen triangle
   * @param {THREE.Camera} camera
   * @param {(material: THREE.RawShaderMaterial) => boolean} inUse whether a material is on screen (never disposed here)
   * @param {import('./loop-cuts.js').LoopCuts} loopCuts where a pass that cannot be guarded is
   *   said to be unchecked; with `enabled` (llvmpipe), each pass with loops compiles guarded
   */
  constructor(three, geometry, camera, inUse, loopCuts) {
    this.three = three;
    this._loopCuts = loopCuts;
    this.camera = camera;
    this._inUse = inUse;
    three.debug.onShaderError = (...args) => this._onShaderError(...args);
    // compiled away from the visible scene, swapped in only when it works
    this.stagingScene = new THREE.Scene();
    // it holds a pass's material only while that compiles; a mesh made without one has a
    // MeshBasicMaterial of three.js's, the stand-in the rest of the time (never compiled: the
    // staging scene is compiled only with a pass's material in it)
    this.stagingMesh = new THREE.Mesh(geometry);
    this._standIn = this.stagingMesh.material;
    this.stagingMesh.frustumCulled = false;
    this.stagingScene.add(this.stagingMesh);
    /** Set while three.js checks a program, read by _onShaderError. @type {ProgramCheck | null} */
    this._compiling = null;
    /**
     * Materials that compiled, by their code, most recent last.
     * @type {Map<string, THREE.RawShaderMaterial>}
     */
    this._compiled = new Map();
  }

  /**
   * Compiles every pass of `project` with `hostBlock` between header and Common, each with the
   * uniforms `passUniforms()` gives. Resolves with the frame's steps once all are compiled; if any
   * fails it rejects with a ShaderCompileError naming each message's tab (for a plain file: its
   * lines). Every pass that compiled is kept either way.
   * @param {import('../../shadertoy/multipass.js').MultipassShader} project
   * @param {string} hostBlock
   * @param {string} fileName
   * @param {() => Record<string, {value: any}>} passUniforms
   * @param {{tiled?: boolean}} [options] tiled: the Image pass as a tile of a larger picture
   *   (header.js: TILE_OFFSET_UNIFORM), for a shader without buffers
   * @returns {Promise<Step[]>}
   */
  async compileSteps(project, hostBlock, fileName, passUniforms, { tiled = false } = {}) {
    const schedule = frameSchedule(project);
    if (tiled && schedule.length > 1) throw new Error("a shader with buffers is not drawn in tiles: its buffers are the picture's size");
    const messages = [];
    /** @type {Step[]} */
    const steps = [];
    for (const step of schedule) {
      const { pass } = step;
      const composed = composePassShader(pass.code, {
        common: project.common,
        hostBlock,
        kind: pass.kind,
        name: pass.name,
        channelTypes: channelTypes(pass),
        tiled,
      });
      const check = passCheck(project, pass, composed);
      try {
        // the Cube A pass has uniforms of its own (cube-buffer.js), its iResolution among them
        const uniforms = pass.kind === 'cubemap' ? () => ({ ...passUniforms(), ...CubeBuffer.ownUniforms() }) : passUniforms;
        const material = await this._compileMaterial(composed, check, uniforms);
        steps.push({ ...step, material: await this._guarded(material, composed, uniforms, pass.name) });
      } catch (error) {
        if (!error.messages) throw error;
        // an error in Common is the same error in every pass that includes it: said once
        const said = new Set(messages.map((m) => JSON.stringify([m.pass, m.line, m.message])));
        messages.push(...error.messages.filter((m) => m.pass !== 'Common' || !said.has(JSON.stringify([m.pass, m.line, m.message]))));
      }
    }
    if (messages.length) {
      for (const step of steps) this._remember(step.material.fragmentShader, step.material);
      throw new ShaderCompileError(formatCompileMessages(messages, project, fileName), messages);
    }
    for (const step of steps) this._remember(step.material.fragmentShader, step.material);
    return steps;
  }

  /**
   * One pass outside the frame's schedule (the Sound tab: src/player/gpu/sound-pass.js),
   * compiled and kept as the frame's passes are; rejects with a ShaderCompileError.
   * @param {{code: string, firstSourceLine: number}} composed
   * @param {{userText: string, sections: PassSection[] | null}} check
   * @param {() => Record<string, {value: any}>} uniforms
   * @param {string} name the pass's name ('Sound'), for what the loop guard says of it
   */
  async compileOne(composed, check, uniforms, name) {
    const material = await this._guarded(await this._compileMaterial(composed, check, uniforms), composed, uniforms, name);
    this._remember(material.fragmentShader, material);
    return material;
  }

  /**
   * On llvmpipe, the guarded form of a pass that compiled (src/shadertoy/loop-guard.js), drawn
   * in its place: the same picture, and where the loop limit cut a loop. The pass as it is, where
   * it has no loop, or (said as unchecked) where its guarded form cannot be made or compiled.
   * The plain material is kept either way: its compile is what reports the user's errors.
   * @param {THREE.RawShaderMaterial} plain
   * @param {{code: string}} composed
   * @param {() => Record<string, {value: any}>} uniforms
   * @param {string} name the pass's name
   */
  async _guarded(plain, { code }, uniforms, name) {
    if (!this._loopCuts.enabled) return plain;
    const form = guardLoops(code);
    if (form.code === null) {
      if (form.reason === 'no loops') this._loopCuts.checkable(name);
      else this._loopCuts.uncheckable(name, `its loops could not be read (${form.reason})`);
      return plain;
    }
    try {
      const guarded = await this._compileMaterial({ code: form.code, firstSourceLine: 1 }, { userText: '', sections: null }, uniforms);
      guarded.userData.loopGuard = true;
      this._remember(plain.fragmentShader, plain);
      this._loopCuts.checkable(name);
      return guarded;
    } catch (error) {
      const why = error?.messages?.[0]?.message ?? error?.message ?? String(error);
      this._loopCuts.uncheckable(name, `its guarded form did not compile (${why})`);
      return plain;
    }
  }

  /**
   * One pass's material, compiled (or the one kept from before for the same code).
   * @param {{code: string, firstSourceLine: number}} composed
   * @param {{userText: string, sections: import('../../shadertoy/header.js').PassSection[] | null}} check
   * @param {() => Record<string, {value: any}>} passUniforms
   */
  async _compileMaterial({ code, firstSourceLine }, { userText, sections }, passUniforms) {
    // the stand-in of the code (verbatim-source.js): one per code, so also the cache's key
    const fragmentShader = verbatimStandIn(code);
    const cached = this._compiled.get(fragmentShader);
    if (cached) return cached;
    const material = new THREE.RawShaderMaterial({
      // the vertex shader's #version; the fragment shader's is the code's own
      glslVersion: THREE.GLSL3,
      vertexShader: VERTEX_SHADER,
      fragmentShader,
      uniforms: passUniforms(),
      depthTest: false,
      depthWrite: false,
      toneMapped: false,
    });
    this.stagingMesh.material = material;
    // compile() creates the program now; compileAsync then waits for it without blocking, where
    // the driver can (KHR_parallel_shader_compile; asking three.js for it would warn otherwise)
    const compiled = this.three.extensions.has('KHR_parallel_shader_compile')
      ? this.three.compileAsync(this.stagingScene, this.camera)
      : Promise.resolve(this.three.compile(this.stagingScene, this.camera));
    this.stagingMesh.material = this._standIn;
    await compiled;

    // Asking for the uniforms makes three.js check the program, calling onShaderError on failure.
    const program = /** @type {{currentProgram: {getUniforms: () => unknown}}} */ (this.three.properties.get(material)).currentProgram;
    /** @type {ProgramCheck} */
    const check = { userText, sections, code, firstSourceLine, error: null };
    this._compiling = check;
    try {
      program.getUniforms();
    } finally {
      this._compiling = null;
    }
    if (check.error) {
      material.dispose();
      throw check.error;
    }
    return material;
  }

  /** Keeps the most recent compiled materials (MATERIALS_KEPT); disposes the ones that fall out. */
  _remember(fragmentShader, material) {
    this._compiled.delete(fragmentShader);
    this._compiled.set(fragmentShader, material);
    for (const [key, old] of this._compiled) {
      if (this._compiled.size <= MATERIALS_KEPT * (this._loopCuts.enabled ? 2 : 1)) break;
      this._compiled.delete(key);
      if (!this._inUse(old)) old.dispose();
    }
  }

  /** Forgets the compiled materials but the ones on screen (their programs died with a lost context). */
  forgetCompiled() {
    for (const material of this._compiled.values()) if (!this._inUse(material)) material.dispose();
    this._compiled.clear();
  }

  /** three.js's hook for a program that did not link: turn the logs into a ShaderCompileError. */
  _onShaderError(gl, program, vertexShader, fragmentShader) {
    const check = this._compiling;
    if (!check) return;
    const offset = userLineOffset(gl.getShaderSource(fragmentShader) ?? '', check.code, check.firstSourceLine, check.userText);
    const log = gl.getShaderInfoLog(fragmentShader) ?? '';
    const messages = [
      ...passMessages(log, offset, check),
      ...parseShaderLog(gl.getShaderInfoLog(vertexShader) ?? '', null, 0).map((m) => ({
        ...m,
        pass: null,
        message: `vertex shader: ${m.message}`,
      })),
    ];
    if (messages.length === 0) {
      messages.push(...parseShaderLog(gl.getProgramInfoLog(program) ?? 'link failed', null, 0).map((m) => ({ ...m, pass: null })));
    }
    check.error = new ShaderCompileError('', messages);
  }
}
