// `shaderproof render SHADER -o OUT.png`: one still of a shader, as the page draws it. The view
// goes into the page's URL (view-options.js) and is drawn by drawView, as the render tests' views
// are; --frame N is frame N as the recorder draws it (iTime = N / fps, iFrame = N), every frame
// before it drawn first for a shader with buffers; --converge N and --frame N are long work
// (long-work.js: no limit but the watchdog, progress on a terminal).

import fs from 'node:fs';
import path from 'node:path';
import { runLong } from '../headless/long-work.js';
import { hungLine } from '../headless/watchdog/limits.js';
import { writePng, writeWhole } from '../headless/png.js';
import { fromBase64 } from '../shared/pixels.js';
import { io, progressBar } from './io.js';
import { commandLineWords, mediaFolders, withLibraryChannels } from './media.js';
import { ShaderproofError, shaderKind } from '../headless/session.js';
import { UsageError, viewQuery } from './view-options.js';

/**
 * Draws the shader `file` at `view` and returns the image and what the page said.
 * @param {import('../headless/session.js').Session} session
 * @param {string} file
 * @param {import('./view-options.js').ViewOptions} view
 * @param {{converge?: number | null, progress?: boolean, say?: (line: string) => void}} [options]
 *   converge: N progressive samples a pixel (the page's "Converge when still", for a shader with
 *   a progressive form); progress: a bar on a terminal for long work; say: hears what is fetched
 *   for the shader (media.js)
 * @returns {Promise<{width: number, height: number, data: Uint8Array, info: any,
 *   notes: import('../headless/view.js').PageNote[]}>}
 */
export async function renderShader(session, file, view, { converge = null, progress = false, say = io.err } = {}) {
  shaderKind(file);
  const mount = (f) => {
    if (!fs.existsSync(f)) throw new ShaderproofError(`${f}: no such file`);
    return session.server.mount(f);
  };
  // a volume or a cubemap in --channelN: the shader as the JSON whose Image pass reads it (media.js)
  const wrapped = withLibraryChannels(file, view.channels);
  const shaderUrl = wrapped ? session.server.mountText(wrapped.json, path.basename(file)) : session.server.mount(path.resolve(file));
  const folders = [...(await mediaFolders(file, view.media, say)), ...(wrapped?.mounts ?? [])];
  const drawnView = wrapped ? { ...view, channels: wrapped.rest } : view;
  const query = viewQuery(shaderUrl, drawnView, mount, folders.length ? session.server.mountFolders(folders) : null);
  let image;
  try {
    image = await session.draw(query);
  } catch (error) {
    if (error instanceof ShaderproofError)
      error.message = error.hung ? `${file}: ${error.message}` : userMessage(error.message.replaceAll(shaderUrl, file), file);
    throw error;
  }
  image.notes = image.notes.map((note) => ({ ...note, lines: note.lines.map((line) => commandLineWords(line, view.media)) }));
  const missing = view.controls.filter(([name]) => !(name in (image.info.controls ?? {}))).map(([name]) => name);
  if (missing.length) {
    const known = Object.keys(image.info.controls ?? {});
    throw new UsageError(
      `--set ${missing.join(', ')}: ${path.basename(file)} has no such control (${known.length ? `its controls: ${known.join(', ')}` : 'it has none'})`,
    );
  }
  const client = /** @type {import('../headless/client.js').EngineClient} */ (session.client());
  if (converge === null && view.frame === null) return image;
  const bar = progressBar(converge !== null ? 'samples' : 'frames');
  try {
    const work =
      converge !== null
        ? { method: /** @type {const} */ ('converge'), request: null, total: converge }
        : {
            method: /** @type {const} */ ('frameAt'),
            request: { frame: view.frame, fps: view.fps, width: view.size.width, height: view.size.height },
            total: /** @type {number} */ (view.frame) + 1,
          };
    const value = await runLong(client, {
      ...work,
      progress: progress ? bar.update : undefined,
      limits: session.limits,
      clock: session.clock(),
    });
    const shot = converge !== null ? await client.capture() : value;
    return { width: shot.width, height: shot.height, data: fromBase64(shot.data), info: image.info, notes: image.notes };
  } catch (error) {
    const what = converge !== null ? `--converge ${converge}` : `--frame ${view.frame}`;
    const said = error.hung ? hungLine(session.limits, session.clock().measure) : error.message.split('\n')[0];
    throw Object.assign(new ShaderproofError(`${what}: ${file}: ${said}`), { hung: Boolean(error.hung) });
  } finally {
    bar.end();
  }
}

