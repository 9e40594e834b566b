// Raw WebGL2 pages: a complete fragment shader (e.g. composeImageShader(source).code) compiled
// in a plain WebGL2 context, no three.js and no page code, as Shadertoy compiles a paste. The
// in-page half is raw-webgl-page.js, served with raw-webgl.html by the harness's routes (routes.js);
// this is the Node half. Used by the Shadertoy paste test, the example-shader comparisons, the
// intersector tests (evaluateFloatShader) and the benchmark's timer (tests/bench/timer.js).

import { countNewlines } from '../../../src/shadertoy/header.js';
import { formatShaderMessages, parseShaderLog, userLineOffset } from '../../../src/shadertoy/shader-errors.js';
import { decodeRgba, openPage } from '../page.js';
import { HARNESS_ROUTES } from '../routes.js';

/** raw-webgl.html, as the harness's routes serve it (routes.js: on the build's server too). */
const RAW_PAGE_PATH = `${HARNESS_ROUTES}repo/tests/support/raw-webgl/raw-webgl.html`;

/**
 * A fresh page (openPage: `deterministic: false` keeps the real clock) at raw-webgl.html, with
 * window.__rawWebGL installed.
 * @returns {Promise<{page: import('puppeteer-core').Page, errors: string[], context: object}>}
 */
export async function openRawPage(title, options) {
  const opened = await openPage(options);
  const { page, errors, context } = opened;
  const url = `${context.baseUrl}${RAW_PAGE_PATH}`;
  const response = await page.goto(url, { waitUntil: 'load' });
  if (!response?.ok()) throw new Error(`${url} answered HTTP ${response?.status()}`);
  const ready = await page.evaluate((t) => {
    document.title = t;
    return Boolean(window.__rawWebGL);
  }, title);
  if (!ready) throw new Error(`${url} did not install window.__rawWebGL${errors.length ? `:\n  ${errors.join('\n  ')}` : ''}`);
  return opened;
}

/**
 * What renderRawShader resolves with: the stage that failed and its log, or the frame (RGBA8,
 * rows top to bottom). Each has the other's fields as undefined, so that `raw.stage` or
 * `raw.glError` can be read before telling which it is.
 * @typedef {{stage: 'vertex' | 'compile' | 'link' | 'setup', log: string, width?: undefined, height?: undefined, data?: undefined, glError?: undefined, renderer?: undefined}} RawShaderFailure
 * @typedef {{width: number, height: number, data: Buffer, glError: number, renderer: string, stage?: undefined, log?: undefined}} RawShaderFrame
 * @typedef {RawShaderFailure | RawShaderFrame} RawShaderResult
 */

/**
 * Compiles a complete fragment shader in a plain WebGL2 context and draws one fullscreen
 * triangle with Shadertoy's uniforms at their first-frame values (FIRST_FRAME_UNIFORMS of the
 * Shadertoy module): iResolution = (width, height, 1), iTime 0, iFrame 0, iMouse 0, iDate from
 * the (frozen) clock. `uniforms` overrides any of them, e.g.
 * { iTime: 1.5, iFrame: 3, iMouse: [40, 59, 40, -59] }. `on`: another browser than the run's
 * (page.js openPage).
 * @param {string} code
 * @param {{width: number, height: number, uniforms?: Record<string, number | number[]>,
 *   on?: {browser: import('puppeteer-core').Browser, context: object}}} options
 * @returns {Promise<RawShaderResult>}
 */
export async function renderRawShader(code, { width, height, uniforms = {}, on = undefined }) {
  const { page, errors } = await openRawPage('raw WebGL2', { on });
  try {
    const result = await page.evaluate((fragment, options) => window.__rawWebGL.render(fragment, options), code, {
      width,
      height,
      uniforms,
    });
    if (errors.length) throw new Error(`raw WebGL2 page logged errors:\n  ${errors.join('\n  ')}`);
    if (result.stage) return { stage: result.stage, log: result.log };
    return {
      width,
      height,
      data: decodeRgba(result.data, width, height, 'raw render'),
      glError: result.glError,
      renderer: result.renderer,
    };
  } finally {
    await page.close().catch(() => {});
  }
}

/**
 * Runs a complete fragment shader over a table of inputs and reads its RGBA32F output back as
 * floats: the way the intersector tests run GLSL functions on chosen rays. The table is an
 * RGBA32F texture `tableUniform` of width x tableHeight texels; output is width x height.
 * @returns {Promise<Float32Array>} RGBA floats, row 0 first (GL order)
 */
export async function evaluateFloatShader(code, { width, height, table, tableHeight, tableUniform }) {
  const { page, errors } = await openRawPage('float WebGL2');
  try {
    const result = await page.evaluate((fragment, options) => window.__rawWebGL.evaluateFloat(fragment, options), code, {
      width,
      height,
      table: Array.from(table),
      tableHeight,
      tableUniform,
    });
    if (errors.length) throw new Error(`float WebGL2 page logged errors:\n  ${errors.join('\n  ')}`);
    if (result.error !== undefined) throw new Error(`evaluateFloatShader: ${result.error}`);
    return new Float32Array(result.data);
  } finally {
    await page.close().catch(() => {});
  }
}

/**
 * A compiler log of a composed shader in terms of the user's file, as the page reports it
 * (src/shadertoy/shader-errors.js): one message a line, `fileName:line:` with the source line
 * under it for lines of the file.
 * @param {string} log the compiler's info log
 * @param {{code: string, firstSourceLine: number, source: string, fileName?: string}} shader
 *   what composeImageShader returned, and the file it composed
 */
export function mapShaderLog(log, { code, firstSourceLine, source, fileName = 'shader' }) {
  const offset = userLineOffset(code, code, firstSourceLine, source);
  return formatShaderMessages(parseShaderLog(String(log ?? ''), offset, countNewlines(source) + 1), source, fileName);
}
