// Shadertoy's frame-0 contract (issue 24, item 1): a shader loaded in place of another (dropped,
// pasted into the editor, given to setProject) starts at iFrame 0 and iTime 0 with cleared
// buffers, and Restart gives a frame 0 whether the page plays or is paused. A real shader whose
// buffers set themselves up on frame 0 (Shadertoy 3tBGzh, "Biological Particles") stayed black
// for good without it.
//
// The test shader is the smallest such case: Buffer A writes white only on iFrame 0 and keeps
// its value after; the Image pass paints green when A was set up, red when it was not. Its Image
// pass is made slow (a loop per pixel) so that a frame is under way when Restart comes, which is
// when the frame-0 was lost: the frame under way landed after the rewind and counted as frame 0.

import { afterAll, describe, expect, test } from 'vitest';
import { allowClipboard, button, pasteIntoEditor, pixel, readPixels, withPage } from '../support/page-helpers.js';
import { dropFile, exportOf } from '../support/page-multipass-helpers.js';
import { disconnect } from '../support/page.js';
import { hook } from '../support/hook.js';

afterAll(disconnect);

const GREEN = [0, 255, 0];

const SETS_UP_ON_FRAME_0 = [
  'void mainImage(out vec4 fragColor, in vec2 fragCoord) {',
  '    fragColor = iFrame == 0 ? vec4(1.0) : texelFetch(iChannel0, ivec2(fragCoord), 0);',
  '}',
  '',
].join('\n');
/** Green when Buffer A was set up; the loop (kept alive at a weight too small to show) makes a frame take a while. */
const SHOWS_SET_UP = [
  'void mainImage(out vec4 fragColor, in vec2 fragCoord) {',
  '    float slow = 0.0;',
  '    for (int i = 0; i < 4000; i++) slow += sin(float(i) + fragCoord.x);',
  '    bool setUp = texelFetch(iChannel0, ivec2(fragCoord), 0).r > 0.5;',
  '    fragColor = vec4(setUp ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0), 1.0) + 1e-30 * slow;',
  '}',
  '',
].join('\n');
const FRAME_0_SHADER = exportOf({ name: 'Frame zero', common: '', bufferA: SETS_UP_ON_FRAME_0, image: SHOWS_SET_UP });
const FRAME_0_JSON = JSON.stringify(FRAME_0_SHADER);

/** The clock as the next frame gets it: {frame: its iFrame, time: its iTime}. */
const clock = (page) =>
  hook(page)
    .info()
    .then((info) => ({ frame: info.iFrame, time: info.time }));

/** Waits until the page has drawn `n` more frames by itself (it plays). */
async function moreFrames(page, n = 3) {
  const start = await hook(page)
    .info()
    .then((r) => r.frame);
  await page.waitForFunction((until) => window.shaderEngine.info().frame >= until, { polling: 20 }, start + n);
}

/** Does `arrive(page)`, and waits until a shader more has compiled. */
async function compiledAfter(page, arrive) {
  const before = await hook(page)
    .info()
    .then((r) => r.compiled);
  await arrive(page);
  await page.waitForFunction((n) => window.shaderEngine.info().compiled > n, { polling: 20 }, before);
}

/** How each way of bringing the shader in is done, on a page already running another one. @type {Array<[string, (page: import('puppeteer-core').Page) => Promise<unknown>]>} */
const ARRIVALS = [
  ['setProject()', (page) => hook(page).setProject(FRAME_0_JSON)],
  ['a dropped .json file', (page) => dropFile(page, 'frame-zero.json', FRAME_0_JSON, 'application/json')],
  ['a paste into the editor', (page) => pasteIntoEditor(page, FRAME_0_JSON)],
];

describe('a shader loaded in place of another starts at iFrame 0 with cleared buffers', () => {
  test.each(ARRIVALS)('while playing, by %s', async (_, arrive) => {
    await withPage(async ({ page, goto, context }) => {
      await allowClipboard(page, context.baseUrl);
      await goto('?shader=examples/pattern.glsl&size=64x36');
      await moreFrames(page, 4); // the clock has run on: iFrame is past 0
      await compiledAfter(page, arrive);
      await moreFrames(page);
      expect(pixel(await readPixels(page), 10, 10), 'Buffer A was set up on its frame 0').toEqual(GREEN);
    });
  });

  test('on a paused ?time=0 page, by a dropped file: iFrame 0 and iTime 0', async () => {
    await withPage(async ({ page, goto }) => {
      await goto('?shader=examples/pattern.glsl&size=64x36&time=0');
      await readPixels(page); // a frame or two of the paused page: iFrame is past 0
      await readPixels(page);
      expect((await clock(page)).frame).toBeGreaterThan(0);
      await hook(page).setTime(3);
      await compiledAfter(page, (p) => dropFile(p, 'frame-zero.json', FRAME_0_JSON, 'application/json'));
      await page.waitForFunction(() => window.shaderEngine.info().iFrame === 1, { polling: 20 });
      expect(await clock(page)).toEqual({ frame: 1, time: 0 }); // frame 0 drawn at iTime 0, paused
      expect(pixel(await readPixels(page), 10, 10)).toEqual(GREEN);
    });
  });

  test('the first shader of a link keeps the link time (nothing ran before it)', async () => {
    await withPage(async ({ page, goto }) => {
      await goto('?shader=examples/pattern.glsl&size=64x36&time=2.5');
      expect(await clock(page)).toEqual({ frame: 1, time: 2.5 });
    });
  });
});

/** The ways to rewind, each while the page plays and while it is paused. @type {Array<[string, (page: import('puppeteer-core').Page) => Promise<unknown>]>} */
const REWINDS = [
  ['R', (page) => page.keyboard.press('KeyR')],
  ['the Restart button', async (page) => (await button(page, 'Restart')).click()],
];

describe('Restart always gives a frame 0', () => {
  const cases = REWINDS.flatMap(([name, rewind]) =>
    [true, false].map((playing) => /** @type {const} */ ([name, playing ? 'playing' : 'paused', rewind, playing])),
  );
  test.each(cases)('%s while %s', async (_, __, rewind, playing) => {
    await withPage(async ({ page, goto }) => {
      await goto('?size=64x36');
      await hook(page).setProject(FRAME_0_JSON);
      await moreFrames(page);
      if (!playing) await hook(page).pause();
      await page.focus('body'); // R is a key of the page, not of the editor
      // a frame is under way when the rewind comes (the Image pass is slow)
      if (playing) await page.waitForFunction(() => window.shaderEngine.info().progress !== null, { polling: 5 });
      await rewind(page);
      if (playing) await moreFrames(page);
      else await page.waitForFunction(() => window.shaderEngine.info().iFrame === 1, { polling: 20 });
      expect(pixel(await readPixels(page), 10, 10), 'Buffer A was set up on the new frame 0').toEqual(GREEN);
      if (!playing) expect((await clock(page)).time).toBe(0);
    });
  });
});
