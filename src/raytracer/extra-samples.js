// Reading the raytracer's "Extra samples" debug view (VIEW in shaders/raytrace.glsl): the pixels
// that took extra samples are a pure colour that names the test that marked them (EDGE_COLOURS),
// every other pixel is grey. Shared by the benchmark (what fraction took them), the same-ray
// float64 reference (which pixels to sample as the shader did) and the page's inspector and
// comparison (which draw the view with the path probe's compile).

/** The shader's debug view of the pixels that took extra samples (VIEW = "Extra samples"; views.test.js checks the number). */
export const EXTRA_SAMPLES_VIEW = Object.freeze({ VIEW: 5 });

/** The label of that choice in the VIEW control's list. */
const EXTRA_SAMPLES_LABEL = 'Extra samples';

/**
 * The control values that draw a shader's "Extra samples" view, found by the choice's label in
 * its VIEW control (any shader that offers it), or null when the shader has no such view.
 * @param {Array<{name: string, options?: Array<{label: string, value: number}>}>} controls parseControls's
 * @returns {{VIEW: number} | null}
 */
export function extraSamplesValues(controls) {
  const option = controls.find((c) => c.name === 'VIEW')?.options?.find((o) => o.label === EXTRA_SAMPLES_LABEL);
  return option ? { VIEW: option.value } : null;
}

/** The debug view's colours, by the test that marked the pixel (the shader's mainImage). */
const EDGE_COLOURS = Object.freeze({
  silhouette: [255, 0, 255],
  shadow: [255, 255, 0],
  reflection: [0, 255, 255],
  quad: [0, 255, 0],
  neighbour: [0, 0, 255],
});

/** Which test marked a pixel of the view (a key of EDGE_COLOURS), or null for a grey one. */
export function edgeKind(data, i) {
  for (const [kind, [r, g, b]] of Object.entries(EDGE_COLOURS))
    if (data[i * 4] === r && data[i * 4 + 1] === g && data[i * 4 + 2] === b) return kind;
  return null;
}

/**
 * One byte a pixel, rows top to bottom as the image's: 1 where the pixel took extra samples.
 * @param {{width: number, height: number, data: Uint8Array}} image RGBA8, rows top to bottom
 */
export function extraSampleMask({ width, height, data }) {
  const mask = new Uint8Array(width * height);
  for (let i = 0; i < mask.length; i++) mask[i] = edgeKind(data, i) ? 1 : 0;
  return mask;
}

/** How many pixels of the view took extra samples. */
export function countExtraSamplePixels(image) {
  return extraSampleMask(image).reduce((n, v) => n + v, 0);
}

// The view marks the pixels that took adaptive anti-aliasing's extra samples, so with ADAPTIVE_AA
// off (uniform supersampling: every pixel takes the grid) or SAMPLES at 1 it marks none, and would
// look like a picture with no edges found: the page says which it is (ui/notices.js).
/**
 * Why the "Extra samples" view marks no pixel, or null (another view, or it marks them).
 * @param {Array<{name: string, label: string, options?: Array<{label: string, value: number}>}>} controls
 * @param {Record<string, any>} values
 */
export function extraSamplesViewNote(controls, values) {
  const view = extraSamplesValues(controls);
  if (!view || values.VIEW !== view.VIEW) return null;
  const label = (name, fallback) => controls.find((c) => c.name === name)?.label ?? fallback;
  const samples = values.SAMPLES;
  if (samples === undefined) return null;
  if (!(samples > 1))
    return `"Extra samples" view: ${label('SAMPLES', 'SAMPLES')} is 1, so no pixel takes extra samples and none is marked.`;
  if (values.ADAPTIVE_AA === undefined || values.ADAPTIVE_AA) return null;
  return `"Extra samples" view: ${label('ADAPTIVE_AA', 'ADAPTIVE_AA')} is off, so every pixel takes all ${samples} samples (uniform supersampling) and none is marked.`;
}
