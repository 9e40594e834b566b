// A day's use of the page, in the real browser (issue 11): shortcuts whatever has focus and never
// while typing; the compile errors never under the panel; the panel never over the scene (1280
// wide and 390 wide); "Copy link" saying what it leaves out, pinning the size only when fixed,
// and carrying an edited shader in its fragment; a refused ?shader= said on the page; Fullscreen.
import { afterAll, describe, expect, test } from 'vitest';
import { disconnect, openPage } from '../support/page.js';
import {
  button,
  editorText,
  info,
  overlayText,
  pixel,
  readPixels,
  recordReadouts,
  solid,
  typeInEditor,
  withControl,
  withPage,
} from '../support/page-helpers.js';
import { hook } from '../support/hook.js';

afterAll(disconnect);

const PATTERN = '?shader=examples/pattern.glsl';
const playing = (page) =>
  hook(page)
    .info()
    .then((r) => r.playing);
const whenPlaying = (page, value) => page.waitForFunction((v) => window.shaderEngine.info().playing === v, { polling: 20 }, value);

/** The overlap of two boxes, in CSS px². */
function overlap(a, b) {
  const w = Math.min(a.right, b.right) - Math.max(a.left, b.left);
  const h = Math.min(a.bottom, b.bottom) - Math.max(a.top, b.top);
  return Math.max(0, w) * Math.max(0, h);
}
const box = (page, selector) =>
  page.$eval(selector, (e) => {
    const r = e.getBoundingClientRect();
    return { left: r.left, top: r.top, right: r.right, bottom: r.bottom, width: r.width, height: r.height };
  });
const PANEL = '.lil-gui.lil-root';

/** The canvas's and the panel's boxes once two reads 150 ms apart agree (at most 6 s of waiting). */
async function settledBoxes(page) {
  let last = null;
  for (let i = 0; i < 40; i++) {
    await new Promise((r) => setTimeout(r, 150));
    const now = { canvas: await box(page, '#view'), panel: await box(page, PANEL) };
    if (last && JSON.stringify(now) === JSON.stringify(last)) return now;
    last = now;
  }
  return last;
}

describe('shortcuts', () => {
  test('Space plays and pauses whatever toolbar button has focus, and never while typing in a field', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`${PATTERN}&time=1`); // no fixed size: the panel's Resolution scale field is enabled
      await page.evaluate(() => {
        const shots = document.documentElement.dataset;
        shots.shots = '0';
        document
          .querySelector('[aria-label="Screenshot"]')
          .addEventListener('click', () => (shots.shots = String(Number(shots.shots) + 1)));
      });
      await (await button(page, 'Screenshot')).click(); // focuses it
      expect(await page.evaluate(() => document.activeElement?.getAttribute('aria-label'))).toBe('Screenshot');
      await page.keyboard.press('Space');
      await whenPlaying(page, true);
      await page.keyboard.press('Space');
      await whenPlaying(page, false);
      await page.keyboard.press('KeyR');
      await page.waitForFunction(() => window.shaderEngine.info().time === 0, { polling: 20 });
      await new Promise((r) => setTimeout(r, 300));
      expect(
        await page.evaluate(() => Number(document.documentElement.dataset.shots)),
        'Space did not click the focused button again',
      ).toBe(1);

      // a panel field: typing a space there is typing, not a shortcut
      const field = await page.$(`${PANEL} input[type="text"]:not(:disabled)`);
      expect(field, 'the panel has a text field').toBeTruthy();
      await field.focus();
      expect(await page.evaluate(() => document.activeElement?.tagName)).toBe('INPUT');
      await page.keyboard.press('Space');
      await page.keyboard.press('KeyR');
      await page.keyboard.press('KeyF');
      await new Promise((r) => setTimeout(r, 300));
      expect(await playing(page)).toBe(false);
      expect(await page.evaluate(() => document.fullscreenElement)).toBe(null);
    });
  });

  test('Fullscreen: the button and F', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`${PATTERN}&size=160x90&time=1`);
      await (await button(page, 'Fullscreen')).click();
      await page.waitForFunction(() => document.fullscreenElement !== null, { polling: 20 });
      expect(await page.evaluate(() => document.fullscreenElement.contains(document.getElementById('view')))).toBe(true);
      await page.keyboard.press('KeyF'); // with the button still focused
      await page.waitForFunction(() => document.fullscreenElement === null, { polling: 20 });
      await page.evaluate(() => /** @type {HTMLElement} */ (document.activeElement)?.blur());
      await page.keyboard.press('KeyF');
      await page.waitForFunction(() => document.fullscreenElement !== null, { polling: 20 });
      await page.keyboard.press('KeyF');
      await page.waitForFunction(() => document.fullscreenElement === null, { polling: 20 });
      expect(await playing(page)).toBe(false);
    });
  });
});

