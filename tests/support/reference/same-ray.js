// The page's image of a view against the float64 reference with the same rays: the measure of the
// hard views (tests/browser/hard-views.test.js), of "Compare with float64" (tests/browser/page-compare.test.js)
// and of `npm run accuracy` (tests/scripts/accuracy-report.js), in one place.
//
// With adaptive anti-aliasing the same rays are the shader's: the pixels its "Extra samples" view
// marks take the grid of samples, the others their centre, so that view is drawn first. The
// reference renders on this thread after the image: rendered in worker threads while the browser
// drew (reference-threads.js), the hard views took 38 s instead of 31 s on this 2-core machine
// (one thread or two alike): SwiftShader already uses every core, and each worker loads the
// reference's modules again.

import { imageError } from '../../../src/reference/error.js';
import { EXTRA_SAMPLES_VIEW, extraSampleMask } from '../../../src/raytracer/extra-samples.js';
import { referenceView } from '../tables/hard-views.js';
import { renderView } from '../page.js';
import { renderReference } from '../../../src/reference/render.js';

/** Whether a view's shader takes extra samples at edges (adaptive anti-aliasing, the default). */
const isAdaptive = (params) => params.ADAPTIVE_AA !== 0 && params.SAMPLES !== 1;

/**
 * Renders `view` in the page and measures it against the same-ray float64 reference.
 * @param {string} source the shader's text (the reference reads its controls and constants)
 * @param {{name: string, params: Record<string, any>}} view (tests/support/tables/views.js)
 * @returns {Promise<{image: Awaited<ReturnType<typeof renderView>>, error: ReturnType<typeof imageError>, mask: Uint8Array | null, share: number | null}>}
 *   the page's image, its error (error.js's figures), and for adaptive anti-aliasing the
 *   pixels with extra samples and their share
 */
export async function measureSameRay(source, view) {
  const mask = isAdaptive(view.params)
    ? extraSampleMask(await renderView({ ...view, params: { ...view.params, ...EXTRA_SAMPLES_VIEW } }))
    : null;
  const image = await renderView(view);
  const error = imageError(image, renderReference(source, referenceView(view), mask ? { extraSamples: mask } : {}));
  return { image, error, mask, share: mask ? mask.reduce((n, v) => n + v, 0) / mask.length : null };
}
