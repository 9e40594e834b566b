// Getting a shader's text: from a URL the page's own server serves (?shader=, and a reload when
// the dev server says the file changed), or from a file dropped on the page. And an image for a
// channel, from a URL or a file. A URL is of the page's own server, never another origin (not
// even through a redirect), and a load that gets no answer ends after TIMEOUTS.loadMs with a
// message rather than waiting for ever.

import { TIMEOUTS } from '../../shared/timeouts.js';
import { channelKind } from '../inputs/media-kind.js';

/** The name a shader goes by in messages and downloads: its URL's last path segment. */
export function shaderName(url) {
  try {
    const path = new URL(url, location.href).pathname;
    return decodeURIComponent(path.slice(path.lastIndexOf('/') + 1)) || url;
  } catch {
    return url;
  }
}

/**
 * @typedef {object} LoadOptions
 * @property {number} [timeoutMs] give up after this long (default TIMEOUTS.loadMs: src/shared/timeouts.js)
 */

const ownOrigin = () => `only files served by this page's server (${location.origin}) can be loaded`;

/**
 * Fetches a file of the page's own server and reads its body, within `timeoutMs` for the whole
 * (headers and body). Refuses another origin up front, and one reached by a redirect.
 * @template T
 * @param {string} url
 * @param {{accept: string, timeoutMs: number}} options
 * @param {(response: Response) => Promise<T>} read
 * @returns {Promise<{response: Response, body: T}>}
 */
async function fetchOwn(url, { accept, timeoutMs }, read) {
  const resolved = new URL(url, location.href);
  if (resolved.origin !== location.origin) throw new Error(ownOrigin());
  const signal = AbortSignal.timeout(timeoutMs);
  try {
    // mode 'no-cors': a redirect to another origin then ends in an opaque response, refused
    // below without a sound. A 'cors' or 'same-origin' request would fail on it with a console
    // error ("blocked by CORS policy", "Unsafe attempt to load URL"), indistinguishable from a
    // network failure; an <img> would load it and leave the texture upload to fail. Same-origin
    // responses (and same-origin redirects) are read as usual.
    const response = await fetch(resolved, { mode: 'no-cors', cache: 'no-cache', headers: { Accept: accept }, signal });
    if (response.type === 'opaque' || new URL(response.url).origin !== location.origin) {
      throw new Error(`the server redirected it to another origin; ${ownOrigin()}`);
    }
    if (!response.ok) throw new Error(`the server answered HTTP ${response.status}${response.statusText ? ` ${response.statusText}` : ''}`);
    return { response, body: await read(response) };
  } catch (error) {
    if (signal.aborted) throw new Error(`the server did not answer within ${timeoutMs / 1000} s`, { cause: error });
    if (error instanceof TypeError) throw new Error(`the request failed (${error.message})`, { cause: error });
    throw error;
  }
}

const isWebPage = (response, text = '') =>
  /text\/html/i.test(response.headers.get('content-type') ?? '') || /^\s*<!doctype html/i.test(text);
/** A dev server answers a missing file with its index page. */
const NO_SUCH_FILE = 'no such file (the server answered with a web page)';

/**
 * Fetches a shader's text from the page's own server. Rejects with a readable reason: another
 * origin (asked for, or reached by a redirect), a network failure, no answer within
 * TIMEOUTS.loadMs, an HTTP error, or an HTML page.
 * @param {string} url
 * @param {LoadOptions} [options]
 * @returns {Promise<string>}
 */
export async function fetchShader(url, { timeoutMs = TIMEOUTS.loadMs } = {}) {
  const { response, body } = await fetchOwn(url, { accept: 'text/plain, */*;q=0.1', timeoutMs }, (r) => r.text());
  if (isWebPage(response, body)) throw new Error(NO_SUCH_FILE);
  return body;
}

