// Time, view and URL, through the page's own widgets in the real browser: Play/Pause (and Space),
// Restart (and R), the time slider, the speed, the frame-time graph; the resolution scale, the
// size cap, window resizes and devicePixelRatio changes; and URLs full of bad values, which must
// be clamped or ignored with a console warning, never break the page.
import { afterAll, describe, expect, test } from 'vitest';
import { assertNotBlank, differingPixels, sameImage } from '../support/images.js';
import { disconnect } from '../support/page.js';
import { button, editorText, info, overlayText, readPixels, typeInEditor, withPage } from '../support/page-helpers.js';
import { hook } from '../support/hook.js';

afterAll(disconnect);

const PATTERN = 'shader=examples/pattern.glsl';
// (an input event's handler has run when the page shows its effect: wait for it, do not race it)
const playing = (page) =>
  hook(page)
    .info()
    .then((r) => r.playing);
const whenPlaying = (page, value) => page.waitForFunction((v) => window.shaderEngine.info().playing === v, { polling: 20 }, value);
const playLabel = (page) => page.$eval('#toolbar button.play', (b) => b.getAttribute('aria-label'));

describe('time', () => {
  test('Play and Pause buttons, Space, Restart button and R', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`?${PATTERN}&size=160x90&time=5`);
      expect(await playing(page)).toBe(false);
      expect(await playLabel(page)).toBe('Play');

      await (await button(page, 'Play')).click();
      await whenPlaying(page, true);
      expect(await playLabel(page)).toBe('Pause');
      await page.waitForFunction(() => window.shaderEngine.info().time > 5.1, { polling: 50 });

      await (await button(page, 'Pause')).click();
      await whenPlaying(page, false);
      const paused = (await info(page)).time;
      await new Promise((r) => setTimeout(r, 300));
      expect((await info(page)).time).toBe(paused);

      await page.evaluate(() => /** @type {HTMLElement | null} */ (document.activeElement)?.blur());
      await page.keyboard.press('Space');
      await whenPlaying(page, true);
      expect(await playLabel(page)).toBe('Pause');
      await page.keyboard.press('Space');
      await whenPlaying(page, false);
      expect(await playLabel(page)).toBe('Play');

      await (await button(page, 'Restart')).click();
      await page.waitForFunction(() => window.shaderEngine.info().time === 0);
      expect(await playing(page)).toBe(false); // restart keeps the play state

      await hook(page).setTime(7);
      await page.keyboard.press('KeyR');
      await page.waitForFunction(() => window.shaderEngine.info().time === 0, { polling: 20 });

      // Space typed into the editor is text, not a shortcut
      const length = (await editorText(page)).length;
      await typeInEditor(page, ' ');
      await page.waitForFunction((n) => window.shaderEngine.editorSource().length === n + 1, { polling: 20 }, length);
      expect(await playing(page)).toBe(false);
    });
  });

  test('the time slider sets iTime; the speed control scales it; the graph shows frame times and fps', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`?${PATTERN}&size=96x54&time=1`);
      const slider = await page.$('::-p-aria([name="Time"][role="slider"])');
      expect(await slider.evaluate((s) => /** @type {HTMLInputElement} */ (s).value)).toBe('1');
      const before = await readPixels(page);
      await slider.focus();
      await page.keyboard.press('End'); // the slider's end: 60 s
      await page.waitForFunction(() => window.shaderEngine.info().time === 60, { polling: 20 });
      expect(await page.$eval('#toolbar output.time', (o) => o.textContent)).toBe('60.00 s');
      const after = await readPixels(page);
      expect(sameImage(before, after)).toBe(false); // the picture moved with time
      await page.keyboard.press('Home');
      await page.waitForFunction(() => window.shaderEngine.info().time === 0, { polling: 20 });

      const speed = await page.$('::-p-aria([name="Speed"][role="combobox"])');
      await speed.select('4');
      await page.waitForFunction(() => window.shaderEngine.info().speed === 4, { polling: 20 });
      // play: the test clock gives every animation frame 1/60 s, so iTime grows 4/60 a frame
      const start = await info(page);
      await hook(page).play();
      await page.waitForFunction((f) => window.shaderEngine.info().frame >= f + 20, { polling: 50 }, start.frame);
      await hook(page).pause();
      const end = await info(page);
      const perFrame = (end.time - start.time) / (end.frame - start.frame);
      expect(perFrame).toBeGreaterThan(3.5 / 60);
      expect(perFrame).toBeLessThan(4.5 / 60);

      // the readout and the graph were drawn while playing (the clock runs at 60 fps)
      await hook(page).play();
      await page.waitForFunction(() => /fps/.test(document.querySelector('#toolbar .fps').textContent), { polling: 50 });
      // (GPU time where the browser measures it, real and not on the test clock)
      expect(await page.$eval('#toolbar .fps', (e) => e.textContent)).toMatch(/^(GPU \d+\.\d ms|16\.7 ms between frames) · 60 fps$/);
      // green bars, as frames come (a loaded machine may have drawn only a few when the line shows)
      const drawn = await page
        .waitForFunction(
          () => {
            const c = /** @type {HTMLCanvasElement} */ (document.querySelector('#toolbar canvas.graph'));
            const d = /** @type {CanvasRenderingContext2D} */ (c.getContext('2d')).getImageData(0, 0, c.width, c.height).data;
            let bars = 0;
            for (let i = 0; i < d.length; i += 4) if (d[i + 1] > 120 && d[i] < 120) bars++;
            return bars > 10 && bars;
          },
          { polling: 50, timeout: 20_000 },
        )
        .then((handle) => handle.jsonValue());
      expect(drawn).toBeGreaterThan(10);
      await (await button(page, 'Pause')).click();
      expect(await page.$eval('#toolbar .fps', (e) => e.textContent)).toBe('Paused');
    });
  });
});

