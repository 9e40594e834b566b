// What happens to a running page when things go wrong or change under it, in the real browser:
// a shader that fails on load, a lost GPU context, no WebGL2 at all, and the dev server's shader
// reload (a shader file edited while the page runs).
import fs from 'node:fs';
import path from 'node:path';
import { afterAll, describe, expect, test } from 'vitest';
import { REPO_ROOT, SHADER_FILE } from '../support/config.js';
import { sameImage } from '../support/images.js';
import { disconnect } from '../support/page.js';
import { startWatchingServer } from '../support/page-server.js';
import { info, overlayText, pixel, readPixels, solid, withPage, withServedDir } from '../support/page-helpers.js';
import { hook } from '../support/hook.js';

afterAll(disconnect);

const SIZE = 'size=160x90';
const PATTERN = `?shader=examples/pattern.glsl&${SIZE}&time=2`;

describe('errors', () => {
  test('a shader that fails on load: the alert names the line, nothing else runs, nothing throws', async () => {
    await withServedDir('test-broken', async (dir, base) => {
      fs.writeFileSync(
        path.join(dir, 'broken.glsl'),
        '// line 1\n// line 2\nvoid mainImage(out vec4 c, in vec2 f) {\n    c = vec3(1.0);\n}\n',
      );
      await withPage(async ({ page, goto }) => {
        await goto(`?shader=${base}/broken.glsl&${SIZE}&time=0`, { expectReady: false });
        await page.waitForFunction(() => document.documentElement.dataset.error === 'shader-compile');
        const alert = await overlayText(page);
        expect(alert).toContain('broken.glsl did not compile');
        expect(alert).toContain('broken.glsl:4:');

        // a shader that compiles after it: it draws, and reading it back works (the first
        // compile's error, which `ready` keeps, no longer stands in the way)
        const outcome = await hook(page).setSource(solid(0, 255, 0));
        expect(outcome).toEqual({ ok: true });
        expect(pixel(await readPixels(page), 3, 3)).toEqual([0, 255, 0]);
        const shot = await hook(page).capture({ width: 8, height: 4 });
        expect([shot.width, shot.height]).toEqual([8, 4]);
      });
    });
  });

  test('a Sound tab beside an Image tab that fails on load: the error, not "Drawing the first frame"; paused; no sound note', async () => {
    /** A Shadertoy export: this Image tab and a Sound tab that compiles. */
    const withSound = (image) =>
      JSON.stringify({
        Shader: {
          ver: '0.1',
          info: { name: 'sound' },
          renderpass: [
            { inputs: [], outputs: [{ id: '4dfGRr', channel: 0 }], code: image, name: 'Image', description: '', type: 'image' },
            {
              inputs: [],
              outputs: [],
              code: 'vec2 mainSound(int s, float t) { return vec2(0.1 * sin(6.2831 * 440.0 * t)); }',
              name: 'Sound',
              description: '',
              type: 'sound',
            },
          ],
        },
      });
    const page = (/** @type {import('puppeteer-core').Page} */ p) =>
      p.evaluate(() => ({
        readout: document.querySelector('#toolbar .fps')?.textContent,
        button: document.querySelector('#toolbar .play')?.getAttribute('aria-label'),
        note: document.getElementById('sound-note')?.textContent ?? null,
        playing: window.shaderEngine.info().playing,
        sound: window.shaderEngine.soundState().available,
      }));
    await withServedDir('test-broken-sound', async (dir, base) => {
      fs.writeFileSync(path.join(dir, 'broken.json'), withSound('void mainImage(out vec4 c, in vec2 f) {\n    c = vec3(1.0);\n}'));
      await withPage(async ({ page: p, goto }) => {
        await goto(`?shader=${base}/broken.json&${SIZE}`, { expectReady: false }); // no time=: it would play
        await p.waitForFunction(() => document.documentElement.dataset.error === 'shader-compile');
        expect(await overlayText(p)).toMatch(/broken\.json did not compile[\s\S]*Image:2:/);
        // the readout refreshes four times a second
        await p.waitForFunction(() => document.querySelector('#toolbar .fps')?.textContent !== 'Drawing the first frame', {
          timeout: 5000,
        });
        expect(await page(p)).toEqual({
          readout: 'Not running · did not compile',
          button: 'Play',
          note: null,
          playing: false,
          sound: false,
        });

        // once a shader compiles it plays, as a fresh load of it would, and its Sound tab waits for a key
        const outcome = await hook(p).setProject(withSound(solid(0, 255, 0)));
        expect(outcome.ok, outcome.error).toBe(true);
        expect(await page(p)).toMatchObject({
          button: 'Pause',
          note: expect.stringMatching(/plays once you click or press a key/),
          playing: true,
          sound: true,
        });
      });
    });
  });

  test('a lost WebGL context shows an alert and comes back with the same picture', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(PATTERN);
      const before = await readPixels(page);
      // the context is the render worker's (WEBGL_lose_context there, through the hook)
      await hook(page).loseContext();
      await page.waitForFunction(
        () => window.shaderEngine.info().contextLost && !(/** @type {HTMLElement} */ (document.querySelector('[role="alert"]')).hidden),
      );
      expect(await overlayText(page)).toContain('GPU context was lost');
      await hook(page).restoreContext();
      await page.waitForFunction(
        () => !window.shaderEngine.info().contextLost && /** @type {HTMLElement} */ (document.querySelector('[role="alert"]')).hidden,
      );
      const after = await readPixels(page);
      expect(sameImage(after, before), 'the restored context draws the same picture').toBe(true);
    });
  });

  test('no WebGL2: a clear message, not a blank page', async () => {
    await withPage(
      async ({ page, goto }) => {
        await goto(PATTERN, { expectReady: false });
        expect(await page.evaluate(() => document.documentElement.dataset.error)).toBe('webgl2');
        const alert = await overlayText(page);
        expect(alert).toContain('WebGL2 is not available');
        expect(alert).toMatch(/browser or GPU provides no WebGL2/);
        const rejected = await page.evaluate(() =>
          window.shaderEngine.ready.then(
            () => null,
            (e) => e.message,
          ),
        );
        expect(rejected).toMatch(/WebGL2/);
      },
      {
        // The page draws in a worker: every worker it starts gets an OffscreenCanvas with no
        // WebGL2 (a module wrapping the real one), as a browser without WebGL2 has.
        beforeLoad: (page) =>
          page.evaluateOnNewDocument(() => {
            const RealWorker = window.Worker;
            window.Worker = class extends RealWorker {
              constructor(url, options) {
                const stub = [
                  'const getContext = OffscreenCanvas.prototype.getContext;',
                  "OffscreenCanvas.prototype.getContext = function (type, ...rest) { return type === 'webgl2' ? null : getContext.call(this, type, ...rest); };",
                  `import ${JSON.stringify(new URL(url, location.href).href)};`,
                ].join('\n');
                super(URL.createObjectURL(new Blob([stub], { type: 'text/javascript' })), options);
              }
            };
          }),
      },
    );
  });
});

