// An endless loop pasted over a playing shader (issue 36, item 8): what the page says while it
// compiles and once it draws for ever, and the wait for the page's paint before that draw.
// SwiftShader never gets over an endless draw, so that page runs in a browser of its own,
// killed after; the tests of that describe read one page, in order.

import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import puppeteer from 'puppeteer-core';
import { CHROME_ARGS } from '../../src/headless/browser.js';
import { findChrome } from '../../src/headless/chrome-path.js';
import { harnessContext } from '../support/page.js';
import { pasteIntoEditor, withPage } from '../support/page-helpers.js';
import { SHORT_TIMEOUTS } from '../support/config.js';
import { hook } from '../support/hook.js';

/** A shader that never finishes: the loop's exit depends on a sum that never gets there. */
const ENDLESS_SHADER = `void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    float sum = 0.0;
    for (int i = 0; ; i++) {
        sum += abs(sin(float(i) + fragCoord.x));
        if (sum < -1.0) break;
    }
    fragColor = vec4(sum, 0.0, 0.0, 1.0);
}`;
/** A cheap shader, pasted first: it too goes by "untitled". */
const CHEAP_SHADER = 'void mainImage(out vec4 c, in vec2 p) { c = vec4(p.x / 128.0, 0.5, 0.25, 1.0); }';
const SIZE = 'size=128x72';
/** The short timeouts, but a browser of its own gets longer to start its first render worker (its
 * GPU process starts with it: it took over 2 s, under load, in 1 of 4 fresh browsers here). */
const OWN_BROWSER_TIMEOUTS = { ...SHORT_TIMEOUTS, workerStartMs: 10_000 };
const readout = (page) => page.$eval('#toolbar .fps', (e) => e.textContent);
const alertText = (page) => page.$eval('[role="alert"]', (e) => e.textContent ?? '');
/** The seconds the watchdog's message says the frame has been drawing. */
const saidSeconds = async (page) => Number(/for (\d+) s without finishing/.exec(await alertText(page))?.[1]);

describe('an endless loop pasted over an untitled shader (in a browser of its own)', () => {
  /** @type {import('puppeteer-core').Browser} */
  let browser;
  /** @type {import('puppeteer-core').Page} */
  let page;
  /** From the paste to the watchdog's "may never finish", ms. */
  let hungAfterMs = 0;

  beforeAll(async () => {
    const { baseUrl } = await harnessContext();
    browser = await puppeteer.launch({ executablePath: findChrome(), args: CHROME_ARGS, headless: true });
    page = await browser.newPage();
    await page.setViewport({ width: 800, height: 600, deviceScaleFactor: 1 });
    await page.evaluateOnNewDocument((chosen) => {
      /** @type {any} */ (window).__shaderEngineTimeouts = chosen;
    }, OWN_BROWSER_TIMEOUTS);
    await page.browserContext().overridePermissions(baseUrl, ['clipboard-read', 'clipboard-write', 'clipboard-sanitized-write']);
    await page.goto(`${baseUrl}/?shader=examples/pattern.glsl&${SIZE}`, { waitUntil: 'load' });
    await page.waitForFunction(() => window.shaderEngine, { polling: 50 });
    await hook(page).ready();
    await page.bringToFront();
    const frame = async () =>
      Number(
        await hook(page)
          .info()
          .then((r) => r.frame),
      );
    await pasteIntoEditor(page, CHEAP_SHADER);
    await page.waitForFunction(() => window.shaderEngine.info().fileName === 'untitled', { polling: 50 });
    // the cheap shader draws frames (it is the one to go back to), and plays
    const drawn = await frame();
    await page.waitForFunction((f) => window.shaderEngine.info().frame > f + 5, { polling: 50, timeout: 30_000 }, drawn);
    const pasted = Date.now();
    await pasteIntoEditor(page, ENDLESS_SHADER);
    await page.waitForFunction(() => document.documentElement.dataset.hung === 'true', {
      polling: 50,
      timeout: SHORT_TIMEOUTS.compileHangMs + 30_000,
    });
    hungAfterMs = Date.now() - pasted;
  });

  afterAll(async () => {
    browser?.process()?.kill('SIGKILL'); // its GPU process is stuck in the draw for good
    await browser?.disconnect().catch(() => {});
  });

  test('it is called a hang once it draws past the watchdog, not after the time a compile is given', async () => {
    // the compile is a draw of no pixel (render-worker.js): the loop runs only in the bands after it
    console.log(`"may never finish" ${hungAfterMs} ms after the paste (compileHangMs ${SHORT_TIMEOUTS.compileHangMs})`);
    expect(hungAfterMs).toBeLessThan(SHORT_TIMEOUTS.compileHangMs);
    expect(await alertText(page)).toContain('untitled may never finish');
  });

  test("the message's seconds count on while the draw goes on", async () => {
    const first = await saidSeconds(page);
    await new Promise((resolve) => setTimeout(resolve, 2200));
    const later = await saidSeconds(page);
    expect(later, `${first} s, then ${later} s`).toBeGreaterThanOrEqual(first + 2);
  });

  test('the readout says no frame is coming, with no figure from frames before it', async () => {
    const line = await readout(page);
    expect(line).toMatch(/^No frame for \d+ s · may never finish$/);
    expect(line).not.toMatch(/fps|ms/);
  });

  test('"Go back" names the shader before apart from the one that hung, both untitled', async () => {
    const labels = await page.$$eval('[role="alert"] button', (buttons) => buttons.map((b) => b.textContent));
    expect(labels).toEqual(['Go back to the previous untitled']);
  });
});

