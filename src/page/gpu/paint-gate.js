// The worker's wait for the page to paint what it was sent, before a draw that may never end.
//
// A program's first draw may be an endless loop, and on SwiftShader that draw holds the GPU
// process for good. The page's main thread shows the ImageBitmaps the render worker sends, and in
// doing so it waits for the GPU process: a bitmap sent just before an endless draw froze the
// page's script for good in 4 of 6 runs of page-heavy's endless shader, and in 1 of 48 once the
// draw waited for the page to paint it. So such a draw waits until the page says it has painted
// every bitmap sent (asked by 'awaitingPaint', answered by 'settled' two animation frames later:
// app/render-client.js), or SETTLE_WAIT_MS. Asked, not told after every bitmap: an animation
// frame the page asks for runs its virtual clock on in the tests
// (tests/harness/deterministic-injection.js).

/** The longest wait: a page that never answers (it should not happen) still gets its draw. */
const SETTLE_WAIT_MS = 1_000;

export class PaintGate {
  /**
   * @param {() => void} ask asks the page to say when it has painted ('awaitingPaint')
   * @param {() => void} retry called when a draw held back may go
   */
  constructor(ask, retry) {
    this._ask = ask;
    this._retry = retry;
    /** ImageBitmaps sent to the page, and how many of them it has said it has painted. */
    this.sent = 0;
    this.settled = 0;
    this._timer = 0;
    /** The wait ran out: the next draw goes. */
    this._over = false;
  }

  /** Counts the bitmaps of a message's transfer list on its way to the page. @param {Transferable[]} transfer */
  sending(transfer) {
    this.sent += transfer.filter((item) => item instanceof ImageBitmap).length;
  }

  /** The page's 'settled': it has painted the first `count` bitmaps. @param {number} count */
  settle(count) {
    this.settled = Math.max(this.settled, count);
    if (this.settled >= this.sent) this._retry();
  }

  /** Whether a draw that may never end can go now; if not, `retry` is called when it can. */
  mayDraw() {
    if (this.settled >= this.sent || this._over) {
      clearTimeout(this._timer);
      this._timer = 0;
      this._over = false;
      return true;
    }
    if (!this._timer) {
      this._ask();
      this._timer = self.setTimeout(() => {
        this._timer = 0;
        this._over = true;
        this._retry();
      }, SETTLE_WAIT_MS);
    }
    return false;
  }
}