describe('size', () => {
  const bufferSize = (page) =>
    page.evaluate(() => {
      const c = /** @type {HTMLCanvasElement} */ (document.getElementById('view'));
      return { width: c.width, height: c.height, cssWidth: c.clientWidth, cssHeight: c.clientHeight, dpr: devicePixelRatio };
    });
  const settle = (page) =>
    hook(page)
      .readPixels()
      .then(() => null);

  /** The pattern at `query` in a window of `viewport`: body(page, size) with the canvas's first size. */
  const inWindow = (query, viewport, body) =>
    withPage(
      async ({ page, goto }) => {
        await goto(`?${PATTERN}&time=1${query}`);
        await body(page, await bufferSize(page));
      },
      { viewport },
    );

  test('the canvas follows window resizes and devicePixelRatio changes', async () => {
    await inWindow('', { width: 320, height: 240, deviceScaleFactor: 1 }, async (page, size) => {
      expect([size.width, size.height]).toEqual([size.cssWidth, size.cssHeight]);
      expect(size.width).toBe(320);

      await page.setViewport({ width: 240, height: 200, deviceScaleFactor: 1 });
      await page.waitForFunction(() => /** @type {HTMLCanvasElement} */ (document.getElementById('view')).width === 240);
      await settle(page);
      size = await bufferSize(page);
      expect([size.width, size.height]).toEqual([240, size.cssHeight]);

      await page.setViewport({ width: 240, height: 200, deviceScaleFactor: 2 });
      await page.waitForFunction(() => /** @type {HTMLCanvasElement} */ (document.getElementById('view')).width === 480);
      await settle(page);
      size = await bufferSize(page);
      expect(size.dpr).toBe(2);
      expect([size.width, size.height]).toEqual([2 * size.cssWidth, 2 * size.cssHeight]);
      expect((await info(page)).width).toBe(480);
    });
  });

  test('resolution scale and size cap', async () => {
    await inWindow('&scale=0.5', { width: 640, height: 480, deviceScaleFactor: 2 }, async (page, size) => {
      expect(size.width).toBe(Math.round(size.cssWidth * 2 * 0.5));
      expect(size.height).toBe(Math.round(size.cssHeight * 2 * 0.5));

      const cap = await page.$('::-p-aria([name="Max canvas size"][role="combobox"])');
      await cap.select('320 px');
      await page.waitForFunction(() => {
        const c = /** @type {HTMLCanvasElement} */ (document.getElementById('view'));
        return Math.max(c.width, c.height) === 320;
      });
      await settle(page);
      size = await bufferSize(page);
      const aspect = size.cssWidth / size.cssHeight;
      expect(Math.abs(size.width / size.height - aspect)).toBeLessThan(0.02);
      // the window's size is the sender's: a link pins only a size the user fixed (?size=)
      expect(new URL(await hook(page).shareUrl()).searchParams.has('size')).toBe(false);
    });
  });

  test('a fixed size larger than the window is shown whole, drawn at full size', async () => {
    await inWindow('&size=640x360', { width: 300, height: 400, deviceScaleFactor: 1 }, async (page, size) => {
      expect([size.width, size.height]).toEqual([640, 360]);
      expect(size.cssWidth).toBeLessThanOrEqual(300);
      expect(Math.abs(size.cssWidth / size.cssHeight - 640 / 360)).toBeLessThan(0.05);
    });
  });
});

