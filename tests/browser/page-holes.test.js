// Issue 12's smaller holes, in the real page: a load that never gets an answer ends with a message
// (src/player/io/shader-loader.js, after src/shared/timeouts.js's loadMs, shortened here), and an image or a shader from another origin is
// refused up front, whether asked for directly or reached through a redirect, without a console
// error. The page's server gets its hanging and redirecting URLs from tests/support/routes.js; the
// other origin is a small server of this file's own.
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { SHORT_TIMEOUTS } from '../support/config.js';
import { makeImage, writePng } from '../support/images.js';
import { disconnect } from '../support/page.js';
import { hangUrl, redirectUrl } from '../support/routes.js';
import { info, overlayText, pixel, readPixels, solid, withPage, withServedDir } from '../support/page-helpers.js';
import { hook } from '../support/hook.js';

afterAll(disconnect);

/** The load timeout these pages run with (the production one is tests/unit/timeouts.test.js's). */
const LOAD_TIMEOUT_MS = SHORT_TIMEOUTS.loadMs;
/** How much longer than LOAD_TIMEOUT_MS a test waits for the page's message before it fails. */
const MESSAGE_MARGIN_MS = 20_000;
/** A test that waits out one LOAD_TIMEOUT_MS (and loads the page). */
const SLOW_TEST_MS = LOAD_TIMEOUT_MS * 2 + MESSAGE_MARGIN_MS;
const TIMED_OUT = `did not answer within ${LOAD_TIMEOUT_MS / 1000} s`;
const SIZE = 'size=64x36&time=0';
const PATTERN = 'shader=examples/pattern.glsl';

/** Top half of the canvas: iChannel0 near its top (v = 0.75); bottom half: near its bottom. Left: rgb, right: alpha, iChannelResolution. */
const CHANNEL_SHADER = `void mainImage(out vec4 c, in vec2 f) {
    vec4 t = texture(iChannel0, vec2(0.5, f.y > iResolution.y * 0.5 ? 0.75 : 0.25));
    c = f.x < iResolution.x * 0.5 ? vec4(t.rgb, 1.0) : vec4(t.a, iChannelResolution[0].xy / 255.0, 1.0);
}
`;
/** A 1x2 image: top row red and half transparent, bottom row blue. */
const TOP = [255, 0, 0, 128];
const BOTTOM = [0, 0, 255, 255];

/** A server on another origin (another port) with an image and a shader, readable by anyone (CORS). */
let other;
let otherOrigin;
beforeAll(async () => {
  const png = fs.readFileSync(await pngFile());
  other = http.createServer((req, res) => {
    if (req.url === '/img.png') res.writeHead(200, { 'content-type': 'image/png' }).end(png);
    else if (req.url === '/a.glsl') res.writeHead(200, { 'content-type': 'text/plain' }).end(solid(0, 255, 0));
    else res.writeHead(404).end();
  });
  await new Promise((resolve) => other.listen(0, '127.0.0.1', () => resolve(undefined)));
  otherOrigin = `http://127.0.0.1:${/** @type {import('node:net').AddressInfo} */ (other.address()).port}`;
});
afterAll(() => new Promise((resolve) => (other ? other.close(resolve) : resolve(undefined))));

async function pngFile() {
  const file = path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'raytracer-holes-')), 'top-red.png');
  const image = makeImage(1, 2, () => [0, 0, 0]);
  image.data.set(TOP, 0);
  image.data.set(BOTTOM, 4);
  writePng(file, image);
  return file;
}

/** Runs `body(base)` with top-red.png and channel.glsl served by the page's server under `base`. */
async function withChannelFiles(body) {
  await withServedDir('test-holes', async (dir, base) => {
    fs.copyFileSync(await pngFile(), path.join(dir, 'top-red.png'));
    fs.writeFileSync(path.join(dir, 'channel.glsl'), CHANNEL_SHADER);
    fs.writeFileSync(path.join(dir, 'green.glsl'), solid(0, 255, 0));
    await body(base);
  });
}

/**
 * What `window.shaderEngine[method](...args)` came to in the page: {value} or {error} (its message),
 * or {error: 'still waiting'} after LOAD_TIMEOUT_MS and the margin, so that a hang fails the test
 * with that rather than with the test's timeout.
 * @returns {Promise<{value?: any, error?: string}>}
 */
function settleInPage(page, method, ...args) {
  return page.evaluate(
    (name, wait, rest) =>
      Promise.race([
        window.shaderEngine[name](...rest).then(
          (value) => ({ value }),
          (error) => ({ error: String(error?.message ?? error) }),
        ),
        new Promise((resolve) => setTimeout(() => resolve({ error: 'still waiting' }), wait)),
      ]),
    method,
    LOAD_TIMEOUT_MS + MESSAGE_MARGIN_MS,
    args,
  );
}

