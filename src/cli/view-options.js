// The flags that say what to draw (--size, --time, --frame, --mouse, --set, --channel0..3), read
// into the page's own URL contract (src/page/io/url-params.js), so that a render from the command
// line is the page's render of that link. A value that cannot be read is a UsageError (exit 2);
// the page's own ranges are the page's (a control out of range is clamped there, and said).

import path from 'node:path';

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
});

/** "WxH" → {width, height}, whole and positive. @param {string} text @param {string} flag */
function readSize(text, flag = '--size') {
  const match = /^(\d+)x(\d+)$/i.exec(text.trim());
  const [width, height] = match ? [Number(match[1]), Number(match[2])] : [0, 0];
  if (!(width >= 1 && height >= 1)) throw new UsageError(`${flag} ${text}: expected WIDTHxHEIGHT in pixels, such as 640x360`);
  return { width, height };
}

/** @param {string} text @param {string} flag @param {{min?: number, whole?: boolean}} [range] */
export function readNumber(text, flag, { min = -Infinity, whole = false } = {}) {
  const value = text.trim() === '' ? NaN : Number(text);
  if (!Number.isFinite(value) || value < min || (whole && !Number.isInteger(value))) {
    throw new UsageError(
      `${flag} ${text}: expected ${whole ? 'a whole number' : 'a number'}${min > -Infinity ? ` of at least ${min}` : ''}`,
    );
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
 * @property {(string | null)[]} channels image files for iChannel0..3
 */

/**
 * @param {Record<string, any>} values parseArgs's values
 * @param {{width: number, height: number}} defaultSize
 * @returns {ViewOptions}
 */
export function readViewOptions(values, defaultSize) {
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
  const channels = [0, 1, 2, 3].map((i) => values[`channel${i}`] ?? null);
  return { size, time, frame, mouse, controls, channels };
}

/**
 * The page's query for a view of a mounted shader: `mount(file)` serves a file and returns its
 * URL path (page-server.js).
 * @param {string} shaderUrl
 * @param {ViewOptions} view
 * @param {(file: string) => string} mount
 */
export function viewQuery(shaderUrl, view, mount) {
  const params = new URLSearchParams();
  params.set('shader', shaderUrl);
  params.set('size', `${view.size.width}x${view.size.height}`);
  if (view.time !== null) params.set('time', String(view.time));
  else params.set('time', '0');
  if (view.mouse) params.set('mouse', view.mouse.join(','));
  view.channels.forEach((file, i) => {
    if (file) params.set(`iChannel${i}`, mount(path.resolve(file)));
  });
  for (const [name, value] of view.controls) params.set(name, value);
  return `/?${params}`;
}
