// Render tests: the goldens of tests/golden/ (a `shaderproof test` folder: shaderproof.json and
// __references__/), each case drawn on the engine page and compared by the runner of `shaderproof
// test` (tests/support/goldens.js), a test a case. Then what keeps the tolerance honest: each
// golden is a rendered scene, every pair of goldens differs by far more than the tolerance
// allows, and so does each view that sets a control no other view contrasts with the same view
// without it.
import fs from 'node:fs';
import { afterAll, describe, expect, test } from 'vitest';
import { parseControls } from '../../src/shadertoy/controls.js';
import { renderShader } from '../../src/api/render.js';
import { readPng } from '../../src/headless/png.js';
import { SHADER_FILE } from '../support/config.js';
import { assertNotBlank, compareImages } from '../support/images.js';
import { GOLDEN_CASES, closeGoldens, goldenSession, runGolden } from '../support/goldens.js';
import { VIEWS, viewControlProblems } from '../support/tables/views.js';

afterAll(closeGoldens);

const controls = parseControls(fs.readFileSync(SHADER_FILE, 'utf8'));

/** Every pair of goldens, and each view against its contrast, differ in more than this many times the allowed pixels. */
const PAIR_MIN_FACTOR = 10;

/**
 * The views of a few flat colours by design, and the least each must show (a golden is checked
 * to be a rendered scene: assertNotBlank, at least 16 colours otherwise).
 */
const FLAT_COLOURS = { 'view-object': 5, 'view-bounces': 4 };

/**
 * Views whose point is one control that no other view contrasts them with: each must differ from
 * itself with these controls in more than PAIR_MIN_FACTOR x the allowed pixels, so that the view
 * really tests what it sets (the 4th bounce; uniform supersampling against one sample).
 */
const CONTRASTS = { 'bounces-max': { BOUNCES: 3 }, aa: { SAMPLES: 1 } };

/** The fraction of a case's pixels its tolerance lets differ. */
const allowedFraction = (testCase) => testCase.tolerance.maxDiffPixels / (testCase.view.size.width * testCase.view.size.height);

describe('views match their goldens', () => {
  test.each(GOLDEN_CASES.map((c) => [c.name]))('%s', async (name) => {
    // A renamed control would otherwise be refused by the page; one out of range, clamped
    const view = VIEWS.find((v) => v.name === name);
    expect(viewControlProblems(view, controls)).toEqual([]);
    const { testCase, result } = await runGolden(name);
    // within the tolerance, and not the same: said (another renderer's rounding, or a new Chromium's)
    if (result.diffPixels) console.log(`${name}: ${result.diffPixels} pixels differ (at most ${result.tolerance.maxDiffPixels} may)`);
    assertNotBlank(readPng(testCase.reference), `${name} (${testCase.reference})`, { minColours: FLAT_COLOURS[name] ?? 16 });
  });
});

test(`every pair of distinct goldens differs in more than ${PAIR_MIN_FACTOR}x the allowed fraction of pixels`, () => {
  const images = GOLDEN_CASES.map((c) => ({ testCase: c, image: readPng(c.reference) }));
  const tooClose = [];
  let closest = { fraction: Infinity, pair: '' };
  for (let i = 0; i < images.length; i++) {
    for (let j = i + 1; j < images.length; j++) {
      const [a, b] = [images[i], images[j]];
      const needed = PAIR_MIN_FACTOR * Math.max(allowedFraction(a.testCase), allowedFraction(b.testCase));
      const threshold = Math.max(a.testCase.tolerance.threshold, b.testCase.tolerance.threshold);
      const { fraction } = compareImages(a.image, b.image, { threshold });
      const pair = `${a.testCase.name} vs ${b.testCase.name}`;
      if (fraction < closest.fraction) closest = { fraction, pair };
      if (fraction < needed)
        tooClose.push(`${pair}: ${(100 * fraction).toFixed(2)}% of pixels differ (need ${(100 * needed).toFixed(2)}%)`);
    }
  }
  console.log(`closest pair of goldens: ${closest.pair}, ${(100 * closest.fraction).toFixed(2)}% of pixels differ`);
  expect(tooClose, 'views that the tolerance cannot tell apart').toEqual([]);
});

test.each(Object.entries(CONTRASTS).map(([name, contrast]) => [name, JSON.stringify(contrast), contrast]))(
  `%s differs from itself with %s in more than ${PAIR_MIN_FACTOR}x the allowed fraction of pixels`,
  async (name, _, contrast) => {
    const testCase = GOLDEN_CASES.find((c) => c.name === name);
    const view = VIEWS.find((v) => v.name === name);
    expect(viewControlProblems({ ...view, params: { ...view.params, ...contrast } }, controls)).toEqual([]);
    const changed = Object.entries(contrast).map(([key, value]) => /** @type {[string, string]} */ ([key, String(value)]));
    const kept = testCase.view.controls.filter(([key]) => !(key in contrast));
    const image = await renderShader(await goldenSession(), testCase.file, { ...testCase.view, controls: [...kept, ...changed] });
    const { fraction } = compareImages(image, readPng(testCase.reference), { threshold: testCase.tolerance.threshold });
    console.log(`${name} vs ${name} with ${JSON.stringify(contrast)}: ${(100 * fraction).toFixed(2)}% of pixels differ`);
    expect(fraction).toBeGreaterThan(PAIR_MIN_FACTOR * allowedFraction(testCase));
  },
);
