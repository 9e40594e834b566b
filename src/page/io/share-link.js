// "Copy link": the URL that reproduces this view (url-params.js), and what it cannot carry.
//
// A shader that came from a URL is named by ?shader=. An edited, pasted or dropped one travels in
// the link itself: its text compressed with the browser's CompressionStream ('deflate-raw'),
// base64url, in the fragment (#source=...&name=...). A multipass shader (or one with channels of
// its own) travels the same way as its Shadertoy JSON export, which the page reads back as such
// (project-files.js: a text that looks like JSON is one). A fragment is never sent to a server, so
// the dev server's limit on a request's headers (it answers HTTP 431 to an over-long URL) does
// not apply; the page reads it on open (main.js).
//
// The size is pinned (?size=) only when the user fixed one: a window's size is the sender's, and
// a phone opening a desktop-sized canvas would see it squeezed with Scale and Max size disabled.
// The time likewise: a link from a playing page opens playing (a feedback shader then runs from
// its first frame, as the sender's did), one from a paused page at that instant, paused.

import { formatUrlParams } from './url-params.js';
import { exportJson, serializeProject } from './project-files.js';
import { fileStem } from './file-names.js';
import { linkValues } from '../app/control-values.js';

/**
 * Longest link we hand out, in characters. Fragments are not sent to servers, but a link still
 * passes through address bars, chat and mail clients, and the servers of link previews that keep
 * the whole thing: RFC 9110 §4.1 asks senders and recipients to support "at a minimum, URIs with
 * lengths of 8000 octets", the common floor; longer links are cut or refused in some of them.
 */
export const MAX_LINK_LENGTH = 8000;

/** @param {Uint8Array} bytes */
function toBase64Url(bytes) {
  let binary = '';
  for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(binary).replaceAll('+', '-').replaceAll('/', '_').replace(/=+$/, '');
}

/** @param {string} text */
function fromBase64Url(text) {
  const binary = atob(text.replaceAll('-', '+').replaceAll('_', '/'));
  return Uint8Array.from(binary, (c) => c.charCodeAt(0));
}

/**
 * @param {Uint8Array<ArrayBuffer>} bytes
 * @param {CompressionStream | DecompressionStream} stream
 */
async function pipe(bytes, stream) {
  const out = new Response(new Blob([bytes]).stream().pipeThrough(stream));
  return new Uint8Array(await out.arrayBuffer());
}

/** A shader's text as it goes in a link: deflate-raw, base64url. @param {string} source */
export async function encodeSource(source) {
  return toBase64Url(await pipe(new TextEncoder().encode(source), new CompressionStream('deflate-raw')));
}

/**
 * The inverse of encodeSource. Rejects, saying what is wrong in words (not the browser's
 * "Failed to fetch" or atob's exception), on anything that is not one: text that is not
 * base64url, or data that does not inflate to UTF-8 (most often a link cut short).
 * @param {string} encoded
 */
export async function decodeSource(encoded) {
  let bytes;
  try {
    bytes = fromBase64Url(encoded);
  } catch (error) {
    throw new Error('its #source= is not a shader this page wrote (it is not base64url text)', { cause: error });
  }
  try {
    return new TextDecoder('utf-8', { fatal: true }).decode(await pipe(bytes, new DecompressionStream('deflate-raw')));
  } catch (error) {
    throw new Error(`its #source= does not unpack to a shader: the link is cut short or damaged (${encoded.length} characters)`, {
      cause: error,
    });
  }
}

/**
 * The shader a link carries in its fragment (#source=...&name=...), or null when it has none.
 * Rejects when the fragment holds a source that cannot be read.
 * @param {string} hash location.hash
 * @returns {Promise<{source: string, name: string} | null>}
 */
export async function sourceFromHash(hash) {
  const fields = new URLSearchParams(hash.replace(/^#/, ''));
  const encoded = fields.get('source');
  if (!encoded) return null;
  return { source: await decodeSource(encoded), name: fields.get('name') || 'shared.glsl' };
}

/**
 * The link for the app's current view, and what it leaves out.
 * @param {import('../app/app.js').RaytracerApp} app
 * @returns {Promise<{url: string, omitted: string[], tooLong: boolean}>}
 */
export async function shareLink(app) {
  const inLink = app.origin === 'editor' || app.origin === 'file';
  const query = formatUrlParams({
    shader: app.origin === 'url' ? app.shaderUrl : null,
    size: app.canvasSize.fixed,
    // a playing page's link plays; a paused one (the user fixed the time) shows that instant
    time: app.inputs.playing ? null : app.inputs.time,
    mouse: app.inputs.mouse(),
    speed: app.inputs.speed,
    channels: app.channels.urls,
    controls: linkValues(app.controls, app.values),
  });
  let fragment = '';
  if (inLink) {
    // a plain shader as its text; any other as its JSON export (serializeProject tells them apart)
    const plain = serializeProject(app.project) === app.source;
    const text = plain ? app.source : exportJson(app.project, app.projectInfo, fileStem(app.fileName), 0);
    const fields = new URLSearchParams({ source: await encodeSource(text), name: app.fileName });
    fragment = `#${fields.toString()}`;
  }
  const url = `${location.origin}${location.pathname}${query}${fragment}`;
  /** @type {string[]} */
  const omitted = [];
  for (let i = 0; i < 4; i++) {
    if (app.channels.inUse(i) && !app.channels.urls[i]) omitted.push(`the image in iChannel${i}`);
  }
  return { url, omitted, tooLong: url.length > MAX_LINK_LENGTH };
}
