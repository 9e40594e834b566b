// The flags that say what to draw (--size, --time, --frame, --mouse, --set, --channel0..3), read
// into the page's own URL contract (src/shared/url-params.js), so that a render from the command
// line is the page's render of that link. A value that cannot be read is a UsageError (exit 2);
// the page's own ranges are the page's (a control out of range is clamped there, and said).
//
// Every view is deterministic unless asked otherwise: iDate is DEFAULT_DATE at iTime 0 (or
// --date ISO; --date now for the real date), and iTimeDelta and iFrameRate are those of the frame
// schedule (--fps, 60 unless given), never measured: the page's ?date= and ?fps=.

import fs from 'node:fs';
import path from 'node:path';
import { MAX_FPS, MIN_FPS, formatUrlParams } from '../shared/url-params.js';
import { ShaderproofError, ENGINE_PAGE } from '../headless/session.js';

/** A flag or value the command cannot use: said with the verb's usage, exit 2. */
export class UsageError extends Error {}

export const VIEW_FLAGS = /** @type {const} */ ({
  size: { type: 'string' },
  time: { type: 'string' },
  frame: { type: 'string' },
  mouse: { type: 'string' },
  set: { type: 'string', multiple: true },
  channel0: { type: 'string' },
  channel1: { type: 'string' },
  channel2: { type: 'string' },
  channel3: { type: 'string' },
  date: { type: 'string' },
  media: { type: 'string' },
  'fetch-media': { type: 'boolean' },
});

/**
 * iDate at iTime 0 in every command-line view unless --date says otherwise: the moment the test
 * harness freezes Date at too (tests/support/deterministic-injection.js), in UTC, the zone the
 * browser runs in (src/headless/browser.js).
 */
export const DEFAULT_DATE = '2024-01-15T12:00:00Z';
/** Shadertoy's nominal frame rate: frame N is drawn at iTime N / 60 unless --fps says otherwise. */
const DEFAULT_FPS = 60;

/**
 * --date ISO (or "now": the real date, not reproducible) → ms since 1970, or null for now.
 * @param {string | undefined} text
 */
export function readDate(text = DEFAULT_DATE) {
  if (text.trim().toLowerCase() === 'now') return null;
  const ms = /^\d{4}-\d{2}-\d{2}/.test(text.trim()) ? Date.parse(text.trim()) : NaN;
  if (!Number.isFinite(ms))
    throw new UsageError(`--date ${text}: expected an ISO 8601 date such as 2024-01-15T12:00:00Z (a zone, else UTC), or "now"`);
  return ms;
}

/** How a view's date is said in a report: the ISO moment, or "now". @param {number | null} date */
export const dateLabel = (date) => (date === null ? 'the real date (--date now)' : new Date(date).toISOString());

/** "WxH" → {width, height}, whole and positive. @param {string} text @param {string} flag */
function readSize(text, flag = '--size') {
  const match = /^(\d+)x(\d+)$/i.exec(text.trim());
  const [width, height] = match ? [Number(match[1]), Number(match[2])] : [0, 0];
  if (!(width >= 1 && height >= 1)) throw new UsageError(`${flag} ${text}: expected WIDTHxHEIGHT in pixels, such as 640x360`);
  return { width, height };
}

/** @param {string} text @param {string} flag @param {{min?: number, max?: number, whole?: boolean}} [range] */
export function readNumber(text, flag, { min = -Infinity, max = Infinity, whole = false } = {}) {
  const value = text.trim() === '' ? NaN : Number(text);
  if (!Number.isFinite(value) || value < min || value > max || (whole && !Number.isInteger(value))) {
    const range =
      min > -Infinity && max < Infinity
        ? ` from ${min} to ${max}`
        : min > -Infinity
          ? ` of at least ${min}`
          : max < Infinity
            ? ` of at most ${max}`
            : '';
    throw new UsageError(`${flag} ${text}: expected ${whole ? 'a whole number' : 'a number'}${range}`);
  }
  return value;
}

/**
 * The view the flags describe.
 * @typedef {object} ViewOptions
 * @property {{width: number, height: number}} size
 * @property {number | null} time iTime, paused (null with --frame)
 * @property {number | null} frame iFrame to draw (frames 0 … N drawn in turn), or null
 * @property {number[] | null} mouse
 * @property {[string, string][]} controls NAME, VALUE as given
 * @property {(string | null)[]} channels image, video or music files for iChannel0..3 (the page tells them apart)
 * @property {number | null} date iDate at iTime 0, ms since 1970 (null: the real date)
 * @property {number} fps the frame schedule: iTimeDelta = 1 / fps, iFrameRate = fps, frame N at N / fps
 * @property {MediaOptions} media where the site's media a Shadertoy JSON names comes from (media.js)
 */

/**
 * @typedef {{dir: string | null, fetch: boolean}} MediaOptions dir: --media DIR, a folder laid out
 *   as the site's media paths; fetch: --fetch-media, what it lacks downloaded into a cache
 */

