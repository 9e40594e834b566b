// How a frame is cut into bands of rows, so that no single draw takes much longer than a budget.
//
// A heavy shader (16 samples at 1280×765 takes ~45 s a frame on SwiftShader) drawn in one call
// holds the GPU for all that time: a control change, a pause or a new shader would wait for it.
// Drawn as bands of full-width rows, each its own draw, the render worker (render-worker.js)
// looks at its messages between two bands, so a change applies after the band in flight.
//
// The planner learns the shader's cost per pixel from the bands it has timed and sizes the next
// band to the budget. A shader it has not timed yet (a new program, a new size) starts with a
// thin band, so that even a very heavy shader shows its first cost quickly. A cheap frame ends up
// as one band: the whole frame in one draw, as before.
//
// Bands start on even rows and (but for the last) have an even number of rows: the GPU shades
// 2×2 quads, and the shader's screen-space derivatives (adaptive anti-aliasing reads them) pair
// rows 2k and 2k+1. A band edge between the two rows of a quad would change those pixels.

/** A band's draw should take about this long: the longest a change waits for the band in flight. */
const BAND_BUDGET_MS = 100;
/** The first band of a shader not timed yet: thin, so that a very heavy one shows its cost soon. */
const FIRST_BAND_ROWS = 8;

export class BandPlanner {
  /** @param {number} [budgetMs] */
  constructor(budgetMs = BAND_BUDGET_MS) {
    this.budgetMs = budgetMs;
    /** Estimated milliseconds per pixel; null until a band has been timed. @type {number | null} */
    this.msPerPixel = null;
  }

  /** A new program or size: what was learnt no longer holds. */
  forget() {
    this.msPerPixel = null;
  }

  /**
   * The rows of the next band.
   * @param {number} width the frame's width
   * @param {number} remaining rows left to draw in this frame
   */
  rows(width, remaining) {
    const wanted = this.msPerPixel === null ? FIRST_BAND_ROWS : Math.floor(this.budgetMs / (this.msPerPixel * width));
    const even = Math.max(2, wanted - (wanted % 2));
    // a remainder of one row (an odd height) goes with the band before it
    return even >= remaining - 1 ? remaining : even;
  }

  /**
   * A band has been drawn: `ms` from its draw call to the GPU's signal that it finished (an
   * upper bound on its cost: it includes the wait for the signal).
   * @param {number} width
   * @param {number} rows
   * @param {number} ms
   */
  measured(width, rows, ms) {
    const sample = ms / Math.max(1, width * rows);
    // half the weight on the latest band: follows a change of cost within a few bands, while one
    // band slowed down by something else (a compile, the page) moves the estimate only half way
    this.msPerPixel = this.msPerPixel === null ? sample : 0.5 * (this.msPerPixel + sample);
  }
}
