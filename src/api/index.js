// shaderproof's Node API (package.json "exports"): render, record and test Shadertoy shaders in
// headless Chromium from a script or a test file, with nothing printed unless `say` is given.
// It is the command line's own path: a session (src/headless/session.js), a still drawn by
// still.js's drawStill, a recording by record.js's recordFrames, a folder run by the runner
// (src/runner/corpus.js testFolder), a comparison by the runner's judgeImage. The options are the
// command line's flags by name (docs/api.md).

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ShaderproofError, shaderKind, startSession } from '../headless/session.js';
import { judgeImage } from '../headless/compare.js';
import { decodePng, pngBytes, readPng } from '../headless/png.js';
import { DEFAULT_TOLERANCE } from '../runner/manifest.js';
import { testFolder } from '../runner/corpus.js';
import { sessionOptions } from './io.js';
import { readRecording, recordFrames } from './record.js';
import { drawStill, readStill } from './still.js';
import { UsageError } from './view-options.js';

export { ShaderproofError };

/**
 * A shader: the path of a .glsl file (an Image tab) or of a Shadertoy JSON export, or its text.
 * Text is written to a temporary file named `name` (default shader.glsl, or shader.json for JSON)
 * for the call, and its errors name it so.
 * @typedef {string | {source: string, name?: string}} Shader
 */

/**
 * What draws and how long a frame may take: for openSession(), and every call that opens its own.
 * @typedef {object} SessionOptions
 * @property {'swiftshader' | 'llvmpipe' | 'gpu'} [renderer] default SwiftShader (the same pixels
 *   on every machine with the same Chromium), or $SHADERPROOF_RENDERER
 * @property {number} [watchdog] seconds of GPU-process CPU time a band of a frame may take
 * @property {(line: string) => void} [say] hears what the command line prints (warnings, notes)
 */

/**
 * The view, as the command line's flags name it.
 * @typedef {object} ViewOptions
 * @property {string | {width: number, height: number}} [size] '640x360' (the default)
 * @property {number} [time] iTime in seconds, paused (default 0)
 * @property {number} [frame] draw frames 0..N and keep frame N (not with time)
 * @property {number[]} [mouse] iMouse in pixels: [x, y] or [x, y, z, w]
 * @property {Record<string, number | string | boolean>} [set] the shader's controls by name
 * @property {(string | null)[]} [channels] files for iChannel0..3
 * @property {string} [date] iDate at iTime 0: ISO 8601 (default 2024-01-15T12:00:00Z) or 'now'
 * @property {number} [fps] the frame schedule (render: 60, record: 30)
 * @property {string} [media] a folder of the site's media a Shadertoy JSON names
 * @property {boolean} [fetchMedia] download what it lacks once, into a cache
 * @property {boolean} [strict] a shader that went without an input or a pass is an error
 */

/**
 * @typedef {ViewOptions & {converge?: number, tile?: number}} RenderOptions converge: N progressive
 *   samples a pixel, for a shader with a progressive form; tile: draw in tiles of this many pixels (even)
 */

/** @typedef {ViewOptions & {frames?: number, format?: 'webm' | 'zip'}} RecordOptions */

/**
 * A still: RGBA8 rows top to bottom, its PNG, the page's notes on it and what drew it.
 * @typedef {object} Rendered
 * @property {number} width
 * @property {number} height
 * @property {Uint8Array} data
 * @property {() => Buffer} png
 * @property {{kind: string, title: string, lines: string[]}[]} notes what the shader went
 *   without (kind 'missing') and values not used as given (kind 'values')
 * @property {string} renderer the WebGL2 renderer that drew it, as the command line names it
 */

/**
 * A recording: the file's bytes (a WebM, or a zip of frame-0000.png ...) and what it holds.
 * @typedef {object} Recorded
 * @property {Buffer} data
 * @property {'webm' | 'zip'} format
 * @property {number} frames
 * @property {number} fps
 * @property {number} width
 * @property {number} height
 * @property {string | null} codec the video's (webm)
 * @property {string | null} audio the Sound tab's track (webm), or null
 * @property {string} renderer
 */

/** An image: a PNG file's path or bytes, or RGBA8 pixels. @typedef {string | Uint8Array | {width: number, height: number, data: Uint8Array}} Image */

/**
 * A session: one browser for many calls. close() it (or `await using` it).
 * @typedef {object} Session
 * @property {(shader: Shader, options?: RenderOptions) => Promise<Rendered>} render
 * @property {(shader: Shader, options?: RecordOptions) => Promise<Recorded>} record
 * @property {() => number} launches how many times Chromium was started: 1 after the first
 *   call, and one more after each shader that hung it
 * @property {() => Promise<void>} close
 */

