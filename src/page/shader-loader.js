// Getting a shader's text: from a URL the page's own server serves (?shader=, and a reload when
// the dev server says the file changed), or from a file dropped on the page. And an image for a
// channel, from a URL or a file.

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
 * Fetches a shader's text from the page's own server. Rejects with a readable reason: another
 * origin, a network failure, an HTTP error, or an HTML page (a dev server answers a missing file
 * with its index page).
 */
export async function fetchShader(url) {
  const resolved = new URL(url, location.href);
  if (resolved.origin !== location.origin) throw new Error(`only files served by this page's server (${location.origin}) can be loaded`);
  let response;
  try {
    response = await fetch(resolved, { cache: 'no-cache', headers: { Accept: 'text/plain, */*;q=0.1' } });
  } catch (error) {
    throw new Error(`the request failed (${error.message})`, { cause: error });
  }
  if (!response.ok) throw new Error(`the server answered HTTP ${response.status}${response.statusText ? ` ${response.statusText}` : ''}`);
  const text = await response.text();
  const type = response.headers.get('content-type') ?? '';
  if (/text\/html/i.test(type) || /^\s*<!doctype html/i.test(text)) throw new Error('no such file (the server answered with a web page)');
  return text;
}

/**
 * Loads and decodes an image for a channel.
 * @param {string | Blob} source a URL, or a File or Blob (a dropped or chosen file)
 * @returns {Promise<HTMLImageElement>} rejects with a readable reason when it is not an image
 */
export async function loadImage(source) {
  const isUrl = typeof source === 'string';
  const url = isUrl ? source : URL.createObjectURL(source);
  try {
    const image = new Image();
    image.src = url;
    await image.decode().catch(() => {
      throw new Error(`cannot load ${isUrl ? source : 'name' in source ? source.name : 'the image'} as an image`);
    });
    return image;
  } finally {
    if (!isUrl) setTimeout(() => URL.revokeObjectURL(url), 0);
  }
}

const SHADER_EXTENSIONS = /\.(glsl|frag|fs|fsh|txt|shader)$/i;

/** What a dropped file is: 'shader', 'image', or null (neither). */
export function droppedKind(file) {
  if (file.type.startsWith('image/')) return 'image';
  if (SHADER_EXTENSIONS.test(file.name) || file.type.startsWith('text/')) return 'shader';
  return null;
}
