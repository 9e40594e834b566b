// A minimal multipass runner for tests, in the raw WebGL2 page (tests/support/raw-webgl/raw-webgl.js's
// openRawPage and its window.__rawWebGL helpers, used unchanged): each buffer two RGBA32F
// textures used in turn, as the site keeps them (https://www.shadertoy.com/js/effect.js:
// TEXFMT.C4F32, a pass renders into the texture it did not write last, every input reads the
// one written last), passes painted in the schedule's order (frameSchedule of
// src/shadertoy/multipass.js), every frame. It is not the page's renderer: it is what lets the
// node tests check composed passes, the schedule and the progressive shader on a real GPU
// (SwiftShader) before the page can run them.

import { openRawPage } from './raw-webgl/raw-webgl.js';
import { composePassShader } from '../../src/shadertoy/header.js';
import { channelTypes, frameSchedule } from '../../src/shadertoy/multipass.js';

/**
 * Composes every pass of a model in Shadertoy's header (no host block unless given) and lists
 * them in render order with the buffer each channel reads (null for none).
 * @param {import('../../src/shadertoy/multipass.js').MultipassShader} model
 * @param {{hostBlock?: string}} [options]
 */
export function composeModel(model, { hostBlock = '' } = {}) {
  return frameSchedule(model).map(({ pass, target, bindings }) => {
    const composed = composePassShader(pass.code, {
      common: model.common,
      hostBlock,
      kind: pass.kind,
      name: pass.name,
      channelTypes: channelTypes(pass),
    });
    return {
      name: pass.name,
      target,
      code: composed.code,
      composed,
      bindings: bindings.map((b) => (b.source === 'buffer' ? { buffer: b.buffer, filter: b.sampler.filter, wrap: b.sampler.wrap } : null)),
    };
  });
}

/**
 * Runs composed passes for a list of frames in a fresh raw WebGL2 page. Frame i gets iFrame = i
 * and iTime 0 unless its `uniforms` say otherwise. A frame with `capture: true` is read back:
 * the screen (RGBA8, rows top to bottom) and every buffer's last written texture (RGBA floats,
 * row 0 = bottom, as GL reads it).
 * @param {Array<{name: string, target: string, code: string, bindings: Array<{buffer: string, filter: string, wrap: string} | null>}>} passes
 * @param {{width: number, height: number, frames: Array<{uniforms?: object, capture?: boolean, resize?: [number, number]}>}} run
 * @returns {Promise<{error?: string, log?: string, pass?: string, captures?: Array<{frame: number, width: number, height: number, screen: string, buffers: Record<string, number[]>}>}>}
 */
export async function runPasses(passes, { width, height, frames }) {
  const { page, errors } = await openRawPage('multipass');
  try {
    const result = await page.evaluate(inPage, {
      width,
      height,
      frames,
      passes: passes.map(({ name, target, code, bindings }) => ({ name, target, code, bindings })),
    });
    if (errors.length) throw new Error(`multipass page logged errors:\n  ${errors.join('\n  ')}`);
    return result;
  } finally {
    await page.close().catch(() => {});
  }
}

/** The in-page half (serialized by page.evaluate: self-contained). */
function inPage({ width, height, frames, passes }) {
  const raw = window.__rawWebGL;
  const gl = raw.context(width, height, { premultipliedAlpha: false, preserveDrawingBuffer: true });
  if (!gl) return { error: 'no WebGL2 context' };
  if (!gl.getExtension('EXT_color_buffer_float')) return { error: 'EXT_color_buffer_float is not supported' };
  const programs = [];
  for (const pass of passes) {
    const built = raw.program(gl, pass.code);
    if (built.stage) return { error: `${pass.name} failed to ${built.stage}`, log: built.log, pass: pass.name };
    programs.push(built.program);
  }
  let size = [width, height];
  const buffers = {};
  const makeBuffer = (w, h, old) => {
    const textures = [0, 1].map(() => {
      const t = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, t);
      gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32F, w, h);
      return t;
    });
    const fbos = textures.map((t) => {
      const f = gl.createFramebuffer();
      gl.bindFramebuffer(gl.FRAMEBUFFER, f);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, t, 0);
      return f;
    });
    if (old) {
      // As the site resizes: the old content copied texel for texel into the lower-left corner.
      for (let i = 0; i < 2; i++) {
        gl.bindFramebuffer(gl.READ_FRAMEBUFFER, old.fbos[i]);
        gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, fbos[i]);
        const cw = Math.min(w, old.size[0]);
        const ch = Math.min(h, old.size[1]);
        gl.blitFramebuffer(0, 0, cw, ch, 0, 0, cw, ch, gl.COLOR_BUFFER_BIT, gl.NEAREST);
      }
    }
    return { textures, fbos, last: 0, size: [w, h] };
  };
  for (const pass of passes) if (pass.target !== 'screen') buffers[pass.target] = makeBuffer(width, height, null);
  const captures = [];
  const wrapOf = (w) => (w === 'repeat' ? gl.REPEAT : gl.CLAMP_TO_EDGE);
  const filterOf = (f) => (f === 'nearest' ? gl.NEAREST : gl.LINEAR);
  for (let frame = 0; frame < frames.length; frame++) {
    const spec = frames[frame];
    if (spec.resize) {
      size = spec.resize;
      for (const name of Object.keys(buffers)) buffers[name] = makeBuffer(size[0], size[1], buffers[name]);
      gl.canvas.width = size[0];
      gl.canvas.height = size[1];
    }
    passes.forEach((pass, i) => {
      gl.useProgram(programs[i]);
      const resolutions = [];
      pass.bindings.forEach((binding, unit) => {
        gl.activeTexture(gl.TEXTURE0 + unit);
        if (!binding) {
          gl.bindTexture(gl.TEXTURE_2D, null);
          resolutions.push(0, 0, 0);
          return;
        }
        const b = buffers[binding.buffer];
        gl.bindTexture(gl.TEXTURE_2D, b.textures[b.last]);
        // RGBA32F is not filterable without OES_texture_float_linear: NEAREST where it is missing.
        const linearOk = Boolean(gl.getExtension('OES_texture_float_linear'));
        const filter = linearOk ? filterOf(binding.filter) : gl.NEAREST;
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, filter);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, filter);
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, wrapOf(binding.wrap));
        gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, wrapOf(binding.wrap));
        resolutions.push(size[0], size[1], 1);
      });
      raw.setShadertoyUniforms(gl, programs[i], {
        width: size[0],
        height: size[1],
        overrides: { iFrame: frame, iChannelResolution: resolutions, ...(spec.uniforms ?? {}) },
      });
      const target = pass.target === 'screen' ? null : buffers[pass.target];
      gl.bindFramebuffer(gl.FRAMEBUFFER, target ? target.fbos[1 - target.last] : null);
      gl.viewport(0, 0, size[0], size[1]);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      if (target) target.last = 1 - target.last;
    });
    if (spec.capture) {
      const read = /** @type {Record<string, number[]>} */ ({});
      for (const [name, b] of Object.entries(buffers)) {
        gl.bindFramebuffer(gl.FRAMEBUFFER, b.fbos[b.last]);
        const out = new Float32Array(size[0] * size[1] * 4);
        gl.readPixels(0, 0, size[0], size[1], gl.RGBA, gl.FLOAT, out);
        read[name] = Array.from(out);
      }
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      captures.push({ frame, width: size[0], height: size[1], screen: raw.readBase64(gl, size[0], size[1]), buffers: read });
    }
  }
  const glError = gl.getError();
  if (glError) return { error: `GL error ${glError}` };
  return { captures };
}
