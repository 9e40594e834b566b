// The cases of `shaderproof test DIR`: every .glsl and .json file under DIR (not a dot-file, as
// OUT/.last-run.json is, nor in a dot-folder), and every view the
// manifest names (sorted together, so shards are stable across machines), with what
// DIR/shaderproof.json says of each:
//
//   { "defaults": { …any case key… },
//     "cases": { "RELATIVE/PATH.glsl": {
//         "size": "WxH", "time": T | "frame": N, "mouse": [x, y, z, w],
//         "date": "ISO" | "now", "fps": F,                       (iDate at iTime 0; the schedule)
//         "set": { "NAME": value }, "channels": ["image.png", …],     (paths relative to DIR)
//         "tolerance": { "threshold": 0..1, "maxDiffPixels": N,
//                        "llvmpipe": { "threshold": t, "maxDiffPixels": n } },
//                                                (a renderer's own, where it rounds otherwise
//                                                 than the references' renderer did)
//         "checks": { "noNaN": true, "deterministic": true,
//                     "halfSize": true | { "threshold": t, "maxDiffFraction": f },
//                     "maxFrameMs": ms },
//         "sound": { "time": T, "duration": S, "tolerance": { "rms": r, "spectrum": s } },
//                                                (the Sound tab against DIR/__references__/<case>.wav:
//                                                 sound-compare.js; from 0 s for 2 s by default)
//         "allowMissing": ["iChannel2", "Sound", "Image/iChannel1"],  (inputs or passes the
//                                                case may go without: else it fails)
//         "skip": "why",
//         "//": "a comment, or a list of lines" },
//       "a-view": { "shader": "../scenes/room.glsl", …any case key… } } }
//                                                (a case named by a view, not by a file under DIR:
//                                                 it draws "shader", a path relative to DIR; one
//                                                 shader may have many views; "defaults" may say
//                                                 it for them all)
//
// An unknown key or a value of the wrong kind is a usage error naming it (a typo must not turn
// a check off in silence).

import fs from 'node:fs';
import path from 'node:path';
import { ShaderproofError } from '../headless/session.js';
import { readViewOptions } from '../api/view-options.js';
import { RENDERER_NAMES } from '../headless/renderers.js';
import { DEFAULT_SOUND_TOLERANCE } from './sound-compare.js';

export const MANIFEST = 'shaderproof.json';
export const REFERENCE_DIR = '__references__';
/** Folders that are never cases: references, dot-folders, installed packages. */
export const SKIPPED_DIRS = /^(\.|__|node_modules$)/;

/** The default tolerance: SwiftShader draws the same bytes on every machine with the same Chromium. */
export const DEFAULT_TOLERANCE = Object.freeze({ threshold: 0, maxDiffPixels: 0 });
/** A half-size render is a different sampling of the picture: close, not equal. */
const DEFAULT_HALF_SIZE = Object.freeze({ threshold: 0.1, maxDiffFraction: 0.05 });
/** A case's size unless its manifest says otherwise: smaller than render's 640x360, a suite being many renders. */
export const DEFAULT_SIZE = Object.freeze({ width: 320, height: 180 });

const CASE_KEYS = [
  'size',
  'time',
  'frame',
  'mouse',
  'date',
  'fps',
  'set',
  'channels',
  'tolerance',
  'checks',
  'sound',
  'allowMissing',
  'skip',
  'shader',
  '//',
];
/** A case named by a view: its name is its reference's file name, with "/" for sub-folders. */
const VIEW_NAME = /^[A-Za-z0-9_][\w.-]*(\/[A-Za-z0-9_][\w.-]*)*$/;
/** A shader file: a case of its own under DIR, or what a view draws. */
export const SHADER_FILE = /\.(glsl|json)$/i;
/** A sound case's default span: short, each second is a second of the GPU's time and of the file's. */
const DEFAULT_SOUND_SPAN = Object.freeze({ time: 0, duration: 2 });
const CHECK_KEYS = ['noNaN', 'deterministic', 'halfSize', 'maxFrameMs'];

/**
 * @typedef {object} TestCase
 * @property {string} name its path under DIR, with forward slashes
 * @property {string} file
 * @property {'glsl' | 'json'} kind
 * @property {string} reference the reference PNG's path
 * @property {import('../api/view-options.js').ViewOptions} view
 * @property {Tolerance} tolerance
 * @property {Partial<Record<import('../headless/renderers.js').RendererName, Tolerance>>} rendererTolerance
 *   a renderer's own tolerance, the rest of it the case's
 * @property {{noNaN?: boolean, deterministic?: boolean, halfSize?: {threshold: number, maxDiffFraction: number}, maxFrameMs?: number}} checks
 * @property {{time: number, duration: number, tolerance: {rms: number, spectrum: number}, reference: string} | null} sound
 *   the Sound tab compared with its reference WAV (sound-compare.js), or null
 * @property {string[]} allowMissing what the case may go without (io.js allowedMissing)
 * @property {string | null} skip
 */

