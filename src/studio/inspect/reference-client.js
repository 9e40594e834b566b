// The page's side of the float64 reference's workers (reference-worker.js): one kept for single
// pixels (the inspector asks one a probe), and for a whole image as many as the machine has cores
// to spare (one on two cores), each rendering its share of the rows band by band. A whole image
// can be cancelled: its workers are stopped at once (a band does not wait for a message).

/**
 * The view the reference renders: the page's frame and control values.
 * @typedef {{width: number, height: number, time: number, mouse: number[], controls: Record<string, unknown>}} ReferenceView
 */

/** How many workers render a whole image: the cores but one for the page and its GPU, at most 4. */
const imageWorkers = () => Math.max(1, Math.min(4, (navigator.hardwareConcurrency || 2) - 1));

const spawn = () => new Worker(new URL('./reference-worker.js', import.meta.url), { type: 'module' });

/**
 * Asks a worker one question; resolves with its answer, rejects with its error.
 * @param {Worker} worker
 * @param {object} message
 * @param {Transferable[]} [transfer]
 * @param {(rows: number) => void} [onProgress]
 */
function ask(worker, message, transfer = [], onProgress = () => {}) {
  const id = Math.random();
  return new Promise((resolve, reject) => {
    const stop = () => {
      worker.removeEventListener('message', listen);
      worker.removeEventListener('error', failed);
    };
    const listen = ({ data }) => {
      if (data.id !== id) return;
      if ('progress' in data) return onProgress(data.progress);
      stop();
      if ('error' in data) reject(new Error(data.error));
      else resolve(data.result);
    };
    const failed = (event) => {
      stop();
      event.preventDefault();
      reject(new Error(`the float64 reference's worker failed: ${event.message}`));
    };
    worker.addEventListener('message', listen);
    worker.addEventListener('error', failed);
    worker.postMessage({ ...message, id }, transfer);
  });
}

/** Raised when a render is cancelled. */
export class ReferenceCancelled extends Error {
  constructor() {
    super('cancelled');
    this.name = 'ReferenceCancelled';
  }
}

export class ReferenceClient {
  constructor() {
    /** @type {Worker | null} */
    this._pixelWorker = null;
    /** The workers of the image being rendered, and how to end its promise. @type {{workers: Worker[], reject: (e: Error) => void} | null} */
    this._image = null;
  }

  /**
   * One pixel of the same-ray reference and the path through its centre (referencePixel).
   * @param {{source: string, view: ReferenceView, x: number, y: number, extraSamples: boolean}} question
   * @returns {Promise<{rgb: number[], path: import('../../raytracer/path-probe.js').PathRay[]}>}
   */
  pixel(question) {
    this._pixelWorker ??= spawn();
    return ask(this._pixelWorker, { type: 'pixel', ...question });
  }

  /**
   * The same-ray reference of a whole view (rows top to bottom, 3 display values a pixel), split
   * over the workers. Cancels an image under way.
   * @param {{source: string, view: ReferenceView, extraSamples: Uint8Array | null}} question
   * @param {(rowsDone: number) => void} onProgress
   * @returns {Promise<Float64Array>}
   */
  async image({ source, view, extraSamples }, onProgress) {
    this.cancel();
    const count = Math.min(imageWorkers(), view.height);
    const workers = Array.from({ length: count }, spawn);
    const done = new Array(count).fill(0);
    /** @type {Promise<never>} */
    const cancelled = new Promise((_, reject) => (this._image = { workers, reject }));
    const rgb = new Float64Array(view.width * view.height * 3);
    const share = Math.ceil(view.height / count);
    const parts = workers.map((worker, i) => {
      const rows = [i * share, Math.min(view.height, (i + 1) * share)];
      return ask(worker, { type: 'rows', source, view, rows, extraSamples }, [], (n) => {
        done[i] = n;
        onProgress(done.reduce((a, b) => a + b, 0));
      }).then((part) => rgb.set(/** @type {Float64Array} */ (part), rows[0] * view.width * 3));
    });
    try {
      await Promise.race([Promise.all(parts), cancelled]);
      return rgb;
    } finally {
      for (const worker of workers) worker.terminate();
      if (this._image?.workers === workers) this._image = null;
    }
  }

  /** Stops the image under way (its promise rejects with ReferenceCancelled). */
  cancel() {
    const image = this._image;
    if (!image) return;
    this._image = null;
    for (const worker of image.workers) worker.terminate();
    image.reject(new ReferenceCancelled());
  }
}
