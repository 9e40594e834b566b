// Every wait on a page ends (src/headless/watch.js), but a wait whose caller gave it a timeout of
// its own keeps it: 0 is no limit but a crash (a converge of thousands of samples, frame 99,999:
// issue 36, item 2, where a blanket 120 s cap cut every long render). Without a browser: a page
// stand-in whose waits settle when told.
import { EventEmitter } from 'node:events';
import { expect, test } from 'vitest';
import { watchPage } from '../../src/headless/watch.js';

/**
 * A page whose waits resolve after `ms` with what a page says when asked what it was doing
 * (watch.js describe() asks with evaluate after a wait is cut), and a browser, both event emitters.
 */
function standIns(ms) {
  const page = Object.assign(new EventEmitter(), {
    setDefaultTimeout() {},
    close: async () => {},
  });
  const state = { url: 'http://stand-in/', frame: null, error: null, status: null, shaderEngine: false, info: null };
  const later = () => new Promise((resolve) => setTimeout(() => resolve(state), ms));
  for (const name of ['evaluate', 'evaluateHandle', 'waitForFunction', 'waitForSelector', 'goto', 'reload', '$eval', '$$eval'])
    page[name] = later;
  return { page: /** @type {any} */ (page), browser: /** @type {any} */ (new EventEmitter()) };
}

test.each([
  ["the watch's own limit cuts a wait that gives none", (p) => p.evaluate(() => 1), 'cut'],
  ["a caller's timeout 0 is no limit", (p) => p.waitForFunction(() => true, { timeout: 0, polling: 50 }), 'done'],
  ["a caller's own longer timeout stands", (p) => p.waitForFunction(() => true, { timeout: 5_000 }), 'done'],
  ["a caller's own shorter timeout stands", (p) => p.goto('http://x/', { timeout: 20 }), 'cut'],
])('%s', async (_, wait, outcome) => {
  const { page, browser } = standIns(300);
  watchPage(page, browser, { waitTimeoutMs: 100 });
  const result = await wait(page).then(
    () => 'done',
    (error) => (/no answer within/.test(error.message) ? 'cut' : error.message),
  );
  expect(result).toBe(outcome);
});

test('an unbounded wait still ends at once when the browser goes', async () => {
  const { page, browser } = standIns(60_000);
  watchPage(page, browser, { waitTimeoutMs: 100 });
  const waiting = page.waitForFunction(() => false, { timeout: 0 });
  setTimeout(() => browser.emit('disconnected'), 50);
  await expect(waiting).rejects.toThrow(/crashed or was closed/);
});
