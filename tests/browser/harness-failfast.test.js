// The harness fails fast and says why (issue 12): no Chromium is said before anything else; a
// wait on a page that gets no answer fails after its own timeout, well before the test's, with
// what the page was doing; a crashed page or browser fails the wait at once, saying "crashed";
// and the next test still gets a fresh page (src/headless/watch.js, tests/support/page.js).
import { spawn } from 'node:child_process';
import puppeteer from 'puppeteer-core';
import { afterAll, describe, expect, test } from 'vitest';
import { REPO_ROOT } from '../support/config.js';
import { INSTALL_HINT, findChrome } from '../../src/headless/chrome-path.js';
import { disconnect, harnessContext, openPage, useHarness } from '../support/page.js';
import { CHROME_ARGS } from '../../src/headless/browser.js';
import { hook } from '../support/hook.js';

afterAll(disconnect);

/** npm test with no Chromium must stop well within this: it starts nothing. */
const NO_CHROME_TIMEOUT_MS = 60_000;

/** Runs `npm test` with `env` added; resolves with its exit code and everything it printed, in order. */
function npmTest(env) {
  return new Promise((resolve, reject) => {
    // the child must not take itself for a worker of this run
    const base = Object.fromEntries(Object.entries(process.env).filter(([k]) => !/^(VITEST|TEST$|NODE_ENV$)/.test(k)));
    const child = spawn('npm', ['test'], { cwd: REPO_ROOT, env: { ...base, ...env }, stdio: ['ignore', 'pipe', 'pipe'] });
    let output = '';
    child.stdout.on('data', (d) => (output += d));
    child.stderr.on('data', (d) => (output += d));
    const timer = setTimeout(() => {
      child.kill('SIGKILL');
      reject(new Error(`npm test with no Chromium still ran after ${NO_CHROME_TIMEOUT_MS} ms:\n${output}`));
    }, NO_CHROME_TIMEOUT_MS);
    child.on('error', reject);
    child.on('close', (code) => {
      clearTimeout(timer);
      resolve({ code, output });
    });
  });
}

test(
  'with CHROME_PATH naming no file, the first line npm test prints is the install hint',
  async () => {
    const { code, output } = await npmTest({ CHROME_PATH: '/nonexistent/chromium' });
    // npm's own lines (its warnings, "> name@version test", the command) come first; then ours
    const lines = output.split('\n').filter((line) => line.trim() && !/^(> |npm (warn|notice|error))/.test(line));
    expect(lines[0], output).toBe(`CHROME_PATH is /nonexistent/chromium, which does not exist. ${INSTALL_HINT}`);
    expect(code).not.toBe(0);
  },
  NO_CHROME_TIMEOUT_MS + 10_000,
);

/** The wait timeout these tests give their pages: short, so that a hang shows in seconds. */
const SHORT_WAIT_MS = 2_000;
/** How long after SHORT_WAIT_MS (or after a crash) the failure must have come. */
const PROMPT_MS = 8_000;
/** A wait these tests stop watching: a harness that has not failed by then does not fail fast. */
const GIVE_UP_MS = 30_000;

/**
 * What `promise` came to within GIVE_UP_MS, and after how long.
 * @returns {Promise<{value?: unknown, error?: Error, stillWaiting?: true, ms: number}>}
 */
async function settle(promise) {
  const started = Date.now();
  let timer;
  const outcome = await Promise.race([
    promise.then(
      (value) => ({ value }),
      (error) => ({ error }),
    ),
    new Promise((resolve) => (timer = setTimeout(() => resolve({ stillWaiting: true }), GIVE_UP_MS))),
  ]);
  clearTimeout(timer);
  if ('stillWaiting' in outcome) promise.catch(() => {});
  return { ...outcome, ms: Date.now() - started };
}

/** A page as the real one looks when it is stuck: frame 7 drawn, an error, a message (its marks, page-marks.js), `ready` never settling. */
const STUCK_PAGE = `<!doctype html><html><body><canvas></canvas>
<script>window.pageMarks = { frame: 7, error: 'shader: boom', context: null, hung: null, status: 'Compile error on line 3' };
window.shaderEngine = { ready: new Promise(() => {}), info: () => ({ fileName: 'stuck.glsl', time: 1.5, playing: false }) };</script>`;

