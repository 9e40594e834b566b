// The cases of `shaderproof test DIR`: every .glsl and .json file under DIR (sorted, so shards
// are stable across machines), with what DIR/shaderproof.json says of each:
//
//   { "defaults": { …any case key… },
//     "cases": { "RELATIVE/PATH.glsl": {
//         "size": "WxH", "time": T | "frame": N, "mouse": [x, y, z, w],
//         "date": "ISO" | "now", "fps": F,                       (iDate at iTime 0; the schedule)
//         "set": { "NAME": value }, "channels": ["image.png", …],     (paths relative to DIR)
//         "tolerance": { "threshold": 0..1, "maxDiffPixels": N },
//         "checks": { "noNaN": true, "deterministic": true,
//                     "halfSize": true | { "threshold": t, "maxDiffFraction": f },
//                     "maxFrameMs": ms },
//         "sound": { "time": T, "duration": S, "tolerance": { "rms": r, "spectrum": s } },
//                                                (the Sound tab against DIR/__references__/<case>.wav:
//                                                 sound-compare.js; from 0 s for 2 s by default)
//         "allowMissing": ["iChannel2", "Sound", "Image/iChannel1"],  (inputs or passes the
//                                                case may go without: else it fails)
//         "skip": "why" } } }
//
// An unknown key or a value of the wrong kind is a usage error naming it (a typo must not turn
// a check off in silence).

import fs from 'node:fs';
import path from 'node:path';
import { CliError } from '../session.js';
import { readViewOptions } from '../view-options.js';
import { DEFAULT_SOUND_TOLERANCE } from './sound-compare.js';

const MANIFEST = 'shaderproof.json';
export const REFERENCE_DIR = '__references__';
/** Folders that are never cases: references, dot-folders, installed packages. */
const SKIPPED_DIRS = /^(\.|__|node_modules$)/;

/** The default tolerance: SwiftShader draws the same bytes on every machine with the same Chromium. */
const DEFAULT_TOLERANCE = Object.freeze({ threshold: 0, maxDiffPixels: 0 });
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
];
/** A sound case's default span: short, each second is a second of the GPU's time and of the file's. */
const DEFAULT_SOUND_SPAN = Object.freeze({ time: 0, duration: 2 });
const CHECK_KEYS = ['noNaN', 'deterministic', 'halfSize', 'maxFrameMs'];

/**
 * @typedef {object} TestCase
 * @property {string} name its path under DIR, with forward slashes
 * @property {string} file
 * @property {'glsl' | 'json'} kind
 * @property {string} reference the reference PNG's path
 * @property {import('../view-options.js').ViewOptions} view
 * @property {{threshold: number, maxDiffPixels: number}} tolerance
 * @property {{noNaN?: boolean, deterministic?: boolean, halfSize?: {threshold: number, maxDiffFraction: number}, maxFrameMs?: number}} checks
 * @property {{time: number, duration: number, tolerance: {rms: number, spectrum: number}, reference: string} | null} sound
 *   the Sound tab compared with its reference WAV (sound-compare.js), or null
 * @property {string[]} allowMissing what the case may go without (io.js allowedMissing)
 * @property {string | null} skip
 */

/** @param {string} dir */
export function readManifest(dir) {
  const file = path.join(dir, MANIFEST);
  if (!fs.existsSync(file)) return { defaults: {}, cases: {} };
  let manifest;
  try {
    manifest = JSON.parse(fs.readFileSync(file, 'utf8'));
  } catch (error) {
    throw new CliError(`${file}: not valid JSON (${error.message})`, 2);
  }
  const unknown = Object.keys(manifest).filter((k) => k !== 'defaults' && k !== 'cases');
  if (unknown.length) throw new CliError(`${file}: unknown key ${unknown.join(', ')} (expected "defaults" and "cases")`, 2);
  return { defaults: manifest.defaults ?? {}, cases: manifest.cases ?? {} };
}

/** @param {string} dir @returns {string[]} paths under dir */
function shaderFiles(dir, under = '') {
  const found = [];
  for (const entry of fs.readdirSync(path.join(dir, under), { withFileTypes: true })) {
    const relative = path.join(under, entry.name);
    if (entry.isDirectory()) {
      if (!SKIPPED_DIRS.test(entry.name)) found.push(...shaderFiles(dir, relative));
    } else if (/\.(glsl|json)$/i.test(entry.name) && relative !== MANIFEST) found.push(relative);
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
    throw new CliError(`${MANIFEST}: ${where}: ${message}`, 2);
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
  const tolerance = { ...DEFAULT_TOLERANCE, ...(entry.tolerance ?? {}) };
  for (const [key, value] of Object.entries(tolerance)) {
    if (!(key in DEFAULT_TOLERANCE)) fail(`unknown tolerance ${key} (expected threshold, maxDiffPixels)`);
    if (typeof value !== 'number' || !(value >= 0)) fail(`tolerance ${key} is ${JSON.stringify(value)}, not a number >= 0`);
  }
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
  return { view: /** @type {import('../view-options.js').ViewOptions} */ (view), tolerance, checks, sound, allowMissing, skip };
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
 * The cases under `dir`, sorted by name, each with the manifest's defaults and its own entry.
 * @param {string} dir
 * @param {{defaults: Record<string, any>, cases: Record<string, any>}} manifest
 * @param {{date?: string}} [run] the run's --date: a case's own "date" (or the defaults') wins
 * @returns {TestCase[]}
 */
export function findCases(dir, manifest, { date } = {}) {
  const names = shaderFiles(dir)
    .map((f) => f.split(path.sep).join('/'))
    .sort();
  const listed = Object.keys(manifest.cases).filter((name) => !names.includes(name));
  if (listed.length) throw new CliError(`${MANIFEST}: no shader ${listed.join(', ')} in ${dir}`, 2);
  return names.map((name) => {
    const own = manifest.cases[name] ?? {};
    const merged = {
      ...(date === undefined ? {} : { date }),
      ...manifest.defaults,
      ...own,
      checks: { ...(manifest.defaults.checks ?? {}), ...(own.checks ?? {}) },
      tolerance: { ...(manifest.defaults.tolerance ?? {}), ...(own.tolerance ?? {}) },
    };
    const file = path.join(dir, name);
    const read = readCase(name, merged, dir);
    if (read.sound) read.sound.reference = path.join(dir, REFERENCE_DIR, `${name}.wav`);
    return {
      name,
      file,
      kind: /\.json$/i.test(name) ? /** @type {const} */ ('json') : /** @type {const} */ ('glsl'),
      reference: path.join(dir, REFERENCE_DIR, `${name}.png`),
      ...read,
    };
  });
}