describe('layout', () => {
  test('1280 wide: the panel is beside the canvas, and compile errors are not under it with the editor open', async () => {
    await withPage(
      async ({ page, goto }) => {
        await goto(`${PATTERN}&time=1`);
        const canvas = await box(page, '#view');
        const panel = await box(page, PANEL);
        expect(panel.height, 'the panel is open').toBeGreaterThan(100);
        expect(overlap(canvas, panel), 'panel over the canvas (px²)').toBe(0);
        expect(canvas.width).toBeGreaterThan(900);

        await (await button(page, 'Edit shader')).click();
        await hook(page).setSource('void mainImage(out vec4 c, in vec2 p) { c = vec4(nope); }\n');
        await page.waitForFunction(() => !document.getElementById('overlay').hidden, { polling: 20 });
        const alert = await box(page, '#overlay');
        expect(overlap(alert, await box(page, PANEL)), 'the error box under the panel (px²)').toBe(0);
        // what is on top at the error box's corners is the error box
        const onTop = await page.evaluate(
          (a) =>
            [
              [a.left + 4, a.top + 4],
              [a.right - 4, a.top + 4],
              [a.left + 4, a.bottom - 4],
              [a.right - 4, a.bottom - 4],
            ].every(([x, y]) => document.getElementById('overlay').contains(document.elementFromPoint(x, y))),
          alert,
        );
        expect(onTop, 'the error box is readable').toBe(true);
        expect(await overlayText(page)).toMatch(/nope/);
      },
      { viewport: { width: 1280, height: 800, deviceScaleFactor: 1 } },
    );
  });

  test('390 wide: the toolbar keeps the frame time and the name; the panel does not cover the canvas, its sliders finger-sized', async () => {
    await withPage(
      async ({ page, goto }) => {
        await goto(`${PATTERN}&time=1`);
        // time=1 holds the clock: once the first frame is drawn the line says "Paused", the
        // shortest it gets, and so the one beside which the name has the least room
        await page.waitForFunction(() => document.querySelector('#toolbar .fps')?.textContent === 'Paused', { polling: 50 });
        // the frame-time line (its graph left out) and the file's name without its folders, whole
        const shown = await page.evaluate(() => {
          const seen = (/** @type {Element} */ e) => {
            const r = e.getBoundingClientRect();
            return r.width > 0 && r.height > 0 && r.left >= 0 && r.right <= innerWidth;
          };
          const name = /** @type {HTMLElement} */ (document.querySelector('#toolbar .name'));
          const fps = /** @type {HTMLElement} */ (document.querySelector('#toolbar .fps'));
          return {
            fps: seen(fps) && fps.textContent,
            name: seen(name) && name.innerText,
            nameClipped: name.scrollWidth > name.clientWidth,
            title: name.title,
          };
        });
        expect(shown.fps, 'the frame-time line').toBe('Paused');
        expect(shown).toMatchObject({ name: 'pattern.glsl', nameClipped: false });
        await goto('?size=64x36'); // the built-in shader, "shaders/raytrace.glsl", a small frame
        const name = await page.$eval('#toolbar .name', (e) => {
          const span = /** @type {HTMLElement} */ (e);
          return [span.innerText, span.title];
        });
        expect(name).toEqual(['raytrace.glsl', 'shaders/raytrace.glsl']);
        await goto(`${PATTERN}&time=1`);
        expect(overlap(await box(page, '#view'), await box(page, PANEL)), 'closed panel over the canvas').toBe(0);
        await page.click(`${PANEL} > .lil-title`);
        await page.waitForFunction((s) => !document.querySelector(s).classList.contains('lil-closed'), { polling: 20 }, PANEL);
        await page.evaluate((s) => {
          for (const t of document.querySelectorAll(`${s} .lil-gui.lil-closed > .lil-title`)) /** @type {HTMLElement} */ (t).click();
        }, PANEL);
        // lil-gui's open transition, then the stage's new layout and the canvas's resize: under
        // load they take longer than a fixed wait, so measure once the boxes stop moving.
        const { canvas, panel } = await settledBoxes(page);
        expect(canvas.height, 'the canvas keeps a useful size').toBeGreaterThan(200);
        expect(overlap(canvas, panel), 'open panel over the canvas').toBe(0);
        const sliders = await page.$$eval(`${PANEL} .lil-slider`, (all) =>
          all.map((s) => {
            const r = s.getBoundingClientRect();
            return { width: r.width, height: r.height };
          }),
        );
        expect(sliders.length).toBeGreaterThan(0);
        for (const s of sliders) {
          expect(s.width, 'slider width').toBeGreaterThanOrEqual(120);
          expect(s.height, 'slider height').toBeGreaterThanOrEqual(32);
        }
      },
      { viewport: { width: 390, height: 844, deviceScaleFactor: 1 } },
    );
  });
});

