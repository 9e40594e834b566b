// One still, from its options to its pixels: what `shaderproof render -o OUT.png|OUT.pfm` and the
// Node API's render() both do (src/cli/main.js, src/api/index.js). The flags (or the API's
// options, said as flags) are read into a view (view-options.js) and checked together here; the
// view is drawn whole, in tiles or converged (render.js), its notes said or refused (--strict),
// and a frame llvmpipe's loop limit cut short refused (loop-limit.js). Writing and the result
// line are the command line's.

import { MAX_PIXELS, MAX_SIZE } from '../shared/canvas-limits.js';
import { ShaderproofError } from '../headless/session.js';
import { sayNotes } from './io.js';
import { refuseCutLoops } from './loop-limit.js';
import { renderShader, renderTiled } from './render.js';
import { UsageError, readNumber, readViewOptions } from './view-options.js';

/** A tiled still's largest size: its RGBA bytes are held in memory whole (1 GiB). */
const MAX_TILED_PIXELS = 2 ** 28;

/**
 * A still's view and how it is drawn, from parseArgs-shaped values (--size, --time, --converge,
 * --tile, ...), checked together; a UsageError says the first that cannot be.
 * @param {Record<string, any>} values
 * @param {{float?: boolean}} [options] float: the colours in float are asked for (-o OUT.pfm)
 */
export function readStill(values, { float = false } = {}) {
  const view = readViewOptions(values, { width: 640, height: 360 });
  if (float && view.frame !== null) throw new UsageError('-o .pfm: the float colours are of a still at --time, not of --frame');
  const converge = values.converge === undefined ? null : readNumber(values.converge, '--converge', { min: 1, whole: true });
  if (converge !== null && (view.frame !== null || float)) throw new UsageError('--converge: a converged still is a .png at --time');
  const tile = values.tile === undefined ? null : readNumber(values.tile, '--tile', { min: 2, whole: true });
  if (tile !== null && tile % 2)
    throw new UsageError(`--tile ${tile}: the tile size must be even (the GPU shades 2x2 quads; an odd size would split them)`);
  if (tile !== null && (view.frame !== null || converge !== null || float))
    throw new UsageError('--tile: a tiled still is a .png at --time');
  checkSize(view.size, tile !== null);
  return { view, converge, tile };
}

/**
 * A size the page draws at once (the page's limits, src/shared/canvas-limits.js), or with
 * `tiled` one whose pixels fit in memory; else a UsageError that says the limit and why.
 * @param {{width: number, height: number}} size
 * @param {boolean} tiled
 */
function checkSize({ width, height }, tiled) {
  const asked = `--size ${width}x${height}`;
  if (tiled) {
    if (width * height > MAX_TILED_PIXELS)
      throw new UsageError(
        `${asked}: a tiled still is at most ${MAX_TILED_PIXELS / 2 ** 20} megapixels (its bytes are held in memory whole)`,
      );
    return;
  }
  if (width > MAX_SIZE || height > MAX_SIZE || width * height > MAX_PIXELS)
    throw new UsageError(
      `${asked}: one draw is at most ${MAX_SIZE} px a side and ${(MAX_PIXELS / 1e6).toFixed(1)} megapixels (8K UHD, the page's limit); use --tile 512 for a larger still`,
    );
}

/**
 * Draws the still readStill described on `session`: the image, its floats when asked, its notes
 * (said as warnings through `say`, or with `strict` an error) and the renderer's label.
 * @param {import('../headless/session.js').Session} session
 * @param {string} file
 * @param {ReturnType<typeof readStill>} still
 * @param {{float?: boolean, strict?: boolean, progress?: boolean, say?: (line: string) => void}} [options]
 */
export async function drawStill(session, file, { view, converge, tile }, { float = false, strict = false, progress = false, say } = {}) {
  const image =
    tile !== null
      ? await renderTiled(session, file, view, tile, { say })
      : await renderShader(session, file, view, { converge, progress, say });
  const { width, height } = view.size;
  if (image.width !== width || image.height !== height)
    throw new ShaderproofError(
      `--size ${width}x${height}: this GPU draws at most ${image.width}x${image.height} at once; use --tile 512 for a larger still`,
      2,
    );
  sayNotes(file, image.notes, { strict, say });
  const floats = float ? await session.drawFloat() : null;
  await refuseCutLoops(session, file);
  const { label: renderer } = await session.environment();
  return { image, floats, renderer };
}
