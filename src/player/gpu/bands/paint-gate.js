// The worker's wait for the page to paint what it was sent, before a draw that may never end.
//
// A program's first draws may be an endless loop, and on SwiftShader such a draw holds the GPU
// process for good. The page's main thread shows the ImageBitmaps the render worker sends, and in
// doing so it waits for the GPU process: a bitmap sent just before an endless draw froze the
// page's script for good in 4 of 6 runs of page-heavy's endless shader. So such a draw waits until
// the page says it has painted every bitmap sent (asked by 'awaitingPaint', answered by 'settled'
// two animation frames later, or at once by a hidden page: app/render-client.js). There is no
// time limit: the wait used to end after 1 s, and a page whose animation frames came later than
// that (a machine under load) got the endless draw before its paint, and froze (1 of 48 runs of
// that test, which was then retried). The page always answers. Asked, not told after every
// bitmap: an animation frame the page asks for runs its virtual clock on in the tests
// (tests/support/deterministic-injection.js).

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
    /** The page has been asked, and has not answered yet. */
    this._asked = false;
  }

  /** Counts the bitmaps of a message's transfer list on its way to the page. @param {Transferable[]} transfer */
  sending(transfer) {
    this.sent += transfer.filter((item) => item instanceof ImageBitmap).length;
  }

  /** The page's 'settled': it has painted the first `count` bitmaps. @param {number} count */
  settle(count) {
    this.settled = Math.max(this.settled, count);
    this._asked = false;
    if (this.settled >= this.sent) this._retry();
    else this.mayDraw(); // more were sent meanwhile: asks again
  }

  /** Whether a draw that may never end can go now; if not, `retry` is called when it can. */
  mayDraw() {
    if (this.settled >= this.sent) return true;
    if (!this._asked) {
      this._asked = true;
      this._ask();
    }
    return false;
  }
}