/** @typedef {{threshold: number, maxDiffPixels: number}} Tolerance */

/**
 * The tolerance a case is compared at when `renderer` draws it: that renderer's own, where the
 * manifest gives one, else the case's.
 * @param {Pick<TestCase, 'tolerance' | 'rendererTolerance'>} testCase
 * @param {import('../headless/renderers.js').RendererName | undefined} renderer
 * @returns {Tolerance}
 */
export function toleranceFor(testCase, renderer) {
  return (renderer && testCase.rendererTolerance[renderer]) || testCase.tolerance;
}

/**
 * A "//" key: a comment (npm's convention in package.json), a string or a list of strings.
 * @param {unknown} value
 */
const isComment = (value) => typeof value === 'string' || (Array.isArray(value) && value.every((line) => typeof line === 'string'));

/** @param {string} dir */
export function readManifest(dir) {
  const file = path.join(dir, MANIFEST);
  if (!fs.existsSync(file)) return { defaults: {}, cases: {} };
  let manifest;
  try {
    manifest = JSON.parse(fs.readFileSync(file, 'utf8'));
  } catch (error) {
    throw new ShaderproofError(`${file}: not valid JSON (${error.message})`, 2);
  }
  if (manifest === null || typeof manifest !== 'object' || Array.isArray(manifest))
    throw new ShaderproofError(`${file}: not an object with "defaults" and "cases"`, 2);
  const unknown = Object.keys(manifest).filter((k) => !['defaults', 'cases', '//'].includes(k));
  if (unknown.length) throw new ShaderproofError(`${file}: unknown key ${unknown.join(', ')} (expected "defaults" and "cases")`, 2);
  if (manifest['//'] !== undefined && !isComment(manifest['//']))
    throw new ShaderproofError(`${file}: "//" is a comment: a string or a list of strings`, 2);
  return { defaults: manifest.defaults ?? {}, cases: manifest.cases ?? {} };
}

/** @param {string} dir @returns {string[]} paths under dir */
function shaderFiles(dir, under = '') {
  const found = [];
  for (const entry of fs.readdirSync(path.join(dir, under), { withFileTypes: true })) {
    const relative = path.join(under, entry.name);
    if (entry.isDirectory()) {
      if (!SKIPPED_DIRS.test(entry.name)) found.push(...shaderFiles(dir, relative));
    } else if (SHADER_FILE.test(entry.name) && !entry.name.startsWith('.') && relative !== MANIFEST) found.push(relative);
  }
  return found;
}

/**
 * @param {string} where
 * @param {Record<string, any>} entry
 * @param {string} dir
 * @returns {Omit<TestCase, 'name' | 'file' | 'kind' | 'reference'>}
 */