/**
 * Before the page loads: once window.__slowFrames is set, an animation frame's callback runs 1.5 s
 * late (a page under load), and the time the page tells the worker 'settled' and the time the
 * worker says a compiling band started are noted.
 */
function slowFramesAndNoteTheGate() {
  const w = /** @type {any} */ (window);
  w.__gate = { settledAt: 0, compileStartedAt: 0 };
  const native = window.requestAnimationFrame.bind(window);
  window.requestAnimationFrame = (callback) => native((time) => (w.__slowFrames ? setTimeout(() => callback(time), 1500) : callback(time)));
  const Native = window.Worker;
  window.Worker = class extends Native {
    /** @param {any} message @param {any} [transfer] */
    postMessage(message, transfer) {
      if (message?.type === 'settled' && w.__slowFrames) w.__gate.settledAt = performance.now();
      super.postMessage(message, transfer);
    }
    set onmessage(handler) {
      super.onmessage = (/** @type {MessageEvent} */ event) => {
        const { kind, type, params } = event.data ?? {};
        if (w.__slowFrames && kind === 'event' && type === 'bandStarted' && params?.compiling)
          w.__gate.compileStartedAt ||= performance.now();
        handler(event);
      };
    }
  };
}

describe("a new program's first draw waits for the page's paint", () => {
  test('however late the animation frames come: the draw starts only after the page said it painted', async () => {
    await withPage(
      async ({ page, goto }) => {
        await goto(`?shader=examples/pattern.glsl&${SIZE}`);
        await page.evaluate(() => {
          /** @type {any} */ (window).__slowFrames = true;
          void window.shaderEngine.setSource('void mainImage(out vec4 c, in vec2 p) { c = vec4(0.5, p.y / 72.0, 0.25, 1.0); }');
        });
        await page.waitForFunction(() => /** @type {any} */ (window).__gate.compileStartedAt > 0, { polling: 50, timeout: 30_000 });
        const { settledAt, compileStartedAt } = await page.evaluate(() => /** @type {any} */ (window).__gate);
        expect(settledAt, 'the page said it had painted').toBeGreaterThan(0);
        expect(compileStartedAt, 'the first draw began after the page said so').toBeGreaterThan(settledAt);
        await page.evaluate(() => {
          /** @type {any} */ (window).__slowFrames = false;
        });
      },
      { deterministic: false, beforeLoad: (page) => page.evaluateOnNewDocument(slowFramesAndNoteTheGate) },
    );
  });
});