/** The largest side the CLI opens the page at for a tiled still; the tiles make the rest. */
const TILED_PAGE_SIDE = 2048;

/**
 * The view drawn in tiles of `tile` pixels: the page opens at the whole size where it can (else
 * at the same aspect, smaller: the tiles' iResolution is the whole picture's either way), and
 * each tile is drawn with fragCoord moved by its place (header.js TILE_OFFSET_UNIFORM). Tiles
 * start at multiples of `tile` from the bottom left, as gl_FragCoord counts, so that with an
 * even `tile` every 2×2 quad is the whole picture's: its derivatives too.
 * @param {import('../headless/session.js').Session} session
 * @param {string} file
 * @param {import('./view-options.js').ViewOptions} view
 * @param {number} tile
 * @param {{say?: (line: string) => void}} [options]
 */
export async function renderTiled(session, file, view, tile, { say = io.err } = {}) {
  const { width, height } = view.size;
  const fits = width <= TILED_PAGE_SIDE && height <= TILED_PAGE_SIDE;
  const scale = fits ? 1 : TILED_PAGE_SIDE / Math.max(width, height);
  const pageSize = { width: Math.max(1, Math.round(width * scale)), height: Math.max(1, Math.round(height * scale)) };
  const mouse = view.mouse && view.mouse.map((v, i) => v * (i % 2 === 0 ? pageSize.width / width : pageSize.height / height));
  const first = await renderShader(session, file, { ...view, size: pageSize, mouse }, { say });
  const client = /** @type {import('../headless/client.js').EngineClient} */ (session.client());
  const data = new Uint8Array(width * height * 4);
  for (let y = 0; y < height; y += tile)
    for (let x = 0; x < width; x += tile) {
      const w = Math.min(tile, width - x);
      const h = Math.min(tile, height - y);
      const shot = await client.captureTile({ x, y, width: w, height: h, fullWidth: width, fullHeight: height }).catch((error) => {
        throw new ShaderproofError(`--tile: ${path.basename(file)}: ${error.message.split('\n')[0]}`);
      });
      const pixels = fromBase64(shot.data);
      // the tile's rows come top to bottom; its top row is the picture's row height - (y + h)
      for (let row = 0; row < h; row++) {
        const to = ((height - (y + h) + row) * width + x) * 4;
        data.set(pixels.subarray(row * w * 4, (row + 1) * w * 4), to);
      }
    }
  return { width, height, data, info: first.info, notes: first.notes };
}

/**
 * The page's message with the shader named as the person gave it: a compile report says
 * "NAME:LINE: error: …" with the file's own name (the page serves it under that name).
 * @param {string} message
 * @param {string} file
 */
function userMessage(message, file) {
  const name = path.basename(file);
  const escaped = name.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
  return message.replace(new RegExp(`(^|\\n)${escaped}:(\\d+):`, 'g'), `$1${file}:$2:`);
}

/**
 * A float image as a Portable FloatMap (.pfm: "PF", the size, -1 for little-endian, then RGB
 * float32 rows from the bottom up), which ImageMagick, GIMP, OpenCV and imageio read. No npm
 * library writes OpenEXR from plain Node without native code; PFM keeps every float as is.
 * @param {{width: number, height: number, data: Float32Array}} image RGBA rows top to bottom
 */
function pfmBytes({ width, height, data }) {
  const header = Buffer.from(`PF\n${width} ${height}\n-1.0\n`, 'ascii');
  const body = Buffer.alloc(width * height * 12);
  for (let y = 0; y < height; y++)
    for (let x = 0; x < width; x++)
      for (let c = 0; c < 3; c++) body.writeFloatLE(data[((height - 1 - y) * width + x) * 4 + c], ((y * width + x) * 3 + c) * 4);
  return Buffer.concat([header, body]);
}

/** The output's format from its name: 'png', or 'pfm' (the colours in float). @param {string} file */
export function outputFormat(file) {
  if (/\.png$/i.test(file)) return 'png';
  if (/\.pfm$/i.test(file)) return 'pfm';
  throw new UsageError(`-o ${file}: a render is a .png file, or a .pfm (Portable FloatMap) for the colours in float`);
}

/** @param {string} file @param {{width: number, height: number, data: Uint8Array}} image */
export function writeImage(file, image) {
  writePng(file, image);
}

/** @param {string} file @param {{width: number, height: number, data: Float32Array}} image */
export function writeFloatImage(file, image) {
  writeWhole(file, pfmBytes(image));
}