describe('links', () => {
  test('"Copy link" pins the size only when it was fixed, and says that a dropped image is not in it', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`${PATTERN}&time=1`);
      expect(new URL(await hook(page).shareUrl()).searchParams.has('size')).toBe(false);
      await goto(`${PATTERN}&time=1&size=160x90`);
      expect(new URL(await hook(page).shareUrl()).searchParams.get('size')).toBe('160x90');

      // drop an image on the page: it goes into iChannel0, and the link cannot carry it
      await page.evaluate(async () => {
        const blob = await (await fetch('/scene.png')).blob();
        const data = new DataTransfer();
        data.items.add(new File([blob], 'dropped.png', { type: 'image/png' }));
        document.dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true, cancelable: true }));
      });
      await page.waitForFunction(() => /Loaded dropped.png/.test(document.getElementById('toast').textContent), { polling: 20 });
      await (await button(page, 'Copy link')).click();
      await page.waitForFunction(() => /link/i.test(document.getElementById('toast').textContent), { polling: 20 });
      expect(await page.$eval('#toast', (t) => t.textContent)).toMatch(/iChannel0.*not in the link|not in the link.*iChannel0/);
    });
  });

  test('an edited shader travels in the link (#source=, compressed); a too-long one says so', async () => {
    let link;
    const source = `// edited\n${solid(20, 200, 90)}`;
    await withPage(async ({ page, goto }) => {
      await goto(`${PATTERN}&time=1&size=64x36`);
      await hook(page).setSource(source);
      link = await hook(page).shareUrl();
    });
    const url = new URL(link);
    expect(url.hash).toMatch(/^#source=[A-Za-z0-9_-]+&name=[^&]+$/);
    expect(url.searchParams.has('shader')).toBe(false);
    await withPage(async ({ page, goto }) => {
      await goto(url.search + url.hash);
      expect(
        await hook(page)
          .info()
          .then((r) => r.origin),
      ).not.toBe('builtin');
      expect(pixel(await readPixels(page), 10, 10)).toEqual([20, 200, 90]);

      // a source that does not compress below the limit: the link says so instead
      let noise = '';
      let x = 12345;
      for (let i = 0; i < 16000; i++) {
        x = (x * 1103515245 + 12345) % 2147483648;
        noise += String.fromCharCode(33 + (x % 90));
      }
      await hook(page).setSource(`// ${noise}\n${solid(1, 2, 3)}`);
      await (await button(page, 'Copy link')).click();
      await page.waitForFunction(() => /too long/i.test(document.getElementById('toast').textContent), { polling: 20 });
    });
  });

  test('an edit of the built-in raytracer travels as a patch against it, and opens as the same text', async () => {
    let link = '';
    let edited = '';
    await withPage(async ({ page, goto }) => {
      await goto('?size=64x36&time=1&SAMPLES=1');
      await typeInEditor(page, '\n// my edit', 'end');
      await withControl(page, 'Enter');
      await page.waitForFunction(() => window.shaderEngine.info().fileName === 'raytrace.glsl (edited)', { polling: 50 });
      edited = await editorText(page);
      link = await hook(page).shareUrl();
    });
    const url = new URL(link);
    expect(url.hash).toMatch(/^#patch=[A-Za-z0-9_-]+&base=builtin&hash=[0-9a-f]{8}&name=/);
    expect(link.length, 'the whole text would be ~34,000 characters').toBeLessThan(2000);
    await withPage(async ({ page, goto }) => {
      await goto(url.search + url.hash);
      expect(await editorText(page)).toBe(edited);
      expect((await info(page)).fileName).toBe('raytrace.glsl (edited)');
    });
  });

  test('?shader= on another origin says so on the page', async () => {
    await withPage(async ({ page, goto, warnings }) => {
      await goto('?shader=https://example.com/x.glsl&size=64x36');
      await page.waitForFunction(() => !document.getElementById('overlay').hidden, { polling: 20 });
      expect(await overlayText(page)).toMatch(/https:\/\/example\.com\/x\.glsl/);
      expect(warnings.join('\n')).toMatch(/example\.com/);
    });
  });
});

describe('the frame-time readout', () => {
  test('GPU time where measured, else labelled as the time between frames; never a frame rate the page did not reach', async () => {
    // the real clock (no deterministic injection): what is measured is the browser's real speed
    const { page, errors, context } = await openPage({ deterministic: false });
    try {
      await recordReadouts(page);
      await page.goto(`${context.baseUrl}/?size=640x360&SAMPLES=4`, { waitUntil: 'load' });
      await page.waitForFunction(() => window.shaderEngine, { polling: 50 });
      await hook(page).ready();
      // once the page's first frame is out of the two seconds (it comes unevenly, after the compile)
      await page.waitForFunction(() => /** @type {any} */ (window).__readouts.filter(([t, , n]) => /fps/.test(t) && n > 2500).length >= 5, {
        polling: 100,
      });
      /** @type {Array<[string, number, number]>} */
      const samples = await page.evaluate(() => /** @type {any} */ (window).__readouts.filter(([t, , n]) => /fps/.test(t) && n > 2500));
      for (const [text, reached] of samples) {
        expect(text, 'the readout says what it measures').toMatch(/^(GPU \d+\.\d ms|\d+\.\d ms between frames) · \d+(\.\d)? fps$/);
        const claimed = Number(/([\d.]+) fps$/.exec(text)[1]);
        expect(claimed, `"${text}" while the page drew ${reached.toFixed(2)} frames a second`).toBeLessThanOrEqual(reached * 1.02);
      }
    } finally {
      await page.close().catch(() => {});
    }
    expect(errors, 'the page logged errors').toEqual([]);
  });
});
