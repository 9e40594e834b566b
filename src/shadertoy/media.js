// The site's media library as data: which files a channel's input names, and the site's binary
// volume format. Pure: the page (src/player/inputs/media-library.js) fetches and decodes, the
// render worker (src/player/gpu/channels/media-textures.js) uploads, the command line (src/api/media.js)
// finds and downloads the same files by these paths.
//
// What the site's player does with each kind (https://www.shadertoy.com/js/effect.js,
// EffectPass.NewTexture, and piLibs.js's CreateTextureFromImage / CreateTexture):
// - a texture is one image, uploaded RGBA8 (four grey noise textures by their asset ids as one
//   channel, R8), flipped when its sampler says vflip, never colour-converted nor premultiplied;
// - a cubemap is six images: `<hash>.<ext>` and `<hash>_1.<ext>` … `_5`, uploaded to +X, −X, +Y,
//   −Y, +Z, −Z in that order, each flipped when vflip says so; with vflip the +Y and −Y images
//   trade places (a flipped face turns the cube upside down, so the top face is the bottom one);
// - a volume is the site's `.bin`: a 20-byte header (a signature, then width, height and depth
//   as uint32, channels as uint8, a layout byte, a format uint16: 0 for bytes, 10 for float32),
//   then the texels, x fastest, then y, then z;
// - the sampler's filter, wrap and vflip apply as read (Sampler2Renderer); its `srgb` is read and
//   kept but applied by nothing there, so not here either.

/**
 * How the page says that a channel's media needs a media folder, and that a file is not in the
 * one it has: the command line, which knows what --media and --fetch-media were given, says the
 * same in its own words (src/api/media.js commandLineWords).
 */
export const MEDIA_WORDS = Object.freeze({
  noFolder: "needs the site's media: give a media folder (shaderproof --media DIR, or the page's ?media=URL)",
  notInFolder: 'is not in the media folder',
});

/** The site's media paths: `/media/a/<hash>.<ext>` (and the older `/presets/…` previews). */
const SITE_MEDIA = /^\/media\/(.+)$/;

/**
 * The asset ids the site uploads as one channel (R8), not RGBA (effect.js NewTexture: the grey
 * noise textures): their .gba read (0, 0, 1) as any R8 texture's.
 */
const ONE_CHANNEL_TEXTURES = new Set(['Xdf3zn', '4sf3Rn', '4dXGzn', '4sf3Rr']);

/** The volume format's header size in bytes, and its format codes. */
const VOLUME_HEADER_BYTES = 20;
const VOLUME_FORMATS = /** @type {const} */ ({ 0: 'byte', 10: 'float' });

/**
 * A site media path as a path inside a media folder (`/media/a/x.png` → `a/x.png`), or null
 * for a path that is not the site's media (or that would leave the folder).
 * @param {string} src the input's `filepath` (or `src`), or a full URL of the site
 */
export function mediaPath(src) {
  let path = String(src ?? '');
  try {
    path = new URL(path, 'https://www.shadertoy.com').pathname;
  } catch {
    return null;
  }
  const match = SITE_MEDIA.exec(path);
  if (!match) return null;
  let inside;
  try {
    inside = decodeURIComponent(match[1]);
  } catch {
    return null; // a stray "%": no file of the site's
  }
  // a path that could leave the folder (.., a backslash or a drive on Windows) names no file of the site's
  if (inside.split('/').some((part) => part === '..' || part === '' || part === '.' || /[\\:]/.test(part))) return null;
  return inside;
}

/**
 * A media-folder path as a URL path again (each segment encoded: a name may hold # or %).
 * @param {string} path a path mediaPath or mediaFiles gave
 */
export const mediaUrlPath = (path) => path.split('/').map(encodeURIComponent).join('/');

/**
 * The files a channel's input is made of, as media-folder paths: one for a texture, volume,
 * video or music, six for a cubemap (its faces in the site's order). Empty for a path that is not
 * the site's media.
 * @param {{kind: string, src: string}} channel
 * @returns {string[]}
 */
export function mediaFiles({ kind, src }) {
  const path = mediaPath(src);
  if (!path) return [];
  return kind === 'cubemap' ? cubeFaceFiles(path) : [path];
}

/**
 * A cubemap's six files from its first: `sky.png`, then `sky_1.png` … `sky_5.png` beside it.
 * @param {string} first a path (or a file's name) of the first face
 */
