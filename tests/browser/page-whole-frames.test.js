// A heavy frame is drawn in bands (src/player/gpu/bands/band-planner.js). A still frame, or the first
// frame of a shader, is shown as it builds up (there is nothing newer to show); frames that
// follow one another while playing are shown only whole (issue 45, item 10): one shown as it
// builds up lies half over the frame before it, a torn picture.
//
// Every picture the page's canvas is given is recorded (its bitmap renderer's
// transferFromImageBitmap, wrapped before the page loads), with the colours in it. The shader's
// colour depends only on iFrame (and on iMouse, still in the playing part), so a whole frame is
// one colour and a torn one is two.

import fs from 'node:fs';
import path from 'node:path';
import { afterAll, describe, expect, test } from 'vitest';
import { disconnect } from '../support/page.js';
import { info, withPage, withServedDir } from '../support/page-helpers.js';
import { hook } from '../support/hook.js';

afterAll(disconnect);

/**
 * One colour a frame, another each next frame (red flips with iFrame's parity, green with its
 * half), more blue once iMouse.x is past 0, and never black (the canvas before a frame); each pixel costs WORK loop trips, whose sum is kept alive
 * at a weight too small to show.
 */
const FRAMES_SHADER = `
const int WORK = 50000;
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float sum = 0.0;
    for (int i = 0; i < WORK; i++) sum += sin(float(i) * 1e-3 + fragCoord.x);
    float f = float(iFrame);
    vec3 colour = 0.25 + 0.5 * vec3(mod(f, 2.0), mod(floor(f / 2.0), 2.0), iMouse.x > 0.0 ? 1.0 : 0.0);
    fragColor = vec4(colour + 1e-30 * sum, 1.0);
}
`;
/**
 * The canvas's size: with WORK trips a pixel, a frame takes about 0.4 s on SwiftShader on an idle
 * machine (60000 trips at 128x72 took 0.45 s: page-heavy.test.js), several bands of ~0.1 s and
 * more than the worker's 0.25 s between pictures of a frame under way; longer on a loaded one.
 */
const SIZE = '128x72';
/** Frames the playing part draws, and the longest it may take (a loaded machine draws slower). */
const FRAMES = 3;
const PLAY_TIMEOUT_MS = 60_000;

/**
 * Before the page loads: every bitmap the canvas is shown is recorded in window.__shown as the
 * list of its distinct colours (at most 4).
 */
function recordShown() {
  /** @type {number[][]} */
  const shown = [];
  window.__shown = shown;
  const proto = ImageBitmapRenderingContext.prototype;
  const transfer = proto.transferFromImageBitmap;
  proto.transferFromImageBitmap = function (bitmap) {
    if (bitmap && /** @type {HTMLCanvasElement} */ (this.canvas).id === 'view') {
      const copy = new OffscreenCanvas(bitmap.width, bitmap.height);
      const g = /** @type {OffscreenCanvasRenderingContext2D} */ (copy.getContext('2d', { willReadFrequently: true }));
      g.drawImage(bitmap, 0, 0);
      const data = g.getImageData(0, 0, bitmap.width, bitmap.height).data;
      const colours = new Set();
      for (let i = 0; i < data.length && colours.size < 4; i += 4) colours.add((data[i] << 16) | (data[i + 1] << 8) | data[i + 2]);
      shown.push([...colours]);
    }
    return transfer.call(this, bitmap);
  };
}

/** The pictures shown from the `from`th on. @returns {Promise<number[][]>} */
const shownSince = (page, from) => page.evaluate((n) => window.__shown.slice(n), from);
const torn = (/** @type {number[][]} */ pictures) => pictures.filter((colours) => colours.length > 1);

describe('a heavy shader: built up when still or new, whole frames while playing', () => {
  test('the first frame builds up; playing shows one colour a picture; a still frame builds up again', async () => {
    await withServedDir('test-whole-frames', async (dir, base) => {
      fs.writeFileSync(path.join(dir, 'frames.glsl'), FRAMES_SHADER);
      await withPage(
        async ({ page, goto }) => {
          // it plays from its load (no ?time=)
          await goto(`?shader=${base}/frames.glsl&size=${SIZE}`);
          const first = await shownSince(page, 0);
          expect(torn(first).length, `the first frame shown as it built up: ${JSON.stringify(first)}`).toBeGreaterThan(0);

          const mark = (await shownSince(page, 0)).length;
          const from = (await info(page)).frame;
          await page.waitForFunction(
            (n) => window.shaderEngine.info().frame >= n,
            { polling: 100, timeout: PLAY_TIMEOUT_MS },
            from + FRAMES,
          );
          await hook(page).pause();
          const playing = await shownSince(page, mark);
          const frames = new Set(playing.map((colours) => colours.join()));
          expect(frames.size, `frames shown while playing: ${JSON.stringify(playing)}`).toBeGreaterThanOrEqual(3);
          expect(torn(playing), `pictures of two frames at once while playing, of ${playing.length}`).toEqual([]);

          // paused: a still frame (a new iMouse) builds up over the one before, as it is drawn
          const still = (await shownSince(page, 0)).length;
          await hook(page).setMouse([10, 10, 0, 0]);
          await hook(page).readPixels();
          const built = await shownSince(page, still);
          expect(torn(built).length, `the still frame shown as it built up: ${JSON.stringify(built)}`).toBeGreaterThan(0);
        },
        { deterministic: false, beforeLoad: (page) => page.evaluateOnNewDocument(recordShown) },
      );
    });
  });
});
