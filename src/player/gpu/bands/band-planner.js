// How a frame is cut into bands of rows, so that no single draw takes much longer than a budget.
//
// A heavy shader (16 samples at 1280×765 takes ~45 s a frame on SwiftShader) drawn in one call
// holds the GPU for all that time: a control change, a pause or a new shader would wait for it.
// Drawn as bands of full-width rows, each its own draw, the render worker (render-worker.js)
// looks at its messages between two bands, so a change applies after the band in flight.
//
// The planner learns each pass's cost from the bands of it it has timed, row by row, and sizes
// the next band of that pass to the budget:
//
// - Each pass has its own cost. A frame's cheap Buffer A says nothing of its heavy Image pass
//   (which, sized from Buffer A's cost, was once drawn whole in one band of a minute, and the
//   watchdog took it for endless).
// - Each row has its own: what its band cost when it was last drawn. A picture's rows differ
//   (a sky that costs nothing above a floor that costs much): the next frame's first band, at
//   the bottom, is sized by the bottom rows' cost, not by the top rows' that the last band of
//   the frame before drew. A row not drawn yet is taken to cost what the band before it did.
// - A pass not timed yet (a new program, a new size, a change) starts with a thin band of about
//   FIRST_BAND_PIXELS, and a band has at most GROWTH times the rows of the largest before it. So
//   even a very heavy shader shows its cost quickly; a cheap frame takes a few bands, then one.
//
// The watchdog (src/headless/watchdog/limits.js) gives a band 5 s of the GPU process's CPU time: 50 times
// this budget on one core, 25 times on two. What can still pass it: a band of two rows (the
// least) that costs more; and, on a pass's first frame, a band that climbs from cheap rows into
// rows over 25 times dearer, which no row drawn so far could foretell.
//
// Bands start on even rows and (but for the last) have an even number of rows: the GPU shades
// 2×2 quads, and the shader's screen-space derivatives (adaptive anti-aliasing reads them) pair
// rows 2k and 2k+1. A band edge between the two rows of a quad would change those pixels.

/** A band's draw should take about this long: the longest a change waits for the band in flight. */
const BAND_BUDGET_MS = 100;
/**
 * The first band of a pass not timed yet: about this many pixels (two rows at 320 wide, ten at
 * 64), so that a shader of a few ms a pixel shows its cost within seconds.
 */
const FIRST_BAND_PIXELS = 640;
/** How many times the rows of the largest band of its pass so far a band may have. */
const GROWTH = 8;

/**
 * What is known of a pass's cost: ms per pixel of each row drawn (an upper bound: a band's time
 * includes the wait for the GPU's signal), of the last band drawn (for rows not drawn yet), and
 * the most rows a band of it has had.
 * @typedef {{byRow: number[], last: number, rows: number}} PassCost
 */

/** An even number of rows, at least two; all that remain when at most one would be left. @param {number} wanted @param {number} remaining */
function band(wanted, remaining) {
  const even = Math.max(2, wanted - (wanted % 2));
  return even >= remaining - 1 ? remaining : even;
}

export class BandPlanner {
  /** @param {number} [budgetMs] */
  constructor(budgetMs = BAND_BUDGET_MS) {
    this.budgetMs = budgetMs;
    /** Each pass's cost, by the pass (its step). @type {Map<object, PassCost>} */
    this._costs = new Map();
  }

  /** A new program or size, or a change: what was learnt no longer holds. */
  forget() {
    this._costs.clear();
  }

  /**
   * The rows of the next band of `pass`, from row `y`.
   * @param {object} pass the pass drawn (its step: each has its own cost)
   * @param {number} width the frame's width
   * @param {number} y the band's first row
   * @param {number} remaining rows left to draw in this frame
   */
  rows(pass, width, y, remaining) {
    const cost = this._costs.get(pass);
    if (!cost) return band(Math.floor(FIRST_BAND_PIXELS / width), remaining);
    const most = Math.min(remaining, cost.rows * GROWTH);
    let ms = 0;
    let rows = 0;
    while (rows < most) {
      const next = ms + (cost.byRow[y + rows] ?? cost.last) * width;
      if (next > this.budgetMs && rows >= 2) break;
      ms = next;
      rows++;
    }
    return band(rows, remaining);
  }

  /**
   * A band of `pass` has been drawn: `ms` from its draw call to the GPU's signal that it
   * finished (an upper bound on its cost: it includes the wait for the signal).
   * @param {object} pass
   * @param {number} width
   * @param {number} y its first row
   * @param {number} rows
   * @param {number} ms
   */
  measured(pass, width, y, rows, ms) {
    const sample = ms / Math.max(1, width * rows);
    const known = this._costs.get(pass);
    const cost = known ?? { byRow: [], last: sample, rows };
    for (let row = y; row < y + rows; row++) cost.byRow[row] = sample;
    cost.last = sample;
    // the last band of a frame is what rows are left, and may be few: the next frame does not
    // start small again for it
    cost.rows = Math.max(cost.rows, rows);
    this._costs.set(pass, cost);
  }
}