/**
 * Loads and decodes an image for a channel, as the pixels of the file: no colour-space
 * conversion, no premultiplied alpha (a channel holds data as much as pictures). The result is
 * an ImageBitmap, so it can be transferred to a worker. Its rows are flipped (bottom row
 * first), as Shadertoy uploads a channel: texture(iChannelN, vec2(u, 1)) is the image's top.
 * WebGL ignores UNPACK_FLIP_Y_WEBGL for an ImageBitmap, and three.js skips texture.flipY for
 * one, so the flip has to be in the bitmap.
 * A URL must be of the page's own server, and not redirect elsewhere; it gets TIMEOUTS.loadMs.
 * @param {string | Blob} source a URL, or a File or Blob (a dropped or chosen file)
 * @param {LoadOptions} [options]
 * @returns {Promise<ImageBitmap>} rejects with a readable reason when it cannot be had or is not an image
 */
async function loadImage(source, { timeoutMs = TIMEOUTS.loadMs } = {}) {
  const name = typeof source === 'string' ? shaderName(source) : 'name' in source ? source.name : 'the image';
  let blob = source;
  if (typeof source === 'string') {
    const { response, body } = await fetchOwn(source, { accept: 'image/*, */*;q=0.1', timeoutMs }, (r) => r.blob());
    if (isWebPage(response)) throw new Error(NO_SUCH_FILE);
    blob = body;
  }
  try {
    return await createImageBitmap(/** @type {Blob} */ (blob), IMAGE_DECODING);
  } catch (error) {
    throw new Error(`cannot load ${name} as an image`, { cause: error });
  }
}

/**
 * Loads a channel's file by its kind (inputs/media-kind.js: its type, else its name): an image
 * decoded (loadImage), or a video's or music's bytes, for src/player/inputs/ to decode. A URL as
 * for loadImage: the page's own server, TIMEOUTS.loadMs.
 * @param {string | Blob} source a URL, or a File or Blob
 * @param {LoadOptions} [options]
 * @returns {Promise<ImageBitmap | import('../app/channels.js').MediaFile>}
 */
export async function loadChannel(source, { timeoutMs = TIMEOUTS.loadMs } = {}) {
  const name = typeof source === 'string' ? shaderName(source) : source instanceof File ? source.name : 'the file';
  const kind = channelKind(typeof source === 'string' ? { name: source } : { name, type: source.type });
  if (kind === 'image') return loadImage(source, { timeoutMs });
  if (typeof source !== 'string') return { kind, blob: source, name };
  const { response, body } = await fetchOwn(source, { accept: '*/*', timeoutMs }, (r) => r.blob());
  if (isWebPage(response)) throw new Error(NO_SUCH_FILE);
  return { kind, blob: body, name };
}

/**
 * A media file's bytes (the site's media from a media folder: inputs/media-library.js), from the
 * page's own server as every file, within `timeoutMs`.
 * @param {string} url
 * @param {LoadOptions} [options]
 * @returns {Promise<Blob>} rejects with a readable reason
 */
export async function fetchMedia(url, { timeoutMs = TIMEOUTS.loadMs } = {}) {
  const { response, body } = await fetchOwn(url, { accept: '*/*', timeoutMs }, (r) => r.blob());
  if (isWebPage(response)) throw new Error(NO_SUCH_FILE);
  return body;
}

/** @type {ImageBitmapOptions} */
const IMAGE_DECODING = { imageOrientation: 'flipY', colorSpaceConversion: 'none', premultiplyAlpha: 'none' };

const SHADER_EXTENSIONS = /\.(glsl|frag|fs|fsh|txt|shader)$/i;

/**
 * What a dropped file is: 'shader', 'json' (Shadertoy's JSON export, by its name or type),
 * 'image', 'video' or 'music' (a channel's: inputs/media-kind.js), or null (none of them).
 * @param {{name: string, type: string}} file
 */
export function droppedKind(file) {
  if (file.type.startsWith('image/')) return 'image';
  const media = channelKind(file);
  if (media !== 'image') return media;
  if (/\.json$/i.test(file.name) || file.type === 'application/json') return 'json';
  if (SHADER_EXTENSIONS.test(file.name) || file.type.startsWith('text/')) return 'shader';
  return null;
}
