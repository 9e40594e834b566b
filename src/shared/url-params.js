// The page's URL contract, for sharing a view and for automation:
//
//   ?shader=URL      the Image-tab source to run: a URL the page's own server serves (relative,
//                    such as examples/pattern.glsl, or absolute on the same origin). Without it
//                    the page runs shaders/raytrace.glsl.
//   &time=T          render at iTime = T seconds, paused (0 .. 1e6)
//   &mouse=x,y,z,w   iMouse in device pixels (until the first click); x,y alone means z = w = 0
//   &size=WxH        drawing buffer of W×H device pixels (CSS size W/dpr × H/dpr; no scaling)
//   &scale=s         resolution scale, 0.25 .. 1 of device pixels (ignored with size)
//   &cap=N           cap on the drawing buffer's longer side, in device pixels; 0: no cap (ignored
//                    with size)
//   &speed=s         time speed, 0 .. 16 (1 is real time)
//   &date=ISO        iDate fixed: this moment at iTime 0, moving on with iTime (not the real
//                    date), so that a clock draws the same frame on every run (the command line's
//                    default; the date is read in the browser's time zone)
//   &fps=F           the clock's frame schedule: each frame advances iTime by speed / F, and
//                    iTimeDelta and iFrameRate are those of F frames a second, not measured ones
//                    (1 .. 240)
//   &iChannel0=URL   an image for iChannel0 (likewise iChannel1..3), same origin as the page
//   &media=URL       a folder of the site's media, laid out as its paths (URL/a/<hash>.jpg for
//                    /media/a/<hash>.jpg), same origin as the page: the textures, cubemaps and
//                    volumes a Shadertoy JSON's channels name (src/player/inputs/media-library.js)
//   &NAME=value      any shader control; vectors as comma lists (LIGHT_POSITION=1,2,3)
//
// A key given more than once is read once, from its last occurrence, and the others are warned
// about. Anything unreadable is reported in `warnings` and ignored, anything out of range is clamped and
// reported; the page never fails on a URL. Control values are returned as written: the app checks
// them against the shader's controls (coerceControlValue), as it does for the panel and the
// hook. formatUrlParams writes the same contract back (the "Copy link" button).

import { MAX_PIXELS, MAX_SCALE, MAX_SIZE, MIN_SCALE, clampSize } from './canvas-limits.js';

/** The smallest cap= that caps; cap=0 means no cap, as the panel's "No cap". */
const MIN_CAP = 16;
const MAX_SPEED = 16;
const MAX_TIME = 1e6;
const MAX_MOUSE = 1e6;
/** The frame schedule's range (?fps=), frames a second. */
export const MIN_FPS = 1;
export const MAX_FPS = 240;
export const CHANNEL_PARAMS = ['iChannel0', 'iChannel1', 'iChannel2', 'iChannel3'];

function finiteNumbers(text) {
  const parts = text.split(',').map((s) => (s.trim() === '' ? NaN : Number(s)));
  return parts.every(Number.isFinite) ? parts : null;
}

/**
 * A same-origin URL from a query value, or null and why not. `base` is the page's address.
 * @param {string} value
 * @param {string} base
 * @returns {{url: string, why?: undefined} | {url: null, why: string}}
 */
function sameOriginUrl(value, base) {
  let url;
  try {
    url = new URL(value, base);
  } catch {
    return { url: null, why: 'not a URL' };
  }
  const origin = new URL(base).origin;
  if (url.origin !== origin) return { url: null, why: `only files served by this page's server (${origin}) can be loaded` };
  return { url: url.href };
}

/** What the page does instead of a page parameter it cannot read (said with the warning). */
const INSTEAD = {
  time: 'the clock runs from 0',
  mouse: 'iMouse is 0,0,0,0',
  size: 'the canvas follows the window',
  scale: 'the scale is 1',
  cap: 'no cap',
  speed: 'the speed is 1',
  date: 'iDate is the real date',
  fps: 'iTimeDelta and iFrameRate are measured',
  media: "the site's media a shader names stay black",
  shader: 'the built-in raytracer runs',
};

/**
 * A name GLSL ES 3.00 keeps for itself (section 3.7: `gl_` prefixes, and any name with two
 * underscores in a row), so no shader control can have it. `__proto__` is one of them: as a key
 * of a plain object it would set the object's prototype instead of naming a control.
 */
