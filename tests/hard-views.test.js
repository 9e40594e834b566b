// Hard views (tests/hard-views.js): the page's float32 image against the float64 reference
// with the same rays. Free of NaN, of shadow acne and of speckle means: almost no pixel is off
// by more than 2/255 (acne or speckle would put whole areas there).
import fs from 'node:fs';
import { afterAll, describe, expect, test } from 'vitest';
import { parseControls } from '../src/shadertoy/controls.js';
import { renderReference } from '../src/reference/render.js';
import { imageError, formatImageError } from '../src/reference/error.js';
import { SHADER_FILE } from './harness/config.js';
import { assertNotBlank } from './harness/images.js';
import { disconnect, renderView } from './harness/page.js';
import { viewControlProblems } from './views.js';
import { HARD_VIEWS, MAX_OVER_2, referenceView } from './hard-views.js';

afterAll(disconnect);

const source = fs.readFileSync(SHADER_FILE, 'utf8');
const controls = parseControls(source);

describe('hard views against the same-ray float64 reference', () => {
  test.each(HARD_VIEWS.map((v) => [v.name, v]))('%s', async (_, view) => {
    expect(viewControlProblems(view, controls)).toEqual([]);
    const image = await renderView(view);
    if (!view.uniform) assertNotBlank(image, view.name);
    const error = imageError(image, renderReference(source, referenceView(view)));
    console.log(`${view.name}: ${formatImageError(error)}`);
    expect(error.nonFinite).toBe(0);
    expect(error.over2, `${view.name} (${view.what}): ${formatImageError(error)}`).toBeLessThanOrEqual(view.maxOver2 ?? MAX_OVER_2);
  });
});
