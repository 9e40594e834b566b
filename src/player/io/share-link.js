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
// An edit of a shader the page ships (its built-in shader, a ?shader= file) goes as a patch
// against that file instead, when that is shorter: the studio's is ~34,000 characters deflated
// and base64url'd, past MAX_LINK_LENGTH, and a few changed lines are a few hundred
// (#patch=...&base=builtin|URL&hash=...&name=...). The patch is a unified diff (jsdiff); `hash`
// names the version it was made against, and a page with another version says so, and applies it
// where its context still matches.
//
// The size is pinned (?size=) only when the user fixed one: a window's size is the sender's, and
// a phone opening a desktop-sized canvas would see it squeezed with Scale and Max size disabled.
// The time likewise: a link from a playing page opens playing (a feedback shader then runs from
// its first frame, as the sender's did), one from a paused page at that instant, paused.

import { applyPatch, createPatch } from 'diff';
import { formatUrlParams } from '../../shared/url-params.js';
import { textHash } from './kept-source.js';
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
async function decodeSource(encoded) {
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

/** The `base` of a patch link for the page's built-in shader (any other base is the ?shader= URL). */
export const BUILTIN_BASE = 'builtin';
/** Lines of context around each change in a patch: enough to place it in a file that moved on. */
const PATCH_CONTEXT = 3;
/** Context lines a hunk may miss in another version of its file and still apply (jsdiff's fuzzFactor). */
const PATCH_FUZZ = 2;

/**
 * The shader a link carries in its fragment (#source=..., or #patch=... against a file the page
 * ships), or null when it has none. Rejects, in words, when the fragment holds a source that
 * cannot be read or a patch that does not apply. `note` says when the patch was made against
 * another version of its file and applied all the same.
 * @param {string} hash location.hash
 * @param {(base: string) => Promise<string>} [baseText] the text of a patch's base (BUILTIN_BASE or a URL)
 * @returns {Promise<{source: string, name: string, note?: string} | null>}
 */
export async function sourceFromHash(hash, baseText = () => Promise.reject(new Error('no base files here'))) {
  const fields = new URLSearchParams(hash.replace(/^#/, ''));
  const name = fields.get('name') || 'shared.glsl';
  const encoded = fields.get('source');
  if (encoded) return { source: await decodeSource(encoded), name };
  const patch = fields.get('patch');
  if (!patch) return null;
  const base = fields.get('base') || BUILTIN_BASE;
  const baseName = base === BUILTIN_BASE ? "the page's built-in shader" : base;
  const diff = await decodeSource(patch).catch((error) => {
    throw new Error(error.message.replace('#source=', '#patch='), { cause: error });
  });
  const original = await baseText(base);
  const sameVersion = textHash(original) === fields.get('hash');
  const source = applyPatch(original, diff, { fuzzFactor: sameVersion ? 0 : PATCH_FUZZ });
  if (source === false)
    throw new Error(
      sameVersion
        ? `its edit of ${baseName} does not apply to it (the patch is damaged)`
        : `its edit of ${baseName} was made against another version of it than this page has, and does not apply to this one`,
    );
  const note = sameVersion
    ? undefined
    : `This link's edit of ${baseName} was made against another version of it than this page has; it applied, but what it changes may differ from what its sender saw.`;
  return { source, name, note };
}

/**
 * The fragment that carries a plain shader's text: its edit as a patch against the file it came
 * from, when the page ships that file and the patch is the shorter, else the whole text.
 * @param {string} source
 * @param {string} name
 * @param {{base: string, source: string} | null} shipped the file the text is an edit of, if the page ships it
 */
export async function textFragment(source, name, shipped) {
  const whole = new URLSearchParams({ source: await encodeSource(source), name });
  if (!shipped) return whole;
  const diff = createPatch(name, shipped.source, source, undefined, undefined, { context: PATCH_CONTEXT });
  const patch = new URLSearchParams({ patch: await encodeSource(diff), base: shipped.base, hash: textHash(shipped.source), name });
  return patch.toString().length < whole.toString().length ? patch : whole;
}

/**
 * The link for the app's current view, and what it leaves out.
 * @param {import('../app/app.js').ShaderApp} app
 * @param {{base: string, source: string} | null} [shipped] the file the page ships that the
 *   editor's text is an edit of (BUILTIN_BASE, or its ?shader= URL), if it is one
 * @returns {Promise<{url: string, omitted: string[], tooLong: boolean}>}
 */
export async function shareLink(app, shipped = null) {
  const inLink = app.origin === 'editor' || app.origin === 'file';
  const query = formatUrlParams({
    shader: app.origin === 'url' ? app.shaderUrl : null,
    size: app.canvasSize.fixed,
    // a playing page's link plays; a paused one (the user fixed the time) shows that instant
    time: app.inputs.playing ? null : app.inputs.time,
    mouse: app.inputs.mouse(),
    speed: app.inputs.speed,
    date: app.inputs.fixedDate,
    fps: app.inputs.fixedFps,
    channels: app.channels.urls,
    media: app.media.given,
    controls: linkValues(app.controls, app.values),
  });
  let fragment = '';
  if (inLink) {
    // a plain shader as its text; any other as its JSON export (serializeProject tells them apart)
    const plain = serializeProject(app.project) === app.source;
    const fields = plain
      ? await textFragment(app.source, app.fileName, shipped)
      : new URLSearchParams({
          source: await encodeSource(exportJson(app.project, app.projectInfo, fileStem(app.fileName), 0)),
          name: app.fileName,
        });
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
