// Render tests: each view of tests/views.js, rendered by the real page in headless Chromium
// (SwiftShader), must match tests/golden/<name>.png within the tolerance written in views.js.
import fs from 'node:fs';
import { afterAll, describe, expect, test } from 'vitest';
import { parseControls } from '../src/shadertoy/controls.js';
import { SHADER_FILE } from './harness/config.js';
import { assertNotBlank, compareImages, expectMatchesGolden } from './harness/images.js';
import { disconnect, renderView } from './harness/page.js';
import { MAX_DIFF_FRACTION, PAIR_MIN_FACTOR, VIEWS, viewControlProblems } from './views.js';

afterAll(disconnect);

const controls = parseControls(fs.readFileSync(SHADER_FILE, 'utf8'));

// One render per view, shared by the golden test and the pairwise test.
const renders = new Map();
function render(view) {
  if (!renders.has(view.name)) renders.set(view.name, renderView(view));
  return renders.get(view.name);
}

describe('views match their goldens', () => {
  test.each(VIEWS.map((v) => [v.name, v]))('%s', async (_, view) => {
    // A renamed control would otherwise be ignored by the page and render the default.
    expect(viewControlProblems(view, controls)).toEqual([]);
    const image = await render(view);
    assertNotBlank(image, `${view.name} (${image.url})`, { minColours: view.flatColours ?? 16 });
    await expectMatchesGolden(view.name, image);
  });
});

test(`every pair of distinct views differs in more than ${PAIR_MIN_FACTOR}x the allowed fraction of pixels`, async () => {
  const images = [];
  for (const view of VIEWS) images.push({ name: view.name, image: await render(view) });
  const tooClose = [];
  const needed = PAIR_MIN_FACTOR * MAX_DIFF_FRACTION;
  let closest = { fraction: Infinity };
  for (let i = 0; i < images.length; i++) {
    for (let j = i + 1; j < images.length; j++) {
      const { fraction } = compareImages(images[i].image, images[j].image);
      if (fraction < closest.fraction) closest = { fraction, pair: `${images[i].name} vs ${images[j].name}` };
      if (fraction < needed) {
        tooClose.push(
          `${images[i].name} vs ${images[j].name}: ${(100 * fraction).toFixed(2)}% of pixels differ (need ${(100 * needed).toFixed(2)}%)`,
        );
      }
    }
  }
  console.log(
    `closest pair of views: ${closest.pair}, ${(100 * closest.fraction).toFixed(2)}% of pixels differ (tolerance ${(100 * MAX_DIFF_FRACTION).toFixed(2)}%)`,
  );
  expect(tooClose, 'views that the tolerance cannot tell apart').toEqual([]);
});

const contrasted = VIEWS.filter((v) => v.contrast);
test.each(contrasted.map((v) => [v.name, JSON.stringify(v.contrast), v]))(
  `%s differs from itself with %s in more than ${PAIR_MIN_FACTOR}x the allowed fraction of pixels`,
  async (_, __, view) => {
    const other = { name: `${view.name}-contrast`, params: { ...view.params, ...view.contrast }, size: view.size };
    expect(viewControlProblems(other, controls)).toEqual([]);
    const { fraction } = compareImages(await render(view), await renderView(other));
    console.log(`${view.name} vs ${other.name}: ${(100 * fraction).toFixed(2)}% of pixels differ`);
    expect(fraction).toBeGreaterThan(PAIR_MIN_FACTOR * MAX_DIFF_FRACTION);
  },
);