function readCase(where, entry, dir) {
  const fail = (message) => {
    throw new ShaderproofError(`${MANIFEST}: ${where}: ${message}`, 2);
  };
  const unknown = Object.keys(entry).filter((k) => !CASE_KEYS.includes(k));
  if (unknown.length) fail(`unknown key ${unknown.join(', ')} (a case may have ${CASE_KEYS.join(', ')})`);
  const values = {
    size: entry.size,
    time: entry.time === undefined ? undefined : String(entry.time),
    frame: entry.frame === undefined ? undefined : String(entry.frame),
    mouse: Array.isArray(entry.mouse) ? entry.mouse.join(',') : entry.mouse,
    date: entry.date === undefined ? undefined : String(entry.date),
    fps: entry.fps === undefined ? undefined : String(entry.fps),
    set: Object.entries(entry.set ?? {}).map(([name, value]) => `${name}=${Array.isArray(value) ? value.join(',') : value}`),
  };
  /** @type {(string | undefined)[]} */
  const channels = entry.channels ?? [];
  if (!Array.isArray(channels) || channels.length > 4) fail('"channels" is a list of up to 4 image paths');
  channels.forEach((file, i) => {
    if (file) values[`channel${i}`] = path.resolve(dir, file);
  });
  let view;
  try {
    view = readViewOptions(values, DEFAULT_SIZE);
  } catch (error) {
    fail(error.message.replace(/^--/, '"').replace(/^"(\w+)/, '"$1"'));
  }
  if (entry['//'] !== undefined && !isComment(entry['//'])) fail('"//" is a comment: a string or a list of strings');
  const { tolerance, rendererTolerance } = readTolerance(entry.tolerance ?? {}, fail);
  const given = entry.checks ?? {};
  const unknownChecks = Object.keys(given).filter((k) => !CHECK_KEYS.includes(k));
  if (unknownChecks.length) fail(`unknown check ${unknownChecks.join(', ')} (the checks are ${CHECK_KEYS.join(', ')})`);
  /** @type {TestCase['checks']} */
  const checks = {};
  for (const key of ['noNaN', 'deterministic']) {
    if (given[key] === undefined) continue;
    if (typeof given[key] !== 'boolean') fail(`check ${key} is ${JSON.stringify(given[key])}, not true or false`);
    checks[key] = given[key];
  }
  if (given.halfSize === true) checks.halfSize = { ...DEFAULT_HALF_SIZE };
  else if (given.halfSize && typeof given.halfSize === 'object') checks.halfSize = { ...DEFAULT_HALF_SIZE, ...given.halfSize };
  else if (given.halfSize !== undefined && given.halfSize !== false) fail('check halfSize is true, false or {threshold, maxDiffFraction}');
  if (given.maxFrameMs !== undefined) {
    if (typeof given.maxFrameMs !== 'number' || !(given.maxFrameMs > 0))
      fail(`check maxFrameMs is ${JSON.stringify(given.maxFrameMs)}, not a number of ms`);
    checks.maxFrameMs = given.maxFrameMs;
  }
  const skip = entry.skip === undefined ? null : String(entry.skip);
  const allowMissing = entry.allowMissing ?? [];
  if (!Array.isArray(allowMissing) || !allowMissing.every((a) => typeof a === 'string' && a))
    fail('"allowMissing" is a list of pass names and channels, such as ["iChannel2", "Sound", "Image/iChannel1"]');
  const sound = entry.sound === undefined ? null : readSound(entry.sound, fail);
  return {
    view: /** @type {import('../api/view-options.js').ViewOptions} */ (view),
    tolerance,
    rendererTolerance,
    checks,
    sound,
    allowMissing,
    skip,
  };
}

/**
 * A case's "tolerance": its own, and each renderer's that it names (the rest of that one the
 * case's).
 * @param {Record<string, any>} given
 * @param {(message: string) => never} fail
 */
function readTolerance(given, fail) {
  if (given === null || typeof given !== 'object' || Array.isArray(given))
    fail('"tolerance" is {"threshold": t, "maxDiffPixels": n}, with a renderer\'s own such as "llvmpipe": {…}');
  const numbers = (/** @type {Record<string, any>} */ values, /** @type {string} */ where) => {
    for (const [key, value] of Object.entries(values))
      if (typeof value !== 'number' || !(value >= 0)) fail(`tolerance ${where}${key} is ${JSON.stringify(value)}, not a number >= 0`);
    return values;
  };
  /** @type {Record<string, any>} */
  const own = {};
  /** @type {Record<string, any>} */
  const byRenderer = {};
  for (const [key, value] of Object.entries(given)) {
    if (key in DEFAULT_TOLERANCE) own[key] = value;
    else if (RENDERER_NAMES.includes(/** @type {any} */ (key))) byRenderer[key] = value;
    else fail(`unknown tolerance ${key} (expected threshold, maxDiffPixels, or a renderer's own: ${RENDERER_NAMES.join(', ')})`);
  }
  /** @type {Tolerance} */
  const tolerance = { ...DEFAULT_TOLERANCE, ...numbers(own, '') };
  /** @type {TestCase['rendererTolerance']} */
  const rendererTolerance = {};
  for (const [renderer, values] of Object.entries(byRenderer)) {
    if (values === null || typeof values !== 'object' || Array.isArray(values))
      fail(`tolerance ${renderer} is ${JSON.stringify(values)}, not {"threshold": t, "maxDiffPixels": n}`);
    const unknown = Object.keys(values).filter((k) => !(k in DEFAULT_TOLERANCE));
    if (unknown.length) fail(`unknown tolerance ${renderer}.${unknown.join(', ')} (expected threshold, maxDiffPixels)`);
    rendererTolerance[/** @type {import('../headless/renderers.js').RendererName} */ (renderer)] = {
      ...tolerance,
      ...numbers(values, `${renderer}.`),
    };
  }
  return { tolerance, rendererTolerance };
}

/**
 * A case's "sound": its span and tolerances (the reference's path is findCases').
 * @param {any} given
 * @param {(message: string) => never} fail
 */
function readSound(given, fail) {
  if (given === null || typeof given !== 'object' || Array.isArray(given))
    fail('"sound" is {"time": T, "duration": S, "tolerance": {"rms": r, "spectrum": s}}');
  const unknown = Object.keys(given).filter((k) => !['time', 'duration', 'tolerance'].includes(k));
  if (unknown.length) fail(`unknown sound key ${unknown.join(', ')} (expected time, duration, tolerance)`);
  const span = { ...DEFAULT_SOUND_SPAN, ...given };
  if (typeof span.time !== 'number' || !(span.time >= 0)) fail(`sound time is ${JSON.stringify(span.time)}, not seconds >= 0`);
  if (typeof span.duration !== 'number' || !(span.duration > 0 && span.duration <= 180))
    fail(`sound duration is ${JSON.stringify(span.duration)}, not seconds from 0 to 180`);
  const tolerance = { ...DEFAULT_SOUND_TOLERANCE, ...(given.tolerance ?? {}) };
  for (const [key, value] of Object.entries(tolerance)) {
    if (!(key in DEFAULT_SOUND_TOLERANCE)) fail(`unknown sound tolerance ${key} (expected rms, spectrum)`);
    if (typeof value !== 'number' || !(value >= 0)) fail(`sound tolerance ${key} is ${JSON.stringify(value)}, not a number >= 0`);
  }
  return { time: span.time, duration: span.duration, tolerance, reference: '' };
}

/**
 * Two "tolerance" entries merged, a renderer's own key by key.
 * @param {Record<string, any>} under @param {Record<string, any>} over
 */
function mergeTolerance(under, over) {
  const merged = { ...under, ...over };
  for (const name of RENDERER_NAMES) {
    const [a, b] = [under[name], over[name]];
    if (a && b && typeof a === 'object' && typeof b === 'object') merged[name] = { ...a, ...b };
  }
  return merged;
}

/**
 * The shader a case named by a view draws: its "shader", relative to DIR, a .glsl or .json file
 * that is there.
 * @param {string} name @param {unknown} shader @param {string} dir
 */
function viewShader(name, shader, dir) {
  /** @type {(message: string) => never} */
  const fail = (message) => {
    throw new ShaderproofError(`${MANIFEST}: ${name}: ${message}`, 2);
  };
  if (!VIEW_NAME.test(name))
    fail(
      'a case that is not a file under DIR is a view, and its name is its reference\'s file name: letters, digits, "-", "_", "." and "/"',
    );
  if (shader === undefined)
    fail(`no shader ${name} in DIR, and no "shader" to draw: a view names its shader, such as "shader": "../shaders/scene.glsl"`);
  if (typeof shader !== 'string' || !SHADER_FILE.test(shader)) fail(`"shader" is ${JSON.stringify(shader)}, not a .glsl or .json file`);
  const file = path.resolve(dir, shader);
  if (!fs.existsSync(file) || !fs.statSync(file).isFile()) fail(`"shader" ${shader}: no such file (a path relative to ${dir})`);
  return file;
}

/**
 * The cases under `dir`, and the views its manifest names, sorted by name, each with the
 * manifest's defaults and its own entry.
 * @param {string} dir
 * @param {{defaults: Record<string, any>, cases: Record<string, any>}} manifest
 * @param {{date?: string}} [run] the run's --date: a case's own "date" (or the defaults') wins
 * @returns {TestCase[]}
 */
export function findCases(dir, manifest, { date } = {}) {
  const files = shaderFiles(dir).map((f) => f.split(path.sep).join('/'));
  const listed = Object.keys(manifest.cases).filter((name) => !files.includes(name));
  const missing = listed.filter((name) => SHADER_FILE.test(name));
  if (missing.length) throw new ShaderproofError(`${MANIFEST}: no shader ${missing.join(', ')} in ${dir}`, 2);
  const names = [...files, ...listed].sort();
  return names.map((name) => {
    const own = manifest.cases[name] ?? {};
    const isFile = files.includes(name);
    if (isFile && own.shader !== undefined)
      throw new ShaderproofError(`${MANIFEST}: ${name}: "shader" is for a view; a shader file under DIR draws itself`, 2);
    for (const [where, entry] of [
      ['defaults', manifest.defaults],
      [name, own],
    ])
      for (const key of ['tolerance', 'checks'])
        if (entry[key] !== undefined && (entry[key] === null || typeof entry[key] !== 'object' || Array.isArray(entry[key])))
          throw new ShaderproofError(`${MANIFEST}: ${where}: "${key}" is ${JSON.stringify(entry[key])}, not an object`, 2);
    const { shader, ...defaults } = manifest.defaults;
    const merged = {
      ...(date === undefined ? {} : { date }),
      ...defaults,
      ...own,
      checks: { ...(manifest.defaults.checks ?? {}), ...(own.checks ?? {}) },
      tolerance: mergeTolerance(manifest.defaults.tolerance ?? {}, own.tolerance ?? {}),
    };
    const file = isFile ? path.join(dir, name) : viewShader(name, own.shader ?? shader, dir);
    delete merged.shader;
    const read = readCase(name, merged, dir);
    if (read.sound) read.sound.reference = path.join(dir, REFERENCE_DIR, `${name}.wav`);
    return {
      name,
      file,
      kind: /\.json$/i.test(file) ? /** @type {const} */ ('json') : /** @type {const} */ ('glsl'),
      reference: path.join(dir, REFERENCE_DIR, `${name}.png`),
      ...read,
    };
  });
}