const RESERVED_NAME = /^gl_|__/;

/**
 * @typedef {{shader?: string, time?: number, mouse?: number[], size?: {width:number, height:number},
 *   scale?: number, cap?: number, speed?: number, date?: number, fps?: number, channels: (string|undefined)[], media?: string,
 *   controls: Record<string, string>, warnings: string[], refusedShader?: {url: string, why: string}}} UrlParams
 */

/**
 * @param {string} search location.search
 * @param {string} [base] the page's address (resolves `shader` and `iChannelN` URLs)
 * @returns {UrlParams}
 */
export function parseUrlParams(search, base = 'http://localhost/') {
  /** @type {Record<string, string>} no prototype: any name is just a key (`constructor`, `toString`) */
  const controls = Object.create(null);
  /** @type {UrlParams} */
  const out = { controls, channels: [], warnings: [] };
  const warn = (key, value, why) => {
    const instead = INSTEAD[key] ?? (CHANNEL_PARAMS.includes(key) ? 'the channel is black' : '');
    out.warnings.push(`URL parameter ${key}=${value} ignored: ${why}${instead ? `; ${instead}` : ''}`);
  };
  const clamped = (key, value, used) => out.warnings.push(`URL parameter ${key}=${value} is out of range: using ${used}`);
  const number = (key, value, min, max, what) => {
    const n = finiteNumbers(value);
    if (!n || n.length !== 1) {
      warn(key, value, `expected ${what}`);
      return undefined;
    }
    const v = Math.min(max, Math.max(min, n[0]));
    if (v !== n[0]) clamped(key, value, v);
    return v;
  };

  const entries = [...new URLSearchParams(search)];
  const last = new Map(entries.map(([key, value], i) => [key, { value, i }]));
  for (const [i, [key, value]] of entries.entries()) {
    const kept = /** @type {{value: string, i: number}} */ (last.get(key)); // every key is in `last`
    if (kept.i !== i) {
      warn(key, value, `${key} is given more than once; the last one is used (${key}=${kept.value})`);
      continue;
    }
    if (key === 'time') {
      const t = number(key, value, 0, MAX_TIME, 'a number of seconds');
      if (t !== undefined) out.time = t;
    } else if (key === 'mouse') {
      const m = finiteNumbers(value);
      if (m && (m.length === 4 || m.length === 2)) {
        const mouse = (m.length === 4 ? m : [...m, 0, 0]).map((v) => Math.min(MAX_MOUSE, Math.max(-MAX_MOUSE, v)));
        if (mouse.some((v, i) => v !== m[i] && i < m.length)) clamped(key, value, mouse.join(','));
        out.mouse = mouse;
      } else warn(key, value, 'expected x,y,z,w (finite numbers, device pixels)');
    } else if (key === 'size') {
      const m = value.trim().match(/^(\d{1,9})\s*[xX×]\s*(\d{1,9})$/);
      const [width, height] = m ? [Number(m[1]), Number(m[2])] : [0, 0];
      if (width >= 1 && height >= 1) {
        const size = clampSize({ width, height });
        if (size.width !== width || size.height !== height)
          clamped(key, value, `${size.width}x${size.height} (at most ${MAX_SIZE} px a side and ${MAX_PIXELS / 1e6} megapixels)`);
        out.size = size;
      } else warn(key, value, `expected WxH, whole device pixels of at least 1`);
    } else if (key === 'scale') {
      const s = number(key, value, MIN_SCALE, MAX_SCALE, `a number in ${MIN_SCALE} .. ${MAX_SCALE}`);
      if (s !== undefined) out.scale = s;
    } else if (key === 'cap') {
      // 0 is "no cap" (the panel's choice too), not a cap clamped up to MIN_CAP
      const noCap = value.trim() !== '' && Number(value) === 0;
      const c = noCap ? 0 : number(key, value, MIN_CAP, MAX_SIZE, `0 (no cap) or whole device pixels, ${MIN_CAP} .. ${MAX_SIZE}`);
      if (c !== undefined) out.cap = Math.round(c);
    } else if (key === 'speed') {
      const s = number(key, value, 0, MAX_SPEED, `a number in 0 .. ${MAX_SPEED}`);
      if (s !== undefined) out.speed = s;
    } else if (key === 'date') {
      // ISO 8601 (what Date.parse reads everywhere): a date alone, or with a time and a zone
      const ms = /^\d{4}-\d{2}-\d{2}/.test(value.trim()) ? Date.parse(value.trim()) : NaN;
      if (Number.isFinite(ms)) out.date = ms;
      else warn(key, value, 'expected an ISO 8601 date, such as 2024-01-15T12:00:00Z');
    } else if (key === 'fps') {
      const f = number(key, value, MIN_FPS, MAX_FPS, `frames a second, ${MIN_FPS} .. ${MAX_FPS}`);
      if (f !== undefined) out.fps = f;
    } else if (key === 'media') {
      const checked = value.trim() ? sameOriginUrl(value.trim(), base) : { url: null, why: 'empty' };
      if (checked.url === null) warn(key, value, checked.why);
      else out.media = value.trim();
    } else if (key === 'shader' || CHANNEL_PARAMS.includes(key)) {
      const checked = value.trim() ? sameOriginUrl(value.trim(), base) : { url: null, why: 'empty' };
      if (checked.url === null) {
        warn(key, value, checked.why);
        // the page says so too (main.js), not only the console
        if (key === 'shader') out.refusedShader = { url: value, why: checked.why };
      } else if (key === 'shader') out.shader = value.trim();
      else out.channels[CHANNEL_PARAMS.indexOf(key)] = value.trim();
    } else if (!/^[A-Za-z_]\w*$/.test(key)) {
      warn(key, value, 'not a page parameter or a shader control name');
    } else if (RESERVED_NAME.test(key)) {
      warn(key, value, 'not a page parameter, and GLSL reserves the name (gl_ prefix or two underscores), so no shader control has it');
    } else {
      controls[key] = value;
    }
  }
  return out;
}

