// Work never lost, links that show what the sender saw (issue 18, items 3-7): a note belongs to
// the text it restored, a link opens what it names (kept edits are offered, never run in its
// place), a second link in the same tab opens, a paste after a restore is "untitled", and a link
// from a playing page plays.

import { describe, expect, test } from 'vitest';
import { projectKey } from '../../src/player/io/hang-guard.js';
import { singlePass } from '../../src/shadertoy/multipass.js';
import { allowClipboard, button, editorText, info, pasteIntoEditor, solid, typeInEditor, withControl } from '../support/page-helpers.js';
import { withPage, withServedDir } from '../support/page-helpers.js';
import { writeFiles } from '../support/page-multipass-helpers.js';
import { hook } from '../support/hook.js';

const SIZE = 'size=64x36&time=1';

const named = (page, name) => page.waitForFunction((n) => window.shaderEngine.info().fileName === n, { polling: 50 }, name);

/** Opens the page with nothing kept from earlier tests in this browser's storage. */
async function freshPage(page, goto, query) {
  await goto(`?${SIZE}`);
  await page.evaluate(() => localStorage.clear());
  await goto(query);
}

/** Reloads the page as a person does (a reload, not a link opened afresh) and waits for its first frame. */
async function reload(page) {
  await page.reload({ waitUntil: 'load' });
  await page.waitForFunction(() => window.shaderEngine, { polling: 50 });
  await hook(page).ready();
}

/** Edits the built-in raytracer in the editor and runs it: "raytrace.glsl (edited)". */
async function editBuiltin(page) {
  await typeInEditor(page, '\n// my edit', 'end');
  await withControl(page, 'Enter');
  await named(page, 'raytrace.glsl (edited)');
}

describe('a restored note belongs to the text it restored', () => {
  test('pasting another shader after a restore takes the note away; the paste is kept, not discarded', async () => {
    await withPage(async ({ page, context, goto }) => {
      await allowClipboard(page, context.baseUrl);
      await freshPage(page, goto, `?${SIZE}`);
      await editBuiltin(page);
      await reload(page);
      await page.waitForSelector('#restored-note', { visible: true });
      const pasted = solid(10, 20, 30);
      await pasteIntoEditor(page, pasted);
      await named(page, 'untitled'); // item 6: a paste over everything after a restore is a new shader
      expect(await page.$('#restored-note'), 'the note went with the text it restored').toBeNull();
      await reload(page);
      expect(await editorText(page), 'the pasted shader came back').toBe(pasted);
      expect((await info(page)).fileName).toBe('untitled');
    });
  });

  test('after a hang and a restart, nothing is said to be restored when nothing was edited', async () => {
    const hung = 'void mainImage(out vec4 c, in vec2 p) { c = vec4(p.x / iResolution.x); }\n';
    await withServedDir('hang-restart', async (dir, base) => {
      writeFiles(dir, { 'hung.glsl': hung });
      await withPage(async ({ page, goto }) => {
        await freshPage(page, goto, `?${SIZE}`);
        // the note the watchdog leaves: hung.glsl hung, the built-in raytracer had finished a frame
        const back = await hook(page).info();
        const note = {
          key: projectKey(singlePass(hung), {}),
          name: 'hung.glsl',
          project: singlePass(hung),
          back: {
            project: singlePass(await editorText(page)),
            info: null,
            name: 'shaders/raytrace.glsl',
            origin: 'builtin',
            url: null,
            values: back.controls,
          },
        };
        await page.evaluate((n) => localStorage.setItem('shadertoy-runner.hung', JSON.stringify(n)), note);
        await goto(`?shader=${base}/hung.glsl&${SIZE}`);
        expect((await info(page)).fileName, 'the page ran the last shader that finished').toBe('shaders/raytrace.glsl');
        await reload(page);
        expect(await page.$('#restored-note'), 'nothing was edited or kept').toBeNull();
      });
    });
  });
});

