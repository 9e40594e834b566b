// The engine page (engine.html, src/player/engine-main.js) on its own, as the command line loads it:
// no widget and no raytracer. With no ?shader= it runs its own start shader; a shader
// it cannot have rejects `ready`, never another drawn in its place; what stands in the way of its
// picture is one line on the page; and the raytracer's "Converge when still" (--converge),
// plugged in from outside the player (src/engine-plug-ins.js), is a chunk it fetches only when a
// converge is asked for. tests/unit/lint-rooms.test.js checks its imports; this checks what the built
// page loads and does.

import { afterAll, describe, expect, test } from 'vitest';
import { disconnect } from '../support/page.js';
import { info, readPixels, withPage } from '../support/page-helpers.js';
import { hook } from '../support/hook.js';

afterAll(disconnect);

/** A page of its own (not the shared interactive one): withPage shares none set up before it loads. */
const OWN_PAGE = { beforeLoad: async () => {} };

/** The scripts the page has fetched so far, by file name. @param {import('puppeteer-core').Page} page */
const scripts = (page) =>
  page.evaluate(() =>
    performance
      .getEntriesByType('resource')
      .map((entry) => entry.name.split('/').pop() ?? '')
      .filter((name) => /\.(js|glsl)$/.test(name)),
  );

/** The engine page's status line (engine-status.js), or null while it is hidden. @param {import('puppeteer-core').Page} page */
const status = (page) =>
  page.evaluate(() => {
    const line = /** @type {HTMLElement} */ (document.getElementById('overlay'));
    return line.hidden ? null : line.textContent;
  });

/** What `ready` came to: 'ok', or its error's message. @param {import('puppeteer-core').Page} page */
const readyOutcome = (page) =>
  page.evaluate(() =>
    window.shaderEngine.ready.then(
      () => 'ok',
      (error) => String(error?.message ?? error),
    ),
  );

describe('the engine page', () => {
  test('with no ?shader= runs its start shader; converging fetches the raytracer then, and only then', async () => {
    await withPage(async ({ page, goto }) => {
      await goto('engine.html?size=8x4&time=0');
      expect(await info(page)).toMatchObject({ fileName: 'start.glsl', origin: 'builtin', width: 8, height: 4 });
      const black = await readPixels(page);
      expect([...black.data.subarray(0, 4)]).toEqual([0, 0, 0, 255]);
      expect(await status(page)).toBe(null);
      const loaded = await scripts(page);
      expect(loaded.some((name) => name.startsWith('engine-'))).toBe(true);
      // nothing of the interactive page or the raytracer: main.js's bundle, the raytracer's text or its convergence
      expect(loaded.filter((name) => /^(main|convergence)-|raytrace/.test(name))).toEqual([]);
      expect(await page.evaluate(() => typeof (/** @type {any} */ (window.shaderEngine).inspect))).toBe('undefined');

      // the raytracer as the command line serves it (a ?shader= file), converged as --converge does
      await hook(page).open('?shader=shaders/raytrace.glsl&size=16x9&time=0&SAMPLES=1&BOUNCES=0');
      await hook(page).setConverging(true, { frames: 2 });
      expect((await info(page)).converging).toBe(true);
      expect((await scripts(page)).filter((name) => name.startsWith('convergence-'))).toHaveLength(1);
      expect((await scripts(page)).filter((name) => name.startsWith('main-'))).toEqual([]);
    }, OWN_PAGE);
  });

  test.each([
    ['a shader it cannot have', 'engine.html?shader=no-such-file.glsl&size=8x4', /^Could not load no-such-file\.glsl: /],
    ['a link it cannot read', 'engine.html?size=8x4#source=not-a-link', /^Could not read the shader in this link: /],
  ])('%s rejects `ready` and says why on the page, never another shader in its place', async (_, query, why) => {
    await withPage(async ({ page, goto, warnings }) => {
      await goto(query, { expectReady: false });
      expect(await readyOutcome(page)).toMatch(why);
      expect(await status(page)).toMatch(why);
      expect((await info(page)).compiled).toBe(0);
      warnings.length = 0; // the page's console warning says it too
    }, OWN_PAGE);
  });

  test('a shader that does not compile is said in one line, and comes back as data', async () => {
    await withPage(async ({ page, goto }) => {
      await goto('engine.html?size=8x4&time=0');
      const result = await hook(page).setSource('void mainImage(out vec4 c, in vec2 f) { c = nope; }');
      expect(result.ok).toBe(false);
      expect(await status(page)).toMatch(/ did not compile: .*nope/);
      await hook(page).setSource('void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }');
      expect(await status(page)).toBe(null);
    }, OWN_PAGE);
  });
});
