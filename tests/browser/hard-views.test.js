// Hard views (tests/support/tables/hard-views.js): the page's float32 image against the float64 reference
// with the same rays. Free of NaN, of shadow acne and of speckle means: almost no pixel is off
// by more than 2/255 (acne or speckle would put whole areas there).
import fs from 'node:fs';
import { afterAll, describe, expect, test } from 'vitest';
import { parseControls } from '../../src/shadertoy/controls.js';
import { formatImageError } from '../../src/reference/error.js';
import { SHADER_FILE } from '../support/config.js';
import { assertNotBlank } from '../support/images.js';
import { disconnect } from '../support/page.js';
import { measureSameRay } from '../support/reference/same-ray.js';
import { viewControlProblems } from '../support/tables/views.js';
import { HARD_VIEWS, MAX_OVER_2 } from '../support/tables/hard-views.js';

afterAll(disconnect);

const source = fs.readFileSync(SHADER_FILE, 'utf8');
const controls = parseControls(source);

describe('hard views against the same-ray float64 reference', () => {
  test.each(HARD_VIEWS.map((v) => [v.name, { ...v, params: { ...v.params, SAMPLES: 1 } }]))('%s, one sample per pixel', async (_, view) => {
    expect(viewControlProblems(view, controls)).toEqual([]);
    const { image, error } = await measureSameRay(source, view);
    if (!view.uniform) assertNotBlank(image, view.name);
    console.log(`${view.name}: ${formatImageError(error)}`);
    expect(error.nonFinite).toBe(0);
    expect(error.over2, `${view.name} (${view.what}): ${formatImageError(error)}`).toBeLessThanOrEqual(view.maxOver2 ?? MAX_OVER_2);
  });

  // With adaptive anti-aliasing the same rays are the shader's: the pixels its "Extra samples" debug
  // view marks take the 4x4 grid, the others their centre. The same bound holds.
  test.each(HARD_VIEWS.map((v) => [v.name, v]))('%s, adaptive anti-aliasing', async (_, view) => {
    const adaptive = { ...view, params: { ...view.params, SAMPLES: 16, ADAPTIVE_AA: 1 } };
    const { error, share } = await measureSameRay(source, adaptive);
    console.log(`${view.name}, adaptive (extra samples in ${(100 * (share ?? 0)).toFixed(2)}% of pixels): ${formatImageError(error)}`);
    expect(error.nonFinite).toBe(0);
    expect(error.over2, `${view.name}, adaptive: ${formatImageError(error)}`).toBeLessThanOrEqual(
      view.adaptiveMaxOver2 ?? view.maxOver2 ?? MAX_OVER_2,
    );
  });
});