describe('development: editing a shader file reloads it without reloading the page', () => {
  /**
   * Opens `query` on a page server that watches files, runs `body(page)`, and checks that the
   * page is still the same document after it (nothing reloaded the page).
   */
  async function onWatchingServer(query, body) {
    const server = await startWatchingServer();
    try {
      await withPage(async ({ page, goto }) => {
        await goto(query, { base: server.baseUrl });
        await page.evaluate(() => (window.__sameDocument = true));
        await body(page);
        expect(await page.evaluate(() => window.__sameDocument)).toBe(true);
      });
    } finally {
      await server.close();
    }
  }

  /** Does `touch()` and waits `ms`, again until `changed()` or 30 s: the watcher may still be starting. */
  async function touchUntil(touch, ms, changed) {
    const deadline = Date.now() + 30_000;
    do {
      touch();
      await new Promise((r) => setTimeout(r, ms));
    } while (!(await changed()) && Date.now() < deadline);
  }

  // A temporary file in each served folder: public/ (as ?shader=NAME.glsl) and shaders/ (served
  // by vite.config.js as /shaders/NAME.glsl). The page runs it from a server that watches files.
  test.each([
    ['public/', path.join(REPO_ROOT, 'public'), ''],
    ['shaders/', path.join(REPO_ROOT, 'shaders'), 'shaders/'],
  ])('a file under %s', async (_, dir, prefix) => {
    const name = `hmr-test-${process.pid}.glsl`;
    const file = path.join(dir, name);
    fs.writeFileSync(file, solid(200, 0, 0));
    try {
      await onWatchingServer(`?shader=${prefix}${name}&size=32x18&time=0`, async (page) => {
        expect(pixel(await readPixels(page), 5, 5)).toEqual([200, 0, 0]);
        let colour;
        await touchUntil(
          () => fs.writeFileSync(file, solid(0, 0, 200)),
          300,
          async () => (colour = pixel(await readPixels(page), 5, 5))[2] === 200,
        );
        expect(colour).toEqual([0, 0, 200]);
        expect(await info(page)).toMatchObject({ origin: 'url', fileName: name });
      });
    } finally {
      fs.rmSync(file, { force: true });
    }
  });

  // The built-in shader comes in through a `?raw` import: Vite's own hot update. Only the file's
  // modification time is touched (the content is never rewritten, so no edit can be lost).
  test('shaders/raytrace.glsl, the built-in shader', async () => {
    await onWatchingServer('?size=32x18&time=0', async (page) => {
      const before = (await info(page)).compiled;
      let compiled;
      const touch = () => {
        const now = new Date();
        fs.utimesSync(SHADER_FILE, now, now);
      };
      await touchUntil(touch, 400, async () => (compiled = (await info(page)).compiled) !== before);
      expect(compiled).toBeGreaterThan(before);
      expect(await info(page)).toMatchObject({ origin: 'builtin', fileName: 'shaders/raytrace.glsl' });
    });
  });
});
