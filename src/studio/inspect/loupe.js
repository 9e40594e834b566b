// Where the inspector points on the canvas: in Inspect mode a magnifier follows the cursor (the
// pixels around it, enlarged, of the canvas or of the comparison's heat map over it, the one
// under the cursor framed, its coordinates below),
// and the pinned pixel is framed on the canvas itself. Pixels are the frame's (device pixels,
// y from the bottom, as fragCoord counts them), mapped through the canvas's box.
//
// The magnifier never covers the inspector's boxes (the readout, the comparison): it lies on a
// side of the cursor clear of them, is placed again whenever they move (a click that pins a pixel
// brings the readout up under it: issue 45), and hides where no side is clear.

import { element } from '../ui/dom.js';
import { overlapArea, shown } from './box-layout.js';

/** Pixels a side the magnifier shows (odd: the one under the cursor in the middle). */
const SPAN = 11;
/** Screen pixels a magnified pixel takes. */
const ZOOM = 11;
/** How far from the cursor the magnifier lies (CSS px). */
const OFFSET = 24;
/**
 * The sides of the cursor the magnifier may lie on, in order of preference: below and to the
 * right first, then the other diagonals, then straight right, left, below and above (centred).
 */
const SIDES = [
  [1, 1],
  [-1, 1],
  [1, -1],
  [-1, -1],
  [1, 0],
  [-1, 0],
  [0, 1],
  [0, -1],
];

/**
 * The frame pixel under a point of the page, or null outside the canvas.
 * @param {HTMLCanvasElement} canvas
 * @param {number} clientX
 * @param {number} clientY
 * @returns {{x: number, y: number} | null}
 */
export function pixelAt(canvas, clientX, clientY) {
  const box = canvas.getBoundingClientRect();
  const u = (clientX - box.left) / box.width;
  const v = (clientY - box.top) / box.height;
  if (!(u >= 0 && u < 1 && v >= 0 && v < 1)) return null;
  return { x: Math.floor(u * canvas.width), y: canvas.height - 1 - Math.floor(v * canvas.height) };
}

export class Loupe {
  /**
   * @param {HTMLElement} stage
   * @param {HTMLCanvasElement} canvas the page's canvas
   * @param {{boxes: () => Element[], notes: () => Element[]}} avoid the boxes over the canvas that
   *   the magnifier never covers, and the notes it covers only where no side is clear of them
   */
  constructor(stage, canvas, avoid) {
    this.stage = stage;
    this.canvas = canvas;
    this.avoid = avoid;
    /** The pointer it follows (null: none, or not over the canvas). @type {{clientX: number, clientY: number} | null} */
    this._pointer = null;
    this.lens = element('canvas', { class: 'loupe', width: SPAN * ZOOM, height: SPAN * ZOOM, 'aria-hidden': 'true' });
    this.label = element('span', { class: 'loupe-label' });
    this.root = element('div', { class: 'loupe-box', hidden: true }, this.lens, this.label);
    this.marker = element('div', { class: 'pinned-marker', hidden: true, 'aria-hidden': 'true' });
    stage.append(this.marker, this.root);
    this._context = /** @type {CanvasRenderingContext2D} */ (this.lens.getContext('2d'));
  }