describe('a load that never gets an answer ends with a message', () => {
  test(
    `?shader= that never answers: after ${LOAD_TIMEOUT_MS / 1000} s the page says so and runs the built-in shader`,
    async () => {
      await withPage(
        async ({ page, warnings, context }) => {
          const url = hangUrl(context.baseUrl);
          const started = Date.now();
          await page.goto(`${context.baseUrl}/?shader=${encodeURIComponent(url)}&${SIZE}`, { waitUntil: 'load' });
          await page
            .waitForFunction(
              (text) => document.querySelector('[role="alert"]:not([hidden])')?.textContent.includes(text),
              { timeout: LOAD_TIMEOUT_MS + MESSAGE_MARGIN_MS, polling: 200 },
              TIMED_OUT,
            )
            .catch(() => {
              throw new Error(`no "${TIMED_OUT}" on the page after ${(Date.now() - started) / 1000} s`);
            });
          expect(Date.now() - started).toBeGreaterThanOrEqual(LOAD_TIMEOUT_MS);
          expect(await overlayText(page)).toContain(`Could not load ${url}`);
          expect(
            await hook(page)
              .ready()
              .then(() => 'drawn'),
          ).toBe('drawn');
          expect((await info(page)).origin).toBe('builtin');
          expect(
            warnings.some((w) => w.includes(`shader=${url}`) && w.includes(TIMED_OUT)),
            warnings.join('\n'),
          ).toBe(true);
        },
        { timeouts: SHORT_TIMEOUTS },
      );
    },
    SLOW_TEST_MS,
  );

  test(
    'loadShader() and setChannel() of a URL that never answers reject with the same message',
    async () => {
      await withPage(
        async ({ page, goto, context }) => {
          await goto(`?${PATTERN}&${SIZE}`);
          const url = hangUrl(context.baseUrl);
          const [shader, image] = await Promise.all([settleInPage(page, 'loadShader', url), settleInPage(page, 'setChannel', 0, url)]);
          expect(shader.value).toEqual({ ok: false, error: `the server ${TIMED_OUT}` });
          expect(image.error).toBe(`the server ${TIMED_OUT}`);
          expect((await info(page)).fileName).toBe('pattern.glsl'); // still running
        },
        { timeouts: SHORT_TIMEOUTS },
      );
    },
    SLOW_TEST_MS,
  );
});

describe('images and shaders of another origin are refused up front', () => {
  test('an image keeps its orientation (v = 1 is its top row) and its exact pixels, alpha not premultiplied', async () => {
    await withChannelFiles(async (base) => {
      await withPage(async ({ page, goto }) => {
        await goto(`?shader=${base}/channel.glsl&${SIZE}&iChannel0=${base}/top-red.png`);
        await page.waitForFunction(
          () => window.shaderEngine.info().fileName === 'channel.glsl' && document.querySelector('.lil-gui')?.textContent.includes('(1×2)'),
        );
        const frame = await readPixels(page);
        expect(pixel(frame, 10, 5)).toEqual(TOP.slice(0, 3)); // top of the canvas: the image's top
        expect(pixel(frame, 10, 30)).toEqual(BOTTOM.slice(0, 3));
        expect(pixel(frame, 50, 5)).toEqual([TOP[3], 1, 2]); // alpha; the size 1 x 2
      });
    });
  });

  test('setChannel() of an image on another origin rejects, and the channel stays empty', async () => {
    await withChannelFiles(async (base) => {
      await withPage(async ({ page, goto, context }) => {
        await goto(`?shader=${base}/channel.glsl&${SIZE}`);
        const outcome = await settleInPage(page, 'setChannel', 0, `${otherOrigin}/img.png`);
        expect(outcome.error).toBe(`only files served by this page's server (${context.baseUrl}) can be loaded`);
        await page.waitForFunction(() => window.shaderEngine.info().fileName === 'channel.glsl');
        const frame = await readPixels(page);
        // size 0 x 0: nothing bound (the page's state in the message, should it ever differ)
        expect(pixel(frame, 50, 5).slice(1), JSON.stringify(await info(page))).toEqual([0, 0]);
      });
    });
  });

  test('a URL of the page that redirects to another origin is refused: image or shader, by URL or by the hook', async () => {
    await withChannelFiles(async (base) => {
      await withPage(async ({ page, goto, warnings, context }) => {
        const awayImage = redirectUrl(context.baseUrl, `${otherOrigin}/img.png`);
        const awayShader = redirectUrl(context.baseUrl, `${otherOrigin}/a.glsl`);
        const refused = `the server redirected it to another origin; only files served by this page's server (${context.baseUrl}) can be loaded`;

        await goto(`?shader=${encodeURIComponent(awayShader)}&${SIZE}&iChannel0=${encodeURIComponent(awayImage)}`);
        expect(await overlayText(page)).toContain(`Could not load ${awayShader}`);
        expect(await overlayText(page)).toContain(refused);
        expect((await info(page)).origin).toBe('builtin');
        await page.waitForFunction(() => document.getElementById('toast').textContent.includes('into iChannel0'));
        expect(
          warnings.some((w) => w.includes(`iChannel0=${awayImage}`) && w.includes(refused)),
          warnings.join('\n'),
        ).toBe(true);

        await goto(`?shader=${base}/channel.glsl&${SIZE}`);
        const image = await settleInPage(page, 'setChannel', 0, awayImage);
        expect(image.error).toBe(refused);
        expect(pixel(await readPixels(page), 50, 5).slice(1)).toEqual([0, 0]);
        const shader = await settleInPage(page, 'loadShader', awayShader);
        expect(shader.value).toEqual({ ok: false, error: refused });
        expect((await info(page)).fileName).toBe('channel.glsl');
      });
    });
  });

  test("a redirect within the page's own server still loads", async () => {
    await withChannelFiles(async (base) => {
      await withPage(async ({ page, goto, context }) => {
        await goto(`?shader=${base}/channel.glsl&${SIZE}`);
        const image = await settleInPage(page, 'setChannel', 0, redirectUrl(context.baseUrl, `/${base}/top-red.png`));
        expect(image.error).toBeUndefined();
        expect(pixel(await readPixels(page), 10, 5)).toEqual(TOP.slice(0, 3));
        const shader = await settleInPage(page, 'loadShader', redirectUrl(context.baseUrl, `/${base}/green.glsl`));
        expect(shader.value).toEqual({ ok: true });
        expect(pixel(await readPixels(page), 10, 5)).toEqual([0, 255, 0]);
      });
    });
  });
});