export function cubeFaceFiles(first) {
  const dot = first.lastIndexOf('.');
  const [stem, ext] = dot > first.lastIndexOf('/') ? [first.slice(0, dot), first.slice(dot)] : [first, ''];
  return [first, ...[1, 2, 3, 4, 5].map((i) => `${stem}_${i}${ext}`)];
}

/** The kinds the media library holds that are still: uploaded once (src/player/gpu/channels/media-textures.js). */
export const LIBRARY_KINDS = Object.freeze(['texture', 'cubemap', 'volume']);
/**
 * The kinds it holds that move: a video's frame and music's 512 × 2 texture at each frame's iTime
 * (src/player/inputs/media-input.js). A music stream (SoundCloud) and the devices are not files.
 */
export const MOVING_LIBRARY_KINDS = Object.freeze(['video', 'music']);

/**
 * Whether the site uploads a texture as one channel (R8), by the input's asset id.
 * @param {string | undefined} id
 */
export const isOneChannelTexture = (id) => ONE_CHANNEL_TEXTURES.has(String(id));

/**
 * The cubemap faces in upload order (+X, −X, +Y, −Y, +Z, −Z) from the six files in the site's
 * order, with the site's swap of the Y faces when they are flipped.
 * @template T
 * @param {T[]} files
 * @param {boolean} vflip
 * @returns {T[]}
 */
export function cubeFaceOrder(files, vflip) {
  if (files.length !== 6) throw new Error(`a cubemap has six faces, not ${files.length}`);
  return vflip ? [files[0], files[1], files[3], files[2], files[4], files[5]] : [...files];
}

/**
 * @typedef {{width: number, height: number, depth: number, channels: 1 | 2 | 3 | 4,
 *   format: 'byte' | 'float', data: Uint8Array | Float32Array}} Volume
 */

/**
 * Reads the site's binary volume format. Throws a readable reason for a file that is not one.
 * @param {ArrayBuffer} buffer
 * @returns {Volume}
 */
export function parseVolume(buffer) {
  if (buffer.byteLength < VOLUME_HEADER_BYTES) throw new Error(`not a volume: ${buffer.byteLength} bytes, shorter than its header`);
  const view = new DataView(buffer);
  const [width, height, depth] = [4, 8, 12].map((at) => view.getUint32(at, true));
  const channels = view.getUint8(16);
  const format = VOLUME_FORMATS[/** @type {0 | 10} */ (view.getUint16(18, true))];
  if (!(channels >= 1 && channels <= 4)) throw new Error(`not a volume: ${channels} channels (1 to 4)`);
  if (!format) throw new Error(`not a volume: format ${view.getUint16(18, true)} (0: bytes, 10: float)`);
  if (!(width && height && depth)) throw new Error(`not a volume: its size is ${width}x${height}x${depth}`);
  const bytes = width * height * depth * channels * (format === 'float' ? 4 : 1);
  if (buffer.byteLength - VOLUME_HEADER_BYTES < bytes)
    throw new Error(
      `a ${width}x${height}x${depth} volume of ${channels} channels needs ${bytes} bytes of texels, the file has ${buffer.byteLength - VOLUME_HEADER_BYTES}`,
    );
  const data =
    format === 'float'
      ? new Float32Array(buffer.slice(VOLUME_HEADER_BYTES, VOLUME_HEADER_BYTES + bytes))
      : new Uint8Array(buffer, VOLUME_HEADER_BYTES, bytes);
  return { width, height, depth, channels: /** @type {1 | 2 | 3 | 4} */ (channels), format, data };
}

/**
 * A volume in the site's binary format (the inverse of parseVolume), for tests and tools that
 * make media of their own.
 * @param {Omit<Volume, 'format'> & {format?: 'byte' | 'float'}} volume
 */
export function writeVolume({ width, height, depth, channels, format = 'byte', data }) {
  const body = format === 'float' ? new Uint8Array(Float32Array.from(data).buffer) : Uint8Array.from(data);
  const out = new Uint8Array(VOLUME_HEADER_BYTES + body.length);
  const view = new DataView(out.buffer);
  view.setUint32(0, 0x004e4942, true); // "BIN\0"
  view.setUint32(4, width, true);
  view.setUint32(8, height, true);
  view.setUint32(12, depth, true);
  view.setUint8(16, channels);
  view.setUint16(18, format === 'float' ? 10 : 0, true);
  out.set(body, VOLUME_HEADER_BYTES);
  return out;
}
