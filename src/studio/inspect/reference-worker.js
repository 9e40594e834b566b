// The float64 reference's thread (src/reference/render.js, loaded here and only here, when the
// page first asks for it: ESLint keeps it out of the page's bundle). Two questions:
//
// - {type: 'pixel', source, view, x, y, extraSamples}: one pixel of the same-ray reference and
//   the path of the ray through its centre (referencePixel);
// - {type: 'rows', source, view, rows: [first, end), extraSamples}: those rows of the same-ray
//   reference, band by band, with a progress message after each band (bands of about
//   BAND_MS, sized by the time the last one took) and the rows' display values at the end.
//
// Each answer is {id, result} or {id, error}; progress is {id, progress: rows done}.

/** A band of rows should take about this long between progress messages. */
const BAND_MS = 100;

/** The worker's own scope (typed as the page's window by the DOM library). */
const scope = /** @type {{postMessage: (message: any, transfer?: Transferable[]) => void, onmessage: any}} */ (/** @type {any} */ (self));

/** @type {Promise<typeof import('../../reference/render.js')> | null} */
let reference = null;
const load = () => (reference ??= import('../../reference/render.js'));

scope.onmessage = async ({ data }) => {
  const { id, type } = data;
  try {
    const { referencePixel, renderReference } = await load();
    if (type === 'pixel') {
      const { source, view, x, y, extraSamples } = data;
      scope.postMessage({ id, result: referencePixel(source, view, x, y, { extraSamples }) });
      return;
    }
    if (type !== 'rows') throw new Error(`reference worker: no request ${type}`);
    const { source, view, rows, extraSamples } = data;
    const [first, end] = rows;
    const rgb = new Float64Array((end - first) * view.width * 3);
    let band = 2;
    for (let row = first; row < end;) {
      const until = Math.min(end, row + band);
      const started = performance.now();
      const part = renderReference(source, view, { rows: [row, until], extraSamples: extraSamples ?? undefined });
      rgb.set(part.rgb, (row - first) * view.width * 3);
      const ms = performance.now() - started;
      band = Math.max(1, Math.round(((until - row) * BAND_MS) / Math.max(ms, 1)));
      row = until;
      scope.postMessage({ id, progress: row - first });
    }
    scope.postMessage({ id, result: rgb }, [rgb.buffer]);
  } catch (error) {
    scope.postMessage({ id, error: error?.message ?? String(error) });
  }
};