function formatNumber(v) {
  // short but exact enough to reproduce a frame: at most 6 decimals, no trailing zeros
  return Number.isInteger(v) ? String(v) : String(Number(v.toFixed(6)));
}

/**
 * The query string (with its `?`) for a view, the inverse of parseUrlParams.
 * @param {object} state
 * @param {string | null} [state.shader] the shader's URL as the page was given it (omitted: built-in)
 * @param {{width:number, height:number} | null} [state.size] a fixed drawing buffer, device pixels (omitted: the window's)
 * @param {number | null} [state.time] a fixed time (omitted: the link plays, from 0)
 * @param {number[]} [state.mouse] iMouse; omitted when all zero
 * @param {number} [state.speed] omitted when 1
 * @param {number | null} [state.date] a fixed iDate at iTime 0, ms since 1970 (omitted: the real date)
 * @param {number | null} [state.fps] a fixed frame schedule (omitted: measured)
 * @param {(string | null | undefined)[]} [state.channels] image URLs
 * @param {string | null} [state.media] the site's media folder's URL
 * @param {Record<string, unknown>} [state.controls] control values to write (vectors as arrays, a
 *   choice by its name as a string)
 */
export function formatUrlParams({
  shader,
  size,
  time,
  mouse,
  speed = 1,
  date = null,
  fps = null,
  channels = [],
  media = null,
  controls = {},
}) {
  const query = new URLSearchParams();
  if (shader) query.set('shader', shader);
  if (size) query.set('size', `${size.width}x${size.height}`);
  if (time !== undefined && time !== null) query.set('time', formatNumber(time));
  if (mouse && mouse.some((v) => v !== 0)) query.set('mouse', mouse.map(formatNumber).join(','));
  if (speed !== 1) query.set('speed', formatNumber(speed));
  if (date !== null) query.set('date', new Date(date).toISOString());
  if (fps !== null) query.set('fps', formatNumber(fps));
  channels.forEach((url, i) => url && query.set(CHANNEL_PARAMS[i], url));
  if (media) query.set('media', media);
  for (const [name, value] of Object.entries(controls)) {
    const text = Array.isArray(value)
      ? value.map(formatNumber).join(',')
      : typeof value === 'boolean' || typeof value === 'string'
        ? String(value)
        : formatNumber(value);
    query.set(name, text);
  }
  return `?${query.toString().replaceAll('%2C', ',').replaceAll('%2F', '/')}`;
}