const quiet = () => {};

/** A flag's name as the API's option: --fetch-media → fetchMedia, --channel2 → channels[2]. @param {string} message */
const inApiWords = (message) =>
  message
    .replace(/--channel(\d)\b/g, 'channels[$1]')
    .replace(/(^|[\s(/])--([a-z]+)(?:-([a-z]))?/g, (_, before, word, next) => `${before}${word}${next ? next.toUpperCase() : ''}`);

/** Runs `body`, with a UsageError said as the one error of the API. @template T @param {() => Promise<T>} body */
async function asApiErrors(body) {
  try {
    return await body();
  } catch (error) {
    if (error instanceof UsageError) throw new ShaderproofError(inApiWords(error.message), 2);
    if (error instanceof ShaderproofError) error.message = inApiWords(error.message);
    throw error;
  }
}

/** The API's options as parseArgs's values of the command line. @param {Record<string, any>} options */
function asFlags(options) {
  /** @type {Record<string, any>} */
  const values = {};
  const text = (/** @type {string} */ key, value) => value !== undefined && (values[key] = String(value));
  if (options.size !== undefined)
    values.size = typeof options.size === 'string' ? options.size : `${options.size.width}x${options.size.height}`;
  for (const key of [
    'time',
    'frame',
    'fps',
    'converge',
    'tile',
    'frames',
    'date',
    'media',
    'watchdog',
    'renderer',
    'shard',
    'jobs',
    'out',
    'grep',
  ])
    text(key, options[key]);
  if (options.grepInvert !== undefined) values['grep-invert'] = String(options.grepInvert);
  if (options.mouse !== undefined) values.mouse = [options.mouse].flat().join(',');
  if (options.set !== undefined) values.set = Object.entries(options.set).map(([name, value]) => `${name}=${value}`);
  (options.channels ?? []).forEach((file, i) => file && (values[`channel${i}`] = file));
  if (options.fetchMedia) values['fetch-media'] = true;
  return values;
}

/**
 * The file a shader is read from for `body`: its path, or its text in a temporary file (removed
 * after), whose path errors say as the shader's name.
 * @template T
 * @param {Shader} shader
 * @param {(file: string) => Promise<T>} body
 */
async function shaderFile(shader, body) {
  if (typeof shader === 'string') return body(shader);
  if (!shader || typeof shader.source !== 'string')
    throw new ShaderproofError('shader: give the path of a .glsl or .json file, or { source: "…its text…" }', 2);
  const name = path.basename(shader.name ?? (/^\s*[[{]/.test(shader.source) ? 'shader.json' : 'shader.glsl'));
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-source-'));
  const file = path.join(dir, name);
  try {
    fs.writeFileSync(file, shader.source);
    return await body(file);
  } catch (error) {
    if (error instanceof ShaderproofError) error.message = error.message.replaceAll(file, name);
    throw error;
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

/**
 * Opens one headless Chromium (when the first call needs it) for many renders and recordings.
 * @param {SessionOptions} [options]
 * @returns {Promise<Session>}
 */
export async function openSession(options = {}) {
  const say = options.say ?? quiet;
  const core = await asApiErrors(async () => {
    const chosen = sessionOptions(asFlags({ renderer: options.renderer, watchdog: options.watchdog }), 'swiftshader');
    return startSession({ ...chosen, say });
  });
  let closed = false;
  const open = () => {
    if (closed) throw new ShaderproofError('this session is closed: open another with openSession()');
  };
  /** @type {Session} */
  const session = {
    render: (shader, renderOptions = {}) =>
      asApiErrors(() =>
        shaderFile(shader, async (file) => {
          open();
          const still = readStill(asFlags(renderOptions));
          shaderKind(file);
          const { image, renderer } = await drawStill(core, file, still, { strict: Boolean(renderOptions.strict), say });
          const { width, height, data } = image;
          return { width, height, data, png: () => pngBytes(image), notes: image.notes, renderer };
        }),
      ),
    record: (shader, recordOptions = {}) =>
      asApiErrors(() =>
        shaderFile(shader, async (file) => {
          open();
          const format = recordOptions.format ?? 'webm';
          if (format !== 'webm' && format !== 'zip') throw new UsageError(`format ${format}: a recording is 'webm' or 'zip' (of PNGs)`);
          const recording = readRecording(asFlags(recordOptions));
          shaderKind(file);
          const made = await recordFrames(core, file, recording, {
            format: format === 'zip' ? 'png' : 'webm',
            strict: Boolean(recordOptions.strict),
            say,
          });
          return { ...made, format };
        }),
      ),
    launches: () => core.launches(),
    async close() {
      if (closed) return;
      closed = true;
      await core.close();
    },
  };
  // `await using session = await openSession()` closes it (TypeScript 5.2, Node 24: the syntax;
  // Node 20.4+ has the symbol)
  const dispose = /** @type {any} */ (Symbol).asyncDispose;
  if (dispose) Object.defineProperty(session, dispose, { value: () => session.close() });
  return session;
}

/**
 * A still of `shader` in a browser of its own (openSession() for many).
 * @param {Shader} shader
 * @param {RenderOptions & SessionOptions} [options]
 * @returns {Promise<Rendered>}
 */
export async function render(shader, options = {}) {
  const session = await openSession(options);
  try {
    return await session.render(shader, options);
  } finally {
    await session.close();
  }
}

/**
 * A recording of `shader` (frame i at iTime i / fps) in a browser of its own.
 * @param {Shader} shader
 * @param {RecordOptions & SessionOptions} [options]
 * @returns {Promise<Recorded>}
 */
export async function record(shader, options = {}) {
  const session = await openSession(options);
  try {
    return await session.record(shader, options);
  } finally {
    await session.close();
  }
}

/**
 * Runs a folder as `shaderproof test DIR` does (its shaderproof.json, its __references__/), and
 * returns its results instead of an exit code; it writes the references (update), the failing
 * cases' images and the reports into `out`, as the command line does, and prints nothing unless
 * `say` is given (it then hears the command line's lines).
 * @param {string} folder
 * @param {{update?: boolean, shard?: string, jobs?: number, reporters?: ('dot' | 'junit' | 'html')[],
 *   out?: string, date?: string, media?: string, fetchMedia?: boolean, renderer?: 'swiftshader' | 'llvmpipe' | 'gpu',
 *   watchdog?: number, grep?: string, grepInvert?: string, say?: (line: string) => void}} [options]
 *   out: default ./shaderproof-output; renderer: default the one that drew the references; grep,
 *   grepInvert: only the cases whose names match, or do not (a regular expression, as `-g`)
 */
export async function test(folder, options = {}) {
  const say = options.say ?? quiet;
  // no reporters: the case lines only (to `say`), no report files
  const reporter = options.reporters && (options.reporters.length ? [...options.reporters] : ['dot']);
  const values = { ...asFlags(options), update: Boolean(options.update), reporter };
  const run = await asApiErrors(() => testFolder({ values, positionals: [folder] }, { say, out: say, bar: false }));
  const failed = run.results.filter((r) => !r.ok).length;
  return {
    /** every case passed */
    ok: failed === 0,
    passed: run.results.length - failed,
    failed,
    /** each case's result: name, ok, failures, notes, diffPixels, files (in `out`) ... */
    cases: run.results,
    /** what drew them (null when no case ran: --last-failed after a run with none failed) */
    renderer: run.environment?.label ?? null,
    out: run.out,
    reports: run.reports,
  };
}

/**
 * The runner's comparison (the one `test` makes): pixelmatch at `threshold` (0..1), at most
 * `maxDiffPixels` pixels may differ; both default to 0, a case's defaults.
 * @param {Image} actual
 * @param {Image} reference
 * @param {{threshold?: number, maxDiffPixels?: number}} [tolerance]
 * @returns {{ok: boolean, diffPixels: number | null, failure: string | null,
 *   where: import('../headless/compare.js').Where | null,
 *   diff: {width: number, height: number, data: Uint8Array, png: () => Buffer} | null}}
 *   where: the differing pixels' bounding box and the first few, with their values
 */
export function compare(actual, reference, tolerance = {}) {
  const judged = judgeImage(readImage(actual, 'actual'), readImage(reference, 'reference'), { ...DEFAULT_TOLERANCE, ...tolerance });
  const diff = judged.diff;
  return {
    ok: judged.ok,
    diffPixels: judged.diffPixels,
    failure: judged.failure,
    where: judged.where,
    diff: diff && { ...diff, png: () => pngBytes(diff) },
  };
}

/** @param {Image} image @param {string} what */
function readImage(image, what) {
  try {
    if (typeof image === 'string') return readPng(image);
    if (image instanceof Uint8Array) return decodePng(image);
  } catch (error) {
    throw new ShaderproofError(`${what}: ${typeof image === 'string' ? image : 'the bytes'} is no PNG file (${error.message})`);
  }
  if (image && image.data && image.width * image.height * 4 === image.data.length) return image;
  throw new ShaderproofError(`${what}: give a PNG file's path or bytes, or { width, height, data } with RGBA8 data`);
}
