// "Converge when still" (issue 13): the built-in raytracer as its progressive multipass form in
// the page. After N still frames the picture (what Screenshot saves: the Image pass over the
// buffer) is within the same bounds of the float64 reference with N samples of the same jitter
// sequence as the raw-WebGL run in tests/browser/progressive.test.js, and a change starts the sum again.

import fs from 'node:fs';
import { describe, expect, test } from 'vitest';
import { formatImageError, imageError } from '../../src/reference/error.js';
import { renderReference } from '../../src/reference/render.js';
import { SHADER_FILE } from '../support/config.js';
import { decodeRgba } from '../support/page.js';
import { info, withPage, sharePageAcrossTests } from '../support/page-helpers.js';
import { hook } from '../support/hook.js';

// not a test of loading the page: the tests share one, brought to each view by open()
sharePageAcrossTests();

const WIDTH = 64;
const HEIGHT = 36;
const FRAMES = 16;
/** The bounds tests/browser/progressive.test.js holds the progressive buffer to, for the same reason:
 * the page's image is 8-bit, so RMSE 2e-3 and no pixel 8/255 away is a match to the reference. */
const RMSE_BOUND = 2e-3;
const MAX_BOUND = 8 / 255;

describe('Converge when still', () => {
  test(`${FRAMES} still frames of the built-in raytracer match the float64 reference with ${FRAMES} samples; a change starts again`, async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`?size=${WIDTH}x${HEIGHT}&time=0`);
      await hook(page).setConverging(true, { frames: FRAMES });
      expect((await info(page)).controls.SHOW_SAMPLE_COUNT).toBe(1); // the count is shown
      // without the count drawn over it (the form's on-screen overlay, off as a render asks): the picture alone
      await hook(page).setConverging(true, { frames: FRAMES, overlays: false });
      expect((await info(page)).controls.SHOW_SAMPLE_COUNT).toBe(0);
      // the compiles settle (the live controls end as constants); a Restart then clears the sum
      await page.waitForFunction(() => window.shaderEngine.info().liveControls === 'constants', { polling: 100 });
      await hook(page).restart();
      await page.waitForFunction((n) => window.shaderEngine.info().stillFrames >= n, { polling: 100 }, FRAMES);
      const state = await info(page);
      expect(state.converging).toBe(true);
      expect(state.playing).toBe(false);
      expect(state.stillFrames).toBe(FRAMES); // and no more: it stops when it has them

      const shot = await hook(page).capture();
      const image = { width: shot.width, height: shot.height, data: decodeRgba(shot.data, shot.width, shot.height, 'capture') };
      const source = fs.readFileSync(SHADER_FILE, 'utf8');
      const reference = renderReference(
        source,
        { width: WIDTH, height: HEIGHT, time: 0, mouse: [0, 0, 0, 0] },
        { mode: 'progressive', samples: FRAMES },
      );
      const error = imageError(image, reference);
      console.log(`page, converged ${FRAMES} frames at ${WIDTH}x${HEIGHT}: ${formatImageError(error)}`);
      expect(error.rmse).toBeLessThan(RMSE_BOUND);
      expect(error.maxAbs).toBeLessThanOrEqual(MAX_BOUND);

      // the camera moves: the sum starts again from the new view's first sample
      const moved = [40, 30, 40, -30];
      await hook(page).setConverging(true, { frames: 1 });
      await page.waitForFunction(() => window.shaderEngine.info().stillFrames === 1, { polling: 50 });
      const before = (await info(page)).frame;
      await hook(page).setMouse(moved);
      await page.waitForFunction(
        (f) => window.shaderEngine.info().frame > f && window.shaderEngine.info().stillFrames === 1,
        { polling: 50 },
        before,
      );
      const restarted = await hook(page).capture();
      const first = renderReference(source, { width: WIDTH, height: HEIGHT, time: 0, mouse: moved }, { mode: 'progressive', samples: 1 });
      const restartError = imageError(
        { width: WIDTH, height: HEIGHT, data: decodeRgba(restarted.data, WIDTH, HEIGHT, 'capture after the camera moved') },
        first,
      );
      console.log(`page, one frame after the camera moved: ${formatImageError(restartError)}`);
      expect(restartError.rmse).toBeLessThan(RMSE_BOUND);

      // off again: the single-pass shader as it was
      await hook(page).setConverging(false);
      const after = await info(page);
      expect(after.converging).toBe(false);
      expect(after.fileName).toBe('shaders/raytrace.glsl');
    });
  });

  test('while converging, Compare and the path say why they are not there and how to turn it off', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`?size=${WIDTH}x${HEIGHT}&time=0`);
      await hook(page).setConverging(true, { frames: 2 });
      const refused = await page.evaluate(() =>
        window.shaderEngine.compareWithFloat64().then(
          () => null,
          (e) => e.message,
        ),
      );
      for (const said of [refused, (await hook(page).inspect(20, 20)).pathNote]) {
        expect(said).toMatch(/Converge when still.*turn that off \(Controls → View\)/);
        expect(said).not.toMatch(/buffers of its own/);
      }
      // off again: both are there
      await hook(page).setConverging(false);
      const readout = await hook(page).inspect(20, 20);
      expect(readout.path?.rays.length).toBeGreaterThan(0);
    });
  });

  test('a shader that is not the raytracer cannot converge: the toggle is off limits and the hook says why', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`?shader=examples/pattern.glsl&size=${WIDTH}x${HEIGHT}&time=0`);
      const disabled = await page.evaluate(() => {
        const row = [...document.querySelectorAll('.lil-gui .lil-controller')].find((c) => c.textContent?.includes('Converge when still'));
        return row?.classList.contains('lil-disabled');
      });
      expect(disabled).toBe(true);
      const refused = await page.evaluate(() =>
        window.shaderEngine.setConverging(true).then(
          () => null,
          (e) => e.message,
        ),
      );
      expect(refused).toContain('only the raytracer converges');
      expect((await info(page)).converging).toBe(false);
    });
  });

  // Each drawn frame brings its own times (issue 17): a converging view's frames, drawn while the
  // clock is paused, are in the readout as they come, not held back until the next Play.
  test("converging frames are in the frame-time graph as they are drawn, not piled onto the next Play's", async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`?size=${WIDTH}x${HEIGHT}&time=0`);
      await hook(page).setConverging(true, { frames: 40 });
      await page.waitForFunction(() => window.shaderEngine.info().stillFrames >= 12, { polling: 50 });
      const graphFrames = () => page.$eval('#toolbar canvas.graph', (c) => Number(/** @type {HTMLElement} */ (c).dataset.frames ?? 0));
      expect(await graphFrames(), 'the frames drawn while converging are in the graph').toBeGreaterThanOrEqual(8);
      expect(await page.$eval('#toolbar .fps', (e) => e.textContent)).toMatch(/^Converging · \d+ samples/);
      await page.waitForFunction(() => window.shaderEngine.info().stillFrames >= 40, { polling: 50 });
      await page.waitForFunction(() => /^Converged · 40 samples$/.test(document.querySelector('#toolbar .fps').textContent), {
        polling: 50,
      });
      // Play: the graph starts again with the frames played, nothing left over from converging
      await hook(page).setConverging(false);
      const before = (await info(page)).frame;
      await hook(page).play();
      await page.waitForFunction((f) => window.shaderEngine.info().frame >= f + 3, { polling: 20 }, before);
      const [inGraph, played] = await page.evaluate(() => [
        Number(document.querySelector('#toolbar canvas.graph').getAttribute('data-frames')),
        window.shaderEngine.info().frame,
      ]);
      expect(inGraph).toBeGreaterThan(0);
      expect(inGraph).toBeLessThanOrEqual(played - before);
    });
  });
});
