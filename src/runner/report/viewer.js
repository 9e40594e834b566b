// A case's images in the HTML report: the reference, the actual, the diff and a comparison of the
// first two, each in a viewport of one size, zoomed and panned together (viewer-page.js moves
// them). The page opens a failure at its difference: zoomed in on the box the differing pixels
// lie in (compare.js), the box outlined in every view. The pixel under the cursor is read in
// every image from the case's -pixels.js (pixelsScript), loaded when the pointer first comes.

import { escape, href } from './html-text.js';

/** The zooms offered: a pixel stays a square of whole CSS pixels (a large render also gets "Fit"). */
const ZOOMS = [1, 2, 4, 8, 16];
/** The most the page opens a difference at. */
const OPENING_MOST = 8;
/** The width a small render is first shown at, at most (a zoom of whole pixels). */
const SHOWN_WIDTH = 320;
/** The largest viewport, in CSS pixels: three fit side by side in the page. */
const VIEWPORT = { width: 440, height: 330 };

/**
 * The case's kept PNGs as a script the report loads on demand: data: URLs a canvas may read,
 * which the PNG files beside a page opened from file:// are not (Chromium taints the canvas).
 * @param {Partial<Record<'reference' | 'actual' | 'diff', Buffer>>} pngs
 */
export function pixelsScript(pngs) {
  const images = Object.fromEntries(
    Object.entries(pngs).map(([kind, bytes]) => [kind, `data:image/png;base64,${bytes.toString('base64')}`]),
  );
  return `shaderproofPixels(${JSON.stringify(images)});\n`;
}

/**
 * The viewport, the zooms and where the views open.
 * @param {{width: number, height: number}} size the render's
 * @param {import('../../headless/compare.js').Where | null} where
 */
export function viewerLayout({ width, height }, where) {
  // a small render starts enlarged, to about SHOWN_WIDTH
  const start = ZOOMS.filter((z) => z === 1 || width * z <= SHOWN_WIDTH).at(-1) ?? 1;
  const scale = Math.min(1, VIEWPORT.width / (width * start), VIEWPORT.height / (height * start));
  const view = { width: Math.round(width * start * scale), height: Math.round(height * start * scale) };
  const fit = scale < 1 ? start * scale : null;
  const zooms = fit ? [fit, ...ZOOMS] : ZOOMS;
  const whole = fit ?? start;
  if (!where) return { view, zooms, zoom: whole, center: [width / 2, height / 2] };
  const { left, top, right, bottom } = where.box;
  const [w, h] = [right - left + 1, bottom - top + 1];
  // the most that shows the box within half the viewport each way
  const closest = zooms.filter((z) => z <= OPENING_MOST && w * z <= view.width / 2 && h * z <= view.height / 2).at(-1) ?? whole;
  return { view, zooms, zoom: Math.max(whole, closest), center: [left + w / 2, top + h / 2] };
}

/** A zoom's label: "Fit" or "4×". @param {number} zoom */
const zoomLabel = (zoom) => (Number.isInteger(zoom) ? `${zoom}×` : 'Fit');
/** Numbers into an attribute: "12 7.5". @param {number[]} values */
const numbers = (values) => values.map((v) => String(Math.round(v * 1000) / 1000)).join(' ');

/**
 * The case's images, the tools above them and the readout below.
 * @param {import('../case.js').CaseResult} r
 * @param {{width: number, height: number}} thumb the thumbnail's size in the page
 */
export function viewerHtml(r, thumb) {
  const { files } = r;
  const { width, height } = r.size ?? { width: 0, height: 0 };
  const img = (file, alt, size = { width, height }) =>
    `<img src="${href(file)}" alt="${escape(alt)}" loading="lazy" draggable="false" width="${size.width}" height="${size.height}">`;
  if (!files.actual || !r.size) {
    // a static picture: a failed half-size render, or a passed case's thumbnail
    const statics = [];
    if (files.half)
      statics.push(
        `<figure><figcaption>Half-size render</figcaption>${img(files.half, 'half-size render', halfOf({ width, height }))}</figure>`,
      );
    if (files.thumb) statics.push(`<figure><figcaption>Thumbnail</figcaption>${img(files.thumb, 'thumbnail', thumb)}</figure>`);
    return statics.length ? `<div class="statics">${statics.join('')}</div>` : '';
  }
  const layout = viewerLayout(r.size, r.where);
  const view = (kind, caption, inner) =>
    `<figure${kind === 'compare' ? ' class="compare" data-mode="slider"' : ''}><figcaption>${caption}</figcaption><div class="view" data-image="${kind}" tabindex="0">${inner}<span class="mark"><i></i><i></i><i></i><i></i></span><span class="cursor"></span></div>${kind === 'compare' ? '<input type="range" min="0" max="100" value="50" aria-label="Reference on the left, actual on the right: where they meet">' : ''}</figure>`;
  const shown = [];
  if (files.reference) shown.push(view('reference', 'Reference', img(files.reference, `Reference of ${r.name}`)));
  shown.push(view('actual', 'Actual', img(files.actual, `Actual of ${r.name}`)));
  if (files.diff)
    shown.push(view('diff', 'Diff (red: pixels that differ)', img(files.diff, `Diff (red: pixels that differ) of ${r.name}`)));
  const comparable = files.reference && files.diff;
  if (comparable)
    shown.push(
      view(
        'compare',
        'Reference ◀ ▶ Actual',
        `${img(/** @type {string} */ (files.reference), 'reference')}<div class="top">${img(files.actual, 'actual')}</div>`,
      ),
    );
  if (files.half)
    shown.push(
      `<figure><figcaption>Half-size render</figcaption>${img(files.half, 'half-size render', halfOf({ width, height }))}</figure>`,
    );
  const zooms = layout.zooms
    .map((z) => `<button type="button" data-zoom="${numbers([z])}" aria-pressed="${z === layout.zoom}">${zoomLabel(z)}</button>`)
    .join('');
  const modes = comparable
    ? `<span>Compare</span><span class="modes">${['slider', 'reference', 'actual'].map((m) => `<button type="button" data-mode="${m}" aria-pressed="${m === 'slider'}">${m[0].toUpperCase() + m.slice(1)}</button>`).join('')}</span>`
    : '';
  const found = r.where
    ? `<button type="button" data-goto>Go to the difference</button><label><input type="checkbox" data-outline checked> Outline it</label>`
    : '';
  const box = r.where ? ` data-box="${numbers([r.where.box.left, r.where.box.top, r.where.box.right, r.where.box.bottom])}"` : '';
  const attributes = `data-size="${width} ${height}" data-view="${layout.view.width} ${layout.view.height}" data-zoom="${numbers([layout.zoom])}" data-center="${numbers(layout.center)}" data-opening="${numbers([layout.zoom, ...layout.center])}"${box}${files.pixels ? ` data-pixels="${href(files.pixels)}"` : ''}`;
  return `<div class="tools"><span>Zoom</span><span class="zooms">${zooms}</span>${found}${modes}</div><div class="images" ${attributes} style="--vw:${layout.view.width}px;--vh:${layout.view.height}px">${shown.join('')}</div><p class="readout" data-hint>Drag to pan, Ctrl+wheel to zoom; the pixel under the pointer is read here in every image.</p>`;
}

/** @param {{width: number, height: number}} size */
const halfOf = ({ width, height }) => ({ width: Math.floor(width / 2), height: Math.floor(height / 2) });