/** A fresh page answers. */
async function expectFreshPage() {
  const { page, errors } = await openPage();
  try {
    await page.goto('data:text/html,<!doctype html><title>fresh</title>');
    expect(await page.evaluate(() => document.title)).toBe('fresh');
    expect(errors).toEqual([]);
  } finally {
    await page.close();
  }
}

describe('every wait on a page ends, and says why', () => {
  test('a wait that gets no answer fails after its own timeout, saying what the page was doing', async () => {
    const { page } = await openPage({ waitTimeoutMs: SHORT_WAIT_MS });
    try {
      await page.goto(`data:text/html,${encodeURIComponent(STUCK_PAGE)}`);
      for (const wait of [hook(page).ready(), page.waitForFunction(() => document.title === 'never', { polling: 100 })]) {
        const { error, stillWaiting, ms } = await settle(wait);
        expect(stillWaiting, 'still waiting').toBeUndefined();
        expect(ms).toBeLessThan(SHORT_WAIT_MS + PROMPT_MS);
        expect(error?.message).toMatch(/no answer within 2 s|2000 ?ms exceeded/);
        for (const said of ['frames drawn 7', 'shader: boom', 'Compile error on line 3', '"fileName":"stuck.glsl"']) {
          expect(error?.message).toContain(said);
        }
      }
    } finally {
      await page.close();
    }
  });

  test('a page stuck in an endless loop: the wait fails, the page closes at once, the next page is fresh', async () => {
    const { page } = await openPage({ waitTimeoutMs: SHORT_WAIT_MS });
    await page.goto('data:text/html,<!doctype html><title>loop</title>');
    const { error, stillWaiting, ms } = await settle(
      page.evaluate(() => {
        for (;;);
      }),
    );
    expect(stillWaiting, 'still waiting').toBeUndefined();
    expect(ms).toBeLessThan(SHORT_WAIT_MS + PROMPT_MS);
    expect(error?.message).toMatch(/no answer within 2 s\. The page does not answer either/);
    const closed = await settle(page.close());
    expect(closed.stillWaiting, 'close still waiting').toBeUndefined();
    await expectFreshPage();
  });

  test('a page that crashes fails its wait at once, saying "crashed", and the next page is fresh', async () => {
    const { page, errors } = await openPage(); // the full wait timeout: the crash must not wait for it
    await page.goto('data:text/html,<!doctype html><title>crash</title>');
    const wait = page.evaluate(() => new Promise(() => {}));
    const session = await page.createCDPSession();
    session.send('Page.crash').catch(() => {});
    const { error, stillWaiting, ms } = await settle(wait);
    expect(stillWaiting, 'still waiting').toBeUndefined();
    expect(ms).toBeLessThan(PROMPT_MS);
    expect(error?.message).toMatch(/the page crashed/);
    expect(errors.join('\n')).toMatch(/crashed/);
    await page.close();
    await expectFreshPage();
  });

  test('a browser that crashes fails the wait at once, saying "crashed", and the next page comes from another browser', async () => {
    // a browser of this test's own: the run's browser must live on for the other test files
    await disconnect();
    const context = await harnessContext();
    const browser = await puppeteer.launch({ executablePath: findChrome(), headless: true, args: [...CHROME_ARGS] });
    useHarness({ ...context, wsEndpoint: browser.wsEndpoint() });
    try {
      const { page } = await openPage();
      await page.goto('data:text/html,<!doctype html><title>browser crash</title>');
      const wait = page.evaluate(() => new Promise(() => {}));
      const session = await browser.target().createCDPSession();
      session.send('Browser.crash').catch(() => {});
      const { error, stillWaiting, ms } = await settle(wait);
      expect(stillWaiting, 'still waiting').toBeUndefined();
      expect(ms).toBeLessThan(PROMPT_MS);
      expect(error?.message).toMatch(/the browser crashed/);
      await expectFreshPage();
    } finally {
      await disconnect();
      useHarness(undefined);
      browser.process()?.kill('SIGKILL');
    }
  });
});
