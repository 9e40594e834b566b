// What a new user hit, said on the page (issue 18, items 2 and 8-11): the orbit's angles by
// name and range, values a link cannot use said in a note with what was used instead, a link's
// shader that cannot be read said in words, any duration for a recording, a frame-time readout
// that tells what is happening, and the small ones (a tab, wrapping lines, Reset view).

import { describe, expect, test } from 'vitest';
import { openPage } from '../support/page.js';
import { sameImage } from '../support/images.js';
import { button, info, openEditor, overlayText, readPixels, recordReadouts, withPage } from '../support/page-helpers.js';
import { dropFile, loadNotes } from '../support/page-multipass-helpers.js';
import { hook } from '../support/hook.js';

const SIZE = 'size=64x36&time=0';

/** The lines of the note on values not used as given (empty when there is none). */
const valueNotes = (page) => page.$$eval('#value-notes li', (items) => items.map((i) => i.textContent));

describe('the picture', () => {
  test('the orbit has an azimuth all the way round and an elevation, each named, each with its range', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`?${SIZE}&CAMERA_ORBIT=170,10`);
      expect((await info(page)).controls.CAMERA_ORBIT, 'from behind: not clamped to 90').toEqual([170, 10]);
      expect(await valueNotes(page)).toEqual([]);
      const names = await page.evaluate(() => {
        const folder = [...document.querySelectorAll('.lil-gui .lil-gui')].find(
          (f) => f.querySelector('.lil-title')?.textContent.trim() === 'Camera orbit (deg)',
        );
        return [...(folder?.querySelectorAll('.lil-controller .lil-name') ?? [])].map((n) => n.textContent);
      });
      expect(names).toEqual(['azimuth', 'elevation']);
    });
  });
});

describe('say it on the page', () => {
  // Each value the page cannot use as given: the note names it and what was used instead.
  test.each([
    ['size=0x0', `size=0x0&time=0`, /size=0x0 ignored.*the canvas follows the window/],
    ['time=abc', `size=64x36&time=abc`, /time=abc ignored.*the clock runs from 0/],
    ['CONE_HEIGHT=-5', `${SIZE}&CONE_HEIGHT=-5`, /CONE_HEIGHT=-5 is out of range \(0\.05 \.\. 4\): using 0\.05/],
    ['an unknown control', `${SIZE}&NO_SUCH=1`, /NO_SUCH ignored: the shader has no control of that name/],
    ['size=99999x99999', `size=99999x99999&time=0&BOUNCES=0&SAMPLES=1`, /size=99999x99999 is out of range: using 5760x5760/],
  ])('%s is said in a note, with what was used instead', async (_, query, said) => {
    await withPage(async ({ page, goto }) => {
      // (the note is there before the first frame, which at 5760x5760 takes minutes here)
      await goto(`?${query}`, { expectReady: false });
      await page.waitForSelector('#value-notes', { timeout: 30_000 });
      const lines = await valueNotes(page);
      expect(
        lines.some((line) => said.test(line)),
        `a note line like ${said}; got ${JSON.stringify(lines)}`,
      ).toBe(true);
    });
  });

  test('a dropped .json that is not a Shadertoy export: the reason is on the page', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`?${SIZE}`);
      await dropFile(page, 'data.json', '{"values": [1, 2, 3]}', 'application/json');
      await page.waitForFunction(() => document.getElementById('load-notes')?.className === 'error', { polling: 50 });
      const note = await loadNotes(page);
      expect(note.title).toBe('Could not load data.json');
      expect(note.lines.join('\n')).toMatch(/not a Shadertoy shader/);
    });
  });

  test.each([
    ['cut short', '#source=K8vPTFHITczM88xNTE_VyC8tUShLTTZR&name=x.glsl', /cut short or damaged/],
    ['garbled', '#source=%E2%9C%93%21%21&name=x.glsl', /not base64url/],
  ])('a link whose #source= is %s says so in words', async (_, hash, said) => {
    await withPage(async ({ page, goto }) => {
      await goto(`?${SIZE}${hash}`);
      await page.waitForFunction(() => !document.getElementById('overlay').hidden, { polling: 50 });
      const text = await overlayText(page);
      expect(text).toMatch(said);
      expect(text).not.toMatch(/Failed to fetch|atob|InvalidCharacterError/);
      expect((await info(page)).fileName).toBe('shaders/raytrace.glsl');
    });
  });

  test('Record takes any frame count: 100 frames at 30 fps is 3.333 s', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`?${SIZE}&BOUNCES=0&SAMPLES=1`);
      await (await button(page, 'Record')).click();
      const field = async (label, value) => {
        const input = await page.$(`.record-dialog ::-p-aria([name="${label}"])`);
        await input.click({ count: 3 });
        await input.type(String(value));
      };
      await field('Frames per second', 30);
      await field('Frames', 100);
      expect(await page.$eval('.record-dialog [aria-label="Duration (s)"]', (i) => /** @type {HTMLInputElement} */ (i).value)).toBe(
        '3.333',
      );
      await (await page.$('.record-dialog ::-p-aria([name="Start"][role="button"])')).click();
      await page.waitForFunction(
        () => window.shaderEngine.recording().busy || /Saved|Frame/.test(document.querySelector('.record-status').textContent),
        {
          polling: 20,
        },
      );
      expect(await page.$eval('.record-status', (s) => s.textContent)).not.toMatch(/positive number/);
      await hook(page).cancelRecording();
    });
  });
});