describe('a link opens what it names', () => {
  test('a link without #source= runs its shader; edits kept for it are offered, and open when asked', async () => {
    await withPage(async ({ page, goto }) => {
      await freshPage(page, goto, `?${SIZE}`);
      await editBuiltin(page);
      const edited = await editorText(page);
      await goto(`?${SIZE}&BOUNCES=0&CAMERA_ORBIT=30,-20`);
      const opened = await info(page);
      expect(opened.fileName).toBe('shaders/raytrace.glsl');
      expect(opened.controls.BOUNCES).toBe(0);
      expect(await editorText(page)).not.toContain('// my edit');
      const offer = await page.waitForSelector('#kept-offer', { visible: true });
      expect(await offer.evaluate((n) => n.textContent)).toContain('raytrace.glsl (edited)');
      // editing the link's shader does not overwrite the kept edits
      await typeInEditor(page, '\n// link edit', 'end');
      await (await button(page, 'Open my edits')).click();
      await named(page, 'raytrace.glsl (edited)');
      expect(await editorText(page)).toBe(edited);
    });
  });

  test('a second link in the same tab that differs only in its #source= opens it', async () => {
    const links = [];
    await withPage(async ({ page, context, goto }) => {
      await allowClipboard(page, context.baseUrl);
      await freshPage(page, goto, `?${SIZE}`);
      for (const colour of [solid(200, 0, 0), solid(0, 0, 200)]) {
        const compiled = (await info(page)).compiled;
        await pasteIntoEditor(page, colour);
        await page.waitForFunction((n) => window.shaderEngine.info().compiled > n, { polling: 50 }, compiled);
        links.push(new URL(await hook(page).shareUrl()));
      }
      expect(links[0].hash).not.toBe(links[1].hash);
    });
    await withPage(async ({ page, goto }) => {
      await goto(links[0].search + links[0].hash);
      expect(await editorText(page)).toBe(solid(200, 0, 0));
      await page.evaluate((hash) => (location.hash = hash), links[1].hash);
      await page.waitForFunction((c) => window.shaderEngine.editorSource() === c, { polling: 50 }, solid(0, 0, 200));
      const { data } = await hook(page).readPixels();
      expect([...Buffer.from(data, 'base64').subarray(0, 3)]).toEqual([0, 0, 200]);
    });
  });

  test('a link from a playing page plays; from a paused one it shows that instant', async () => {
    await withPage(async ({ page, goto }) => {
      await goto('?size=64x36');
      expect((await info(page)).playing).toBe(true);
      expect(new URL(await hook(page).shareUrl()).searchParams.has('time')).toBe(false);
      await hook(page).pause();
      const time = (await info(page)).time;
      expect(new URL(await hook(page).shareUrl()).searchParams.get('time')).toBe(String(Number(time.toFixed(6))));
    });
  });
});

describe('kept edits that do not compile, and notes with buttons (issue 24, items 11-12)', () => {
  test('a reload with kept edits that do not compile runs the file, says so, and runs the edits once they compile', async () => {
    await withPage(async ({ page, goto }) => {
      await freshPage(page, goto, `?${SIZE}`);
      await typeInEditor(page, '\nfloat broken = ;', 'end'); // kept as typed, mid-work
      await page.waitForFunction(() => window.shaderEngine.editorSource().includes('broken = ;'), { polling: 50 });
      await page.reload({ waitUntil: 'load' });
      await page.waitForFunction(() => window.shaderEngine, { polling: 50 });
      const outcome = await page.evaluate(() =>
        window.shaderEngine.ready.then(
          () => 'drawn',
          (e) => `rejected: ${e.message}`,
        ),
      );
      expect(outcome, 'the file draws while the edits do not compile').toBe('drawn');
      const { data } = await hook(page).readPixels();
      expect(Math.max(...Buffer.from(data, 'base64')), 'not a black canvas').toBeGreaterThan(100);
      expect(await editorText(page), 'the edits are in the editor').toContain('broken = ;');
      const note = await page.$eval('#restored-note', (n) => n.textContent);
      expect(note).toMatch(/do not compile yet: the picture is shaders\/raytrace\.glsl as the file has it/);
      expect(await page.$eval('#overlay', (o) => o.textContent)).toMatch(/error/i);

      // fixed: the edits run, and the note no longer says the file stands in
      const compiled = (await info(page)).compiled;
      await typeInEditor(page, '\n// fixed', 'end');
      await page.evaluate(() => {
        const text = window.shaderEngine.editorSource().replace('float broken = ;', 'float broken = 1.0;');
        return window.shaderEngine.setSource(text);
      });
      await page.waitForFunction((n) => window.shaderEngine.info().compiled > n, { polling: 50 }, compiled);
      const after = await page.$eval('#notes', (n) => n.textContent);
      expect(after, 'the edited text is not the one restored: its note went').not.toMatch(/do not compile|Restored/);
      expect((await info(page)).fileName).toBe('raytrace.glsl (edited)');
    });
  });

  test('notes stack: the kept-work note and a note on values lie apart, and every button can be clicked', async () => {
    await withPage(async ({ page, goto }) => {
      await page.setViewport({ width: 800, height: 600 });
      await freshPage(page, goto, `?${SIZE}`);
      await editBuiltin(page);
      await goto(`?${SIZE}&NO_SUCH=1&BOUNCES=2.5&CAMERA_ORBIT=400,0`); // an offer, and a note of three lines
      await page.waitForSelector('#kept-offer', { visible: true });
      const layout = await page.evaluate(() => {
        const box = (/** @type {Element} */ e) => e.getBoundingClientRect().toJSON();
        const notes = ['#kept-offer', '#value-notes'].map((s) => box(/** @type {Element} */ (document.querySelector(s))));
        const buttons = [...document.querySelectorAll('#kept-offer button, #value-notes button')].map((b) => {
          const r = b.getBoundingClientRect();
          return document.elementFromPoint(r.x + r.width / 2, r.y + r.height / 2) === b ? 'clickable' : b.textContent;
        });
        return { notes, buttons };
      });
      const [offer, values] = layout.notes;
      const apart = offer.bottom <= values.top || values.bottom <= offer.top || offer.right <= values.left || values.right <= offer.left;
      expect(apart, `boxes ${JSON.stringify(layout.notes)}`).toBe(true);
      expect(layout.buttons).toEqual(layout.buttons.map(() => 'clickable'));
    });
  });
});
