// Where the inspector's boxes go: the readout and the comparison's box lie over the canvas (over
// the stage, around a fixed-size canvas much smaller than it), each in a corner, inside it,
// apart from each other (side by side, or one on the other), and off the pinned pixel they
// describe. A box that is wider or taller
// than the room scrolls inside (its header, with its buttons, stays); when no choice of corners
// keeps the pinned pixel clear, the comparison's box folds to its header, then the readout.
// Other notes over the canvas (the notes column, the view's note) are avoided where they can be.

/** @typedef {{left: number, top: number, right: number, bottom: number}} Rect */

/** The room left between a box and the canvas's edge, and between two boxes (CSS px). */
const MARGIN = 12;
const GAP = 8;
/** Room around the pinned pixel's frame that no box takes. */
const PIN_CLEARANCE = 6;
/** A fixed-size canvas under this share of the stage: the boxes use the stage, around it. */
const SMALL_CANVAS = 0.6;
/** The corners, the readout's first choice first (the comparison's box prefers the top). */
const READOUT_CORNERS = ['bottom-left', 'top-left', 'bottom-right', 'top-right'];
const COMPARE_CORNERS = ['top-left', 'top-right', 'bottom-left', 'bottom-right'];

/** The area two rectangles share. @param {Rect} a @param {Rect} b */
export function overlapArea(a, b) {
  const w = Math.min(a.right, b.right) - Math.max(a.left, b.left);
  const h = Math.min(a.bottom, b.bottom) - Math.max(a.top, b.top);
  return w > 0 && h > 0 ? w * h : 0;
}

/** Whether two rectangles come closer than `gap`. @param {Rect} a @param {Rect} b */
function overlaps(a, b, gap = 0) {
  return a.left < b.right + gap && b.left < a.right + gap && a.top < b.bottom + gap && b.top < a.bottom + gap;
}

/** A box of `width` x `height` in a corner of `area`. @param {Rect} area @param {string} corner */
function cornerRect(area, corner, width, height) {
  const left = corner.endsWith('left') ? area.left : area.right - width;
  const top = corner.startsWith('top') ? area.top : area.bottom - height;
  return { left, top, right: left + width, bottom: top + height };
}

/**
 * Corners for the boxes that keep them inside `area`, apart, and off `pin`, the preferred ones
 * (and the ones they are in now) first; null when there are none.
 * @param {{area: Rect, boxes: Array<{width: number, height: number, corners: string[], current: string | null}>, pin: Rect | null, avoid: Rect[]}} question
 * @returns {Array<{corner: string, rect: Rect}> | null}
 */
function chooseCorners({ area, boxes, pin, avoid }) {
  /** @type {{cost: number, placed: Array<{corner: string, rect: Rect}>} | null} */
  let best = null;
  const search = (/** @type {number} */ k, /** @type {Array<{corner: string, rect: Rect}>} */ placed, /** @type {number} */ cost) => {
    if (k === boxes.length) {
      if (!best || cost < best.cost) best = { cost, placed: [...placed] };
      return;
    }
    const box = boxes[k];
    if (box.width > area.right - area.left + 0.5 || box.height > area.bottom - area.top + 0.5) return;
    // a corner of the room, or stacked on a box placed already (both at the bottom, or the top)
    const stacked = placed.flatMap(({ rect: under }) =>
      ['left', 'right']
        .flatMap((side) => [
          [`above-${side}`, under.top - GAP - box.height],
          [`below-${side}`, under.bottom + GAP],
        ])
        .map(([corner, top]) => {
          const left = String(corner).endsWith('left') ? area.left : area.right - box.width;
          return { corner: String(corner), rect: { left, top: Number(top), right: left + box.width, bottom: Number(top) + box.height } };
        }),
    );
    const candidates = [...box.corners.map((corner) => ({ corner, rect: cornerRect(area, corner, box.width, box.height) })), ...stacked];
    candidates.forEach(({ corner, rect }, rank) => {
      if (rect.top < area.top - 0.5 || rect.bottom > area.bottom + 0.5) return;
      if (pin && overlaps(rect, pin)) return;
      if (placed.some((other) => overlaps(rect, other.rect, GAP))) return;
      // a corner further down the list costs more; staying where it is costs less (a box does
      // not jump about as its text changes); covering a note costs its area
      const covered = avoid.reduce((sum, note) => sum + overlapArea(rect, note), 0);
      const extra = rank - (corner === box.current ? 1.5 : 0) + covered / 1000;
      search(k + 1, [...placed, { corner, rect }], cost + extra);
    });
  };
  search(0, [], 0);
  return /** @type {{placed: Array<{corner: string, rect: Rect}>} | null} */ (best)?.placed ?? null;
}