/**
 * --media and --fetch-media read and checked.
 * @param {Record<string, any>} values parseArgs's values
 * @returns {MediaOptions}
 */
export function readMediaOptions(values) {
  const dir = values.media === undefined ? null : path.resolve(String(values.media));
  if (dir !== null && !(fs.existsSync(dir) && fs.statSync(dir).isDirectory()))
    throw new UsageError(
      `--media ${values.media}: ${fs.existsSync(dir) ? 'a file, not a folder' : 'no such folder'} (give a folder laid out as the site's media: DIR/a/<hash>.jpg)`,
    );
  return { dir, fetch: Boolean(values['fetch-media']) };
}

/**
 * @param {Record<string, any>} values parseArgs's values
 * @param {{width: number, height: number}} defaultSize
 * @param {{fps?: number, maxFps?: number}} [schedule] the verb's default rate and its largest
 * @returns {ViewOptions}
 */
export function readViewOptions(values, defaultSize, { fps: defaultFps = DEFAULT_FPS, maxFps = MAX_FPS } = {}) {
  const size = values.size ? readSize(values.size) : defaultSize;
  if (values.time !== undefined && values.frame !== undefined)
    throw new UsageError('--time and --frame: give one (frame N is drawn at iTime N / 60)');
  const time = values.frame !== undefined ? null : values.time !== undefined ? readNumber(values.time, '--time', { min: 0 }) : 0;
  const frame = values.frame !== undefined ? readNumber(values.frame, '--frame', { min: 0, whole: true }) : null;
  let mouse = null;
  if (values.mouse !== undefined) {
    const parts = String(values.mouse).split(',');
    if (parts.length !== 2 && parts.length !== 4) throw new UsageError(`--mouse ${values.mouse}: expected x,y or x,y,z,w in pixels`);
    mouse = parts.map((p) => readNumber(p, '--mouse'));
  }
  /** @type {[string, string][]} */
  const controls = (values.set ?? []).map((pair) => {
    const at = pair.indexOf('=');
    const name = pair.slice(0, at).trim();
    if (at < 1 || !/^[A-Za-z_]\w*$/.test(name)) throw new UsageError(`--set ${pair}: expected NAME=VALUE, such as --set CONE_HEIGHT=2.5`);
    return [name, pair.slice(at + 1).trim()];
  });
  const channels = [0, 1, 2, 3].map((i) => {
    const file = values[`channel${i}`] ?? null;
    const device = /^(mic|microphone|webcam):?$/i.exec(file ?? '')?.[1].toLowerCase();
    if (device)
      throw new UsageError(
        `--channel${i} ${file}: the command line has no ${device === 'webcam' ? 'webcam' : 'microphone'} (the page has); give a ${device === 'webcam' ? 'video' : 'music'} file instead`,
      );
    if (file !== null) checkChannelFile(file, i);
    return file;
  });
  const date = readDate(values.date);
  const fps = values.fps === undefined ? defaultFps : readNumber(values.fps, '--fps', { min: MIN_FPS, max: maxFps });
  return { size, time, frame, mouse, controls, channels, date, fps, media: readMediaOptions(values) };
}

/** What a channel takes, said when it is given something else. */
const CHANNEL_TAKES = "an image, video or music file, a volume (the site's .bin) or a cubemap's first face";

/**
 * A --channelN file that can be read and is not a shader, checked before any browser starts: one
 * that is not there is said with its flag (exit 1, as a SHADER that is not there), and a shader
 * given as a channel's input is refused (exit 2), not drawn with a black channel and a warning.
 * @param {string} file
 * @param {number} index
 */
function checkChannelFile(file, index) {
  const flag = `--channel${index} ${file}`;
  if (!fs.existsSync(file)) throw new ShaderproofError(`${flag}: no such file`);
  if (fs.statSync(file).isDirectory()) throw new UsageError(`${flag}: a folder; give ${CHANNEL_TAKES}`);
  if (/\.(glsl|frag|json)$/i.test(file)) throw new UsageError(`${flag}: a shader, not a channel's input; give ${CHANNEL_TAKES}`);
}

/**
 * The engine page's address for a view of a mounted shader: `mount(file)` serves a file and returns its
 * URL path (page-server.js).
 * @param {string} shaderUrl
 * @param {ViewOptions} view
 * @param {(file: string) => string} mount
 * @param {string | null} [media] the URL of the media folders (page-server.js mountFolders)
 */
export function viewQuery(shaderUrl, view, mount, media = null) {
  return `${ENGINE_PAGE}${formatUrlParams({
    shader: shaderUrl,
    size: view.size,
    time: view.time ?? 0,
    mouse: view.mouse ?? undefined,
    date: view.date,
    fps: view.fps,
    channels: view.channels.map((file) => (file ? mount(path.resolve(file)) : null)),
    media,
    // as given: the page checks them against the shader's controls, and says what it changed
    controls: Object.fromEntries(view.controls),
  })}`;
}
