// The benchmark's timer: complete fragment shaders timed in one raw WebGL2 page
// (tests/support/raw-webgl/raw-webgl.js), interleaved, on one renderer or several. Used by measure.js
// (run.js, ablation.js, apart.js), branches.js and primitives.js.

import { decodeRgba } from '../support/page.js';
import { openRawPage } from '../support/raw-webgl/raw-webgl.js';

/**
 * A shader's outcome in timeShaders: its `frames` times in ms and its last frame (RGBA8, rows top
 * to bottom), or why it could not run. Each has the other's fields as undefined, so that
 * `r.error` or `r.times` can be read before telling which it is.
 * @typedef {{times: number[], width: number, height: number, data: Buffer, error?: undefined}
 *   | {error: string, times?: undefined, width?: undefined, height?: undefined, data?: undefined}} TimedShader
 */

/**
 * Times complete fragment shaders in one plain WebGL2 canvas (no page code), interleaved: each
 * round draws every shader once, so that a machine that speeds up or slows down during the run
 * moves all of them alike. `warmup` untimed rounds (the first compiles the renderer's code), then
 * `frames` timed rounds; a frame is a draw plus a 1-pixel readPixels, so that what is timed is
 * the rendering. Then each shader's last frame is read back. Each frame is its own call into the
 * page (no protocol timeout however slow), and `onRound(i)` can show progress.
 * `shaders` is a list of { code, uniforms } where uniforms are { name, type, value } (float,
 * int, bool, vecN), set after Shadertoy's own at their first-frame values (iTime 0, iMouse 0).
 * On the harness's browser; timeShadersOn times them on several renderers.
 * @param {Array<{code: string, uniforms?: Array<{name: string, type: string, value: number | boolean | number[]}>}>} shaders
 * @param {{width: number, height: number, frames?: number, warmup?: number, onRound?: (round: number) => void}} options
 * @returns {Promise<TimedShader[]>} one a shader, in order
 */
export async function timeShaders(shaders, options) {
  const [results] = await timeShadersOn([{ on: undefined }], shaders, options);
  return results;
}

/**
 * timeShaders on each of `renderers` (renderer-set.js; `on: undefined` is the harness's own
 * browser), interleaved: each round draws every shader on one renderer, then on the next, the
 * renderers' order turned round every other round, so that neither always draws first.
 * @param {Array<{on: import('./renderer-set.js').BenchRenderer['on'] | undefined}>} renderers
 * @param {Parameters<typeof timeShaders>[0]} shaders
 * @param {Parameters<typeof timeShaders>[1]} options
 * @returns {Promise<TimedShader[][]>} one list a renderer, in order
 */
export async function timeShadersOn(renderers, shaders, { width, height, frames = 15, warmup = 3, onRound = () => {} }) {
  /** @type {Array<Awaited<ReturnType<typeof openTimer>>>} */
  const timers = [];
  try {
    for (const { on } of renderers) timers.push(await openTimer(on, shaders, width, height));
    const times = timers.map(() => shaders.map(() => /** @type {number[]} */ ([])));
    for (let round = 0; round < warmup + frames; round++) {
      const order = timers.map((_, t) => t);
      if (round % 2) order.reverse();
      for (const t of order) {
        for (const i of timers[t].live) {
          const ms = await timers[t].page.evaluate((k) => window.__benchmark.frame(k), i);
          if (round >= warmup) times[t][i].push(ms);
        }
      }
      onRound(round);
    }
    /** @type {TimedShader[][]} */
    const all = [];
    for (const [t, timer] of timers.entries()) {
      /** @type {TimedShader[]} */
      const results = [];
      for (const [i, setup] of timer.setups.entries()) {
        if (setup.error) {
          results.push({ error: setup.error });
          continue;
        }
        const data = await timer.page.evaluate((k) => window.__benchmark.pixels(k), i);
        results.push({ times: times[t][i], width, height, data: decodeRgba(data, width, height, 'benchmark frame') });
      }
      if (timer.errors.length) throw new Error(`benchmark page logged errors:\n  ${timer.errors.join('\n  ')}`);
      all.push(results);
    }
    return all;
  } finally {
    for (const timer of timers) await timer.page.close().catch(() => {});
  }
}

/**
 * A raw WebGL2 page on `on` (the harness's browser when undefined) with every shader compiled and
 * linked, and window.__benchmark's frame(i) and pixels(i) to draw them.
 * @param {import('./renderer-set.js').BenchRenderer['on'] | undefined} on
 * @param {Parameters<typeof timeShaders>[0]} shaders
 * @param {number} width
 * @param {number} height
 */
async function openTimer(on, shaders, width, height) {
  // The benchmark needs the real clock: no deterministic injection here.
  const { page, errors } = await openRawPage('benchmark', { deterministic: false, on });
  try {
    const setups = await page.evaluate(
      (list, w, h) => {
        const raw = window.__rawWebGL;
        const gl = raw.context(w, h);
        if (!gl) return list.map(() => ({ error: 'no WebGL2 context' }));
        gl.viewport(0, 0, w, h);
        const one = new Uint8Array(4);
        const programs = list.map(({ code, uniforms }) => {
          const built = raw.program(gl, code);
          if (built.stage) return { error: `${built.stage}: ${built.log}` };
          raw.setShadertoyUniforms(gl, built.program, { width: w, height: h });
          for (const { name, type, value } of uniforms) raw.setUniform(gl, gl.getUniformLocation(built.program, name), type, value);
          return { program: built.program };
        });
        window.__benchmark = {
          frame(i) {
            gl.useProgram(programs[i].program);
            const start = performance.now();
            gl.drawArrays(gl.TRIANGLES, 0, 3);
            gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, one);
            return performance.now() - start;
          },
          pixels(i) {
            gl.useProgram(programs[i].program);
            gl.drawArrays(gl.TRIANGLES, 0, 3);
            return raw.readBase64(gl, w, h);
          },
        };
        return programs.map((p) => (p.error ? { error: p.error } : {}));
      },
      shaders.map(({ code, uniforms = [] }) => ({ code, uniforms })),
      width,
      height,
    );
    const live = setups.map((s, i) => (s.error ? null : i)).filter((i) => i !== null);
    return { page, errors, setups, live };
  } catch (error) {
    await page.close().catch(() => {});
    throw error;
  }
}