describe('the URL', () => {
  test('controls in the URL reach the shader and the panel; the panel is rebuilt per shader', async () => {
    await withPage(async ({ page, goto }) => {
      await goto('?shader=examples/raymarch.glsl&size=96x54&time=1&TWIST=2.5&MAX_STEPS=64');
      expect((await info(page)).controls).toMatchObject({ TWIST: 2.5, MAX_STEPS: 64 });
      const twist = await page.$('::-p-aria([name="Twist (radians per unit)"])');
      expect(twist).not.toBeNull();
      expect(await page.$$eval('.lil-gui input', (inputs) => inputs.map((i) => i.value))).toContain('2.5');
      expect(await hook(page).loadShader('examples/pattern.glsl')).toEqual({ ok: true });
      expect((await info(page)).controls).toEqual({});
      expect(await page.$('::-p-aria([name="Twist (radians per unit)"])')).toBeNull();
      expect(await page.$$eval('.lil-gui .lil-title', (els) => els.map((e) => e.textContent.trim()))).not.toContain('Shader controls');
    });
  });

  // A live (`const`) control is a uniform while it moves and a constant once it rests, so the
  // still page runs the shader as it pastes (src/player/app/live-controls.js, SPECIALIZE_AFTER_MS): both forms show
  // the same picture, and a move back is drawn at once from the uniform form kept compiled.
  test('live controls: uniforms while they move, compiled in as constants when still', async () => {
    await withPage(async ({ page, goto }) => {
      await goto('?size=96x54&time=0');
      expect((await info(page)).liveControls).toBe('constants');
      const before = await readPixels(page);
      await hook(page).setControls({ CONE_HEIGHT: 2.6 });
      expect((await info(page)).liveControls).toBe('uniforms');
      const moving = await readPixels(page);
      await page.waitForFunction(() => window.shaderEngine.info().liveControls === 'constants', { polling: 50, timeout: 10000 });
      const still = await readPixels(page);
      expect(sameImage(still, before)).toBe(false); // the change is drawn ...
      expect(differingPixels(moving, still, 2).count).toBe(0); // ... the same by both forms
      await hook(page).setControls({ CONE_HEIGHT: 1.7 });
      expect(differingPixels(await readPixels(page), before, 2).count).toBe(0);
    });
  });

  // Each bad URL: the page still draws a picture, warns on the console naming the parameter, and
  // logs no error. `check` looks at what the page made of it.
  /** @type {Array<[name: string, query: string, warned: string, check: (s: import('../globals.js').HookInfo) => void, options?: {mayBeDark?: boolean}]>} */
  const BAD_URLS = [
    ['time=NaN', `${PATTERN}&size=64x36&time=NaN`, 'time=NaN', (s) => expect(s.playing).toBe(true)],
    ['negative time', `${PATTERN}&size=64x36&time=-3`, 'time=-3', (s) => expect(s.time).toBe(0)],
    ['mouse with a word', `${PATTERN}&size=64x36&time=0&mouse=1,2,x,4`, 'mouse=', (s) => expect(s.mouse).toEqual([0, 0, 0, 0])],
    ['size 0x0', `${PATTERN}&size=0x0&time=0`, 'size=0x0', (s) => expect(s.width).toBeGreaterThan(0)],
    ['size in words', `${PATTERN}&size=bigxsmall&time=0`, 'size=', (s) => expect(s.width).toBeGreaterThan(0)],
    [
      'absurd width',
      `${PATTERN}&size=99999x50&time=0`,
      'size=',
      (s) => expect([s.width <= 16384, s.width / s.height]).toEqual([true, 2048]),
      { mayBeDark: true },
    ],
    ['scale out of range', `${PATTERN}&scale=40&time=0`, 'scale=40', () => {}],
    ['cap below the minimum', `${PATTERN}&cap=2&time=0`, 'cap=2', (s) => expect(Math.max(s.width, s.height)).toBe(16)],
    ['speed NaN', `${PATTERN}&size=64x36&speed=NaN`, 'speed=NaN', (s) => expect(s.speed).toBe(1)],
    [
      'unknown control',
      `shader=examples/raymarch.glsl&size=64x36&time=0&NO_SUCH=1`,
      'NO_SUCH',
      (s) => expect(s.controls).not.toHaveProperty('NO_SUCH'),
    ],
    [
      'control not a number',
      `shader=examples/raymarch.glsl&size=64x36&time=0&TWIST=abc`,
      'TWIST',
      (s) => expect(s.controls.TWIST).toBe(1.2),
    ],
    [
      'control out of range',
      `shader=examples/raymarch.glsl&size=64x36&time=0&TWIST=99`,
      'TWIST=99',
      (s) => expect(s.controls.TWIST).toBe(4),
    ],
    [
      'vector of the wrong length',
      `shader=examples/raymarch.glsl&size=64x36&time=0&ALBEDO=1,2`,
      'ALBEDO',
      (s) => expect(s.controls.ALBEDO).toEqual([0.85, 0.42, 0.18]),
    ],
    [
      'shader on another site',
      `shader=https://example.com/evil.glsl&size=64x36&time=0`,
      'shader=',
      (s) => expect(s.fileName).toBe('shaders/raytrace.glsl'),
    ],
    [
      'shader that does not exist',
      `shader=examples/missing.glsl&size=64x36&time=0`,
      'missing.glsl',
      (s) => expect(s.origin).toBe('builtin'),
    ],
    ['channel that does not exist', `${PATTERN}&size=64x36&time=0&iChannel0=nope.png`, 'iChannel0=nope.png', () => {}],
    ['a name that is no name', `${PATTERN}&size=64x36&time=0&a%20b=1`, 'a b=1', () => {}],
  ];
  test.each(BAD_URLS)('%s', async (_, query, warned, check, { mayBeDark = false } = {}) => {
    await withPage(async ({ page, warnings, goto }) => {
      await goto(`?${query}`);
      const image = await readPixels(page);
      // (a 16384 x 8 strip of the pattern is a legitimately dark picture; it was drawn, at that size)
      if (mayBeDark) expect(image.width * image.height).toBeGreaterThan(0);
      else assertNotBlank(image, query);
      if (warned.startsWith('iChannel'))
        await page.waitForFunction(() => document.getElementById('toast').textContent.includes('nope.png'));
      expect(
        warnings.some((w) => w.includes(warned)),
        `a warning naming ${warned}; got:\n${warnings.join('\n')}`,
      ).toBe(true);
      check(await info(page));
      if (warned === 'missing.glsl') expect(await overlayText(page)).toContain('Could not load examples/missing.glsl');
    });
  });
});