  /**
   * Shows the magnifier at a pointer position (null hides it), enlarging `source` (the canvas, or
   * the heat map over it: a canvas of the frame's size).
   * @param {{clientX: number, clientY: number} | null} pointer
   * @param {HTMLCanvasElement} [source]
   */
  follow(pointer, source = this.canvas) {
    const at = pointer && pixelAt(source, pointer.clientX, pointer.clientY);
    if (!at) {
      this._pointer = null;
      this.root.hidden = true;
      return;
    }
    this._pointer = { clientX: pointer.clientX, clientY: pointer.clientY };
    const { height } = source;
    const context = this._context;
    context.imageSmoothingEnabled = false;
    context.fillStyle = '#000';
    context.fillRect(0, 0, SPAN * ZOOM, SPAN * ZOOM);
    const half = (SPAN - 1) / 2;
    const top = height - 1 - at.y;
    context.drawImage(source, at.x - half, top - half, SPAN, SPAN, 0, 0, SPAN * ZOOM, SPAN * ZOOM);
    context.strokeStyle = '#fff';
    context.lineWidth = 2;
    context.strokeRect(half * ZOOM, half * ZOOM, ZOOM, ZOOM);
    context.strokeStyle = '#000';
    context.lineWidth = 1;
    context.strokeRect(half * ZOOM - 1.5, half * ZOOM - 1.5, ZOOM + 3, ZOOM + 3);
    this.label.textContent = `fragCoord ${at.x + 0.5}, ${at.y + 0.5} · click to pin`;
    this.place();
  }

  /**
   * Puts the magnifier (lens and label) beside the cursor it follows, wholly on the stage (the
   * panel beside it would clip it), on a side where it covers none of the boxes (and the fewest
   * notes); hides it where no side is clear of the boxes. Called again when the boxes move.
   */
  place() {
    const pointer = this._pointer;
    if (!pointer) return;
    this.root.hidden = false; // measured as it would show
    const stage = this.stage.getBoundingClientRect();
    const { offsetWidth: width, offsetHeight: height } = this.root;
    const rects = (/** @type {Element[]} */ list) => list.filter(shown).map((e) => e.getBoundingClientRect());
    const boxes = rects(this.avoid.boxes());
    const notes = rects(this.avoid.notes());
    const inside = (v, size, from, to) => Math.min(to - size, Math.max(from, v));
    const along = (/** @type {number} */ d, /** @type {number} */ at, /** @type {number} */ size) =>
      d > 0 ? at + OFFSET : d < 0 ? at - OFFSET - size : at - size / 2;
    /** @type {{cost: number, left: number, top: number} | null} */
    let best = null;
    for (const [dx, dy] of SIDES) {
      const left = inside(along(dx, pointer.clientX, width), width, stage.left, stage.right);
      const top = inside(along(dy, pointer.clientY, height), height, stage.top, stage.bottom);
      const rect = { left, top, right: left + width, bottom: top + height };
      if (boxes.some((b) => overlapArea(rect, b) > 0)) continue;
      // the cursor's own pixel stays in sight: a side that would cover it is the last resort
      const onCursor =
        pointer.clientX >= left && pointer.clientX <= left + width && pointer.clientY >= top && pointer.clientY <= top + height;
      const cost = notes.reduce((sum, b) => sum + overlapArea(rect, b), 0) + (onCursor ? 1e9 : 0);
      if (!best || cost < best.cost) best = { cost, left, top };
      if (cost === 0) break;
    }
    if (!best) {
      this.root.hidden = true; // no side clear of the boxes: the pinned pixel's frame and the readout say where it is
      return;
    }
    this.root.style.left = `${best.left - stage.left}px`;
    this.root.style.top = `${best.top - stage.top}px`;
  }

  /**
   * Frames the pinned pixel on the canvas (null: none).
   * @param {{x: number, y: number} | null} pixel
   */
  mark(pixel) {
    const { width, height } = this.canvas;
    if (!pixel || !width || !height) {
      this.marker.hidden = true;
      return;
    }
    const box = this.canvas.getBoundingClientRect();
    const stageBox = this.stage.getBoundingClientRect();
    const cellW = box.width / width;
    const cellH = box.height / height;
    const size = Math.max(9, cellW, cellH);
    const cx = box.left - stageBox.left + (pixel.x + 0.5) * cellW;
    const cy = box.top - stageBox.top + (height - 1 - pixel.y + 0.5) * cellH;
    Object.assign(this.marker.style, { left: `${cx - size / 2}px`, top: `${cy - size / 2}px`, width: `${size}px`, height: `${size}px` });
    this.marker.hidden = false;
  }
}