/** Whether an element is on the page and not hidden. @param {Element} e */
export const shown = (e) => e.isConnected && !(/** @type {HTMLElement} */ (e).hidden);

export class BoxLayout {
  /**
   * @param {HTMLElement} stage
   * @param {HTMLCanvasElement} canvas
   * @param {{readout: HTMLElement, compare: HTMLElement, pin: HTMLElement, avoid: () => Element[]}} parts
   *   the boxes, the pinned pixel's frame, and the notes to keep clear of
   */
  constructor(stage, canvas, parts) {
    this.stage = stage;
    this.canvas = canvas;
    this.parts = parts;
    /** The corner each box is in. @type {Map<HTMLElement, string>} */
    this._corners = new Map();
  }

  /** The room for the boxes, in the page's coordinates: the canvas's box on the stage, inset. */
  area() {
    const stage = this.stage.getBoundingClientRect();
    const canvas = this.canvas.getBoundingClientRect();
    const visible = {
      left: Math.max(stage.left, canvas.left),
      top: Math.max(stage.top, canvas.top),
      right: Math.min(stage.right, canvas.right),
      bottom: Math.min(stage.bottom, canvas.bottom),
    };
    const share =
      (Math.max(0, visible.right - visible.left) * Math.max(0, visible.bottom - visible.top)) / (stage.width * stage.height || 1);
    const room = share < SMALL_CANVAS ? stage : visible;
    return { left: room.left + MARGIN, top: room.top + MARGIN, right: room.right - MARGIN, bottom: room.bottom - MARGIN };
  }

  /** Places the boxes that show (call after their content or the canvas changes). */
  layout() {
    const { readout, compare, pin, avoid } = this.parts;
    const boxes = [readout, compare].filter(shown);
    if (!boxes.length) return;
    const area = this.area();
    const stage = this.stage.getBoundingClientRect();
    const width = Math.max(0, area.right - area.left);
    const height = Math.max(0, area.bottom - area.top);
    const pinRect = shown(pin) ? pin.getBoundingClientRect() : null;
    const pinned = pinRect && {
      left: pinRect.left - PIN_CLEARANCE,
      top: pinRect.top - PIN_CLEARANCE,
      right: pinRect.right + PIN_CLEARANCE,
      bottom: pinRect.bottom + PIN_CLEARANCE,
    };
    const notes = avoid()
      .filter(shown)
      .map((e) => e.getBoundingClientRect());
    // the comparison's box folds first: the readout is about the pixel the person chose
    const folds = [[], [compare], [readout], [readout, compare]].filter((f) => f.every((box) => boxes.includes(box)));
    for (const folded of folds) {
      const sizes = boxes.map((box) => {
        box.classList.toggle('folded', folded.includes(box));
        Object.assign(box.style, {
          left: `${area.left - stage.left}px`,
          top: `${area.top - stage.top}px`,
          right: 'auto',
          bottom: 'auto',
          maxWidth: `${width}px`,
          maxHeight: `${height}px`,
        });
        const r = box.getBoundingClientRect();
        return { width: r.width, height: r.height, corners: box === readout ? READOUT_CORNERS : COMPARE_CORNERS };
      });
      const placed = chooseCorners({
        area,
        boxes: sizes.map((s, i) => ({ ...s, current: this._corners.get(boxes[i]) ?? null })),
        pin: pinned,
        avoid: notes,
      });
      if (!placed && folded.length < boxes.length) continue;
      boxes.forEach((box, i) => {
        // no way to keep them apart (a canvas smaller than a folded box): their first corners
        const { corner, rect } = placed?.[i] ?? {
          corner: sizes[i].corners[0],
          rect: cornerRect(area, sizes[i].corners[0], sizes[i].width, sizes[i].height),
        };
        this._corners.set(box, corner);
        Object.assign(box.style, { left: `${rect.left - stage.left}px`, top: `${rect.top - stage.top}px` });
      });
      return;
    }
  }
}