describe('the frame-time readout tells what is happening', () => {
  test('the first frame is said to be drawing, never "paused"; a GPU time never beyond the time between frames', async () => {
    // the real clock: a first frame of about a second, read as it comes
    const { page, errors, context } = await openPage({ deterministic: false });
    try {
      await recordReadouts(page);
      await page.goto(`${context.baseUrl}/?size=480x270&SAMPLES=16&ADAPTIVE_AA=0`, { waitUntil: 'load' });
      await page.waitForFunction(() => window.shaderEngine, { polling: 50 });
      await hook(page).ready();
      await page.waitForFunction(() => window.shaderEngine.info().frame >= 3, { polling: 100 });
      /** @type {string[]} */
      const seen = (await page.evaluate(() => /** @type {any} */ (window).__readouts)).map(([text]) => text);
      expect(seen[0], `the first readout (all: ${JSON.stringify(seen)})`).toMatch(/^Drawing the first frame/);
      expect(
        seen.filter((t) => /paused/i.test(t)),
        'playing, never "paused"',
      ).toEqual([]);
      for (const text of seen) {
        const gpu = /^GPU ([\d.]+) ms · ([\d.]+) fps$/.exec(text);
        if (gpu) expect(Number(gpu[1]), text).toBeLessThanOrEqual(1000 / Number(gpu[2]) + 0.1);
      }
    } finally {
      await page.close().catch(() => {});
    }
    expect(errors).toEqual([]);
  });

  test('at speed 0× time stands still: no frame is drawn again, and the readout says why', async () => {
    await withPage(async ({ page, goto }) => {
      await goto('?size=64x36&BOUNCES=0&SAMPLES=1');
      await hook(page).setSpeed(0);
      await page.waitForFunction(() => /^Speed 0× · time stands still$/.test(document.querySelector('#toolbar .fps').textContent), {
        polling: 50,
      });
      // A frame may still be in flight when the readout changes, and setting the speed draws the
      // picture once at the new speed: let those land, then count.
      await new Promise((resolve) => setTimeout(resolve, 500));
      const frame = (await info(page)).frame;
      await new Promise((resolve) => setTimeout(resolve, 1000));
      expect((await info(page)).frame, 'no identical frames drawn at full rate').toBeLessThanOrEqual(frame + 1);
    });
  });
});

describe('small things', () => {
  test('"Export JSON" of a single-pass shader says 1 tab', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`?${SIZE}&BOUNCES=0&SAMPLES=1`);
      await (await button(page, 'Export JSON')).click();
      await page.waitForFunction(() => /Saved/.test(document.getElementById('toast').textContent), { polling: 50 });
      expect(await page.$eval('#toast', (t) => t.textContent)).toMatch(/, 1 tab\)$/);
    });
  });

  test('the editor wraps long lines, and a button turns it off', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`?${SIZE}&BOUNCES=0&SAMPLES=1`);
      await openEditor(page);
      const wraps = () => page.$eval('.cm-content', (c) => c.classList.contains('cm-lineWrapping'));
      expect(await wraps()).toBe(true);
      await (await button(page, 'Wrap')).click();
      expect(await wraps()).toBe(false);
    });
  });

  test('"Reset view" puts the mouse back after a click on the canvas turned the camera', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`?${SIZE}&BOUNCES=0&SAMPLES=1`);
      const before = await readPixels(page);
      const box = await (await page.$('#view')).boundingBox();
      await page.mouse.click(box.x + box.width * 0.8, box.y + box.height * 0.3);
      await page.waitForFunction(() => window.shaderEngine.info().mouse[0] !== 0, { polling: 50 });
      expect(sameImage(await readPixels(page), before), 'the click turned the camera (iMouse, as on Shadertoy)').toBe(false);
      await (await button(page, 'Reset view')).click();
      expect((await info(page)).mouse).toEqual([0, 0, 0, 0]);
      expect(sameImage(await readPixels(page), before), 'back to the view the page opened with').toBe(true);
    });
  });
});
