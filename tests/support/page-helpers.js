// Shared steps of the page tests (tests/page-*.test.js): open the real page in the harness's
// Chromium, wait for its first frame, read pixels and the inputs the example inspector shader
// (public/examples/inputs.glsl) encodes, and fail on any console error the page logged.

import fs from 'node:fs';
import path from 'node:path';
import { afterAll, expect } from 'vitest';
import { REPO_ROOT } from './config.js';
import { decodeRgba, openPage } from './page.js';
import { hook } from './hook.js';

export const EXAMPLES_DIR = path.join(REPO_ROOT, 'public', 'examples');
export const exampleSource = (name) => fs.readFileSync(path.join(EXAMPLES_DIR, `${name}.glsl`), 'utf8');

/** A Shadertoy shader that paints every pixel rgb(r, g, b) (0..255). */
export const solid = (r, g, b) =>
  `void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n    fragColor = vec4(${r / 255}, ${g / 255}, ${b / 255}, 1.0);\n}\n`;

/**
 * Runs `body(dir, base)` with a fresh folder public/<prefix>-<pid>/ that the page serves as
 * `base`, and removes the folder after.
 */
export async function withServedDir(prefix, body) {
  const dir = path.join(REPO_ROOT, 'public', `${prefix}-${process.pid}`);
  fs.mkdirSync(dir, { recursive: true });
  try {
    await body(dir, path.basename(dir));
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

/**
 * What withPage hands its body: the page, what it logged, the harness, and `goto`.
 * @typedef {object} PageSession
 * @property {import('puppeteer-core').Page} page
 * @property {string[]} errors console errors and page errors
 * @property {string[]} warnings console warnings
 * @property {import('../globals.js').HarnessContext} context
 * @property {(query: string, options?: {expectReady?: boolean, base?: string}) => Promise<void>} goto
 *   loads the page at `query` ("?shader=...") and waits for its first frame (or its failure)
 */

/**
 * Whether this test file's withPage calls share one page (sharePageAcrossTests): the second and
 * later `goto`s bring it to their view with window.shaderEngine.open(), which gives what a fresh
 * load of that URL gives (tests/browser/page-open.test.js), instead of loading the page again.
 */
let sharing = false;
/** The page this file's tests share, once one has loaded it. @type {{page: import('puppeteer-core').Page, errors: string[], warnings: string[], context: any, loaded: boolean} | null} */
let shared = null;

/**
 * For a test file whose tests are not about loading the page: its withPage calls share one page,
 * and each `goto` after the first is window.shaderEngine.open() (a page load is most of a short
 * test). Call it at the top of the file. The shared page has the production timeouts and the
 * deterministic clocks; a withPage given other ones, or a beforeLoad, gets a page of its own.
 */
export function sharePageAcrossTests() {
  sharing = true;
  afterAll(async () => {
    const kept = shared;
    shared = null;
    await kept?.page.close().catch(() => {});
  });
}

/** A page of openPage's with its warnings collected. */
async function newPage({ deterministic, timeouts }) {
  const { page, errors, context } = await openPage({ deterministic, timeouts });
  const warnings = [];
  page.on('console', (message) => {
    if (message.type() === 'warn') warnings.push(message.text());
  });
  return { page, errors, warnings, context, loaded: false };
}

/**
 * Runs `body({page, errors, warnings, context, goto})` on a fresh page and closes it (or, in a
 * file that called sharePageAcrossTests, on the file's page, brought to each `goto`'s view by
 * open()). The test fails if the page logged a console error or threw, even when `body` passed.
 * @param {(p: PageSession) => Promise<void>} body
 * `deterministic: false` leaves the page's clocks real (the watchdog's tests need time to pass
 * while no animation frame is asked for); `timeouts` shortens the page's (harness/config.js's
 * SHORT_TIMEOUTS).
 * @param {{viewport?: import('puppeteer-core').Viewport, beforeLoad?: (page: import('puppeteer-core').Page) => Promise<unknown>, deterministic?: boolean, timeouts?: Partial<import('../../src/shared/timeouts.js').Timeouts>}} [options]
 */
export async function withPage(body, { viewport, beforeLoad, deterministic = true, timeouts } = {}) {
  // a page set up otherwise before it loads is a page of its own, as without sharing
  const shares = sharing && !beforeLoad && deterministic && !timeouts;
  const session = shares && shared && !shared.page.isClosed() ? shared : await newPage({ deterministic, timeouts });
  if (shares) shared = session;
  const { page, context, errors, warnings } = session;
  // what this test's page logs: from now on (a shared page's earlier tests have had theirs)
  errors.length = 0;
  warnings.length = 0;
  await page.setViewport(viewport ?? { width: 800, height: 600, deviceScaleFactor: 1 });
  if (beforeLoad) await beforeLoad(page);
  /** Loads the page at `query` ("?shader=...") and waits for its first frame (or its failure). */
  const goto = async (query, { expectReady = true, base = context.baseUrl } = {}) => {
    if (shares && session.loaded && base === context.baseUrl && expectReady) {
      const outcome = await page.evaluate(
        (q) =>
          window.shaderEngine.open(q).then(
            () => 'ok',
            (e) => `open rejected: ${e?.message ?? e}`,
          ),
        query,
      );
      expect(outcome, `${query}: the page did not draw its first frame`).toBe('ok');
      return;
    }
    await page.goto(`${base}/${query}`, { waitUntil: 'load' });
    await page.waitForFunction(() => window.shaderEngine || document.documentElement.dataset.error, { polling: 50 });
    session.loaded = base === context.baseUrl;
    if (expectReady) {
      const outcome = await page.evaluate(() =>
        window.shaderEngine.ready.then(
          () => 'ok',
          (e) => `ready rejected: ${e?.message ?? e}`,
        ),
      );
      expect(outcome, `${query}: the page did not draw its first frame`).toBe('ok');
    }
  };
  let passed = false;
  try {
    await body({ page, errors, warnings, context, goto });
    passed = true;
  } finally {
    // edits the page kept in localStorage (kept-source.js) must not reach the next test's page
    await page.evaluate(() => localStorage.clear()).catch(() => {});
    if (!shares || !passed) {
      await page.close().catch(() => {});
      if (shared === session) shared = null;
    }
  }
  expect([...errors], 'the page logged errors').toEqual([]);
}

/** Lets the page read and write the clipboard (and focuses it: the Clipboard API wants focus). */
export async function allowClipboard(page, baseUrl) {
  await page.browserContext().overridePermissions(baseUrl, ['clipboard-read', 'clipboard-write', 'clipboard-sanitized-write']);
  await page.bringToFront();
}

/** Presses a key with Control held. */
export async function withControl(page, key) {
  await page.keyboard.down('Control');
  await page.keyboard.press(key);
  await page.keyboard.up('Control');
}

/** window.shaderEngine.readPixels(): a new frame, rows top to bottom. */
export async function readPixels(page) {
  const r = await hook(page).readPixels();
  return { width: r.width, height: r.height, data: decodeRgba(r.data, r.width, r.height, 'readPixels') };
}

/**
 * Starts waiting for the next frame the page draws by itself, and returns once the page is
 * waiting (so that an action sent after it cannot be drawn before). Call the returned function
 * after acting: it resolves with that frame.
 */
export async function nextFrame(page) {
  await page.evaluate(() => {
    window.__nextFrame = window.shaderEngine.nextFrame();
  });
  return () =>
    page
      .evaluate(() => window.__nextFrame)
      .then((r) => ({ width: r.width, height: r.height, iFrame: r.iFrame, data: decodeRgba(r.data, r.width, r.height, 'nextFrame') }));
}

export async function info(page) {
  return hook(page).info();
}

/** RGB of the pixel at (x, y), y counted from the top. */
export function pixel(image, x, y) {
  const i = (y * image.width + x) * 4;
  return [image.data[i], image.data[i + 1], image.data[i + 2]];
}

// ---- public/examples/inputs.glsl --------------------------------------------------------------

const DATA = Object.freeze({
  iFrame: 0,
  mouseX: 1,
  mouseY: 2,
  mouseZ: 3,
  mouseW: 4,
  resX: 5,
  resY: 6,
  resZ1000: 7,
  year: 8,
  month: 9,
  day: 10,
  seconds: 11,
  timeMs: 12,
  delta1e5: 13,
  fragX2: 14,
  fragY2: 15,
});
const CHECKS = [
  'iResolution.z == 1',
  'fragCoord at pixel centres',
  'fragCoord inside the canvas',
  'iFrame >= 0',
  'iTimeDelta > 0 and iFrameRate > 0',
  'iMouse.w > 0 only while held (z > 0)',
  'clicks land on the canvas',
  'iDate fields in range',
  'an empty channel samples black',
  'iTime >= 0',
];
const CELL = 10;
const PASS = [0, 200, 80];
const FAIL = [230, 30, 30];

/** A value of the data strip at a pixel (gl x, gl y within rows 0..9). */
export function dataAt(image, glX, glY) {
  const [r, g, b] = pixel(image, glX, image.height - 1 - glY);
  return r * 65536 + g * 256 + b - 8388608;
}

/** Data cell `k`, read at its centre. */
function dataCell(image, k) {
  return dataAt(image, k * CELL + CELL / 2, CELL / 2);
}

/** Every decoded input of a frame of inputs.glsl. */
export function decodeInputs(image) {
  const out = {};
  for (const [name, k] of Object.entries(DATA)) out[name] = dataCell(image, k);
  out.mouse = [out.mouseX, out.mouseY, out.mouseZ, out.mouseW];
  return out;
}

/** The check strip: { name: 'pass'|'fail'|'?' } for each rule. */
export function checkResults(image) {
  return Object.fromEntries(
    CHECKS.map((name, k) => {
      const colour = pixel(image, k * CELL + CELL / 2, image.height - 1 - (CELL + CELL / 2));
      const is = (c) => c.every((v, i) => Math.abs(v - colour[i]) <= 1);
      return [name, is(PASS) ? 'pass' : is(FAIL) ? 'fail' : `? rgb(${colour})`];
    }),
  );
}

/** The canvas's box in CSS pixels. */
export async function canvasBox(page) {
  return page.evaluate(() => {
    const r = /** @type {HTMLElement} */ (document.getElementById('view')).getBoundingClientRect();
    return { left: r.left, top: r.top, width: r.width, height: r.height };
  });
}

/** The overlay's text, or null while it is hidden. */
export async function overlayText(page) {
  return page.evaluate(() => {
    const o = /** @type {HTMLElement | null} */ (document.querySelector('[role="alert"]'));
    return o && !o.hidden ? o.textContent : null;
  });
}

/** A button by its accessible name (puppeteer's ARIA query). */
export async function button(page, name) {
  const handle = await page.$(`::-p-aria([name="${name}"][role="button"])`);
  if (!handle) throw new Error(`no button named "${name}"`);
  return handle;
}

// ---- the editor (CodeMirror 6, src/studio/ui/editor.js) -------------------------------------------

/** The editor's text area (CodeMirror's content element). */
export const EDITOR = '.cm-content[aria-label="Shader source"]';

/** Opens the editor with its "Edit shader" button (if it is closed) and waits for its text. */
export async function openEditor(page) {
  if (!(await page.$eval('#editor', (e) => !(/** @type {HTMLElement} */ (e).hidden)))) await (await button(page, 'Edit shader')).click();
  await page.waitForSelector(EDITOR, { visible: true });
}

/** The editor's whole text (compiled or not). */
export async function editorText(page) {
  return hook(page).editorSource();
}

/**
 * Types `text` into the editor as a person does: `at` 'end' (Ctrl+End first), 'start' (Ctrl+Home)
 * or 'cursor' (where the cursor is). CodeMirror closes brackets as they are typed, and skips the
 * closing one when it is typed.
 * @param {import('puppeteer-core').Page} page
 * @param {string} text
 * @param {'end' | 'start' | 'cursor'} [at]
 */
export async function typeInEditor(page, text, at = 'end') {
  await openEditor(page);
  if (!(await page.$eval(EDITOR, (e) => e.contains(document.activeElement)))) await page.focus(EDITOR);
  if (at !== 'cursor') {
    await page.keyboard.down('Control');
    await page.keyboard.press(at === 'end' ? 'End' : 'Home');
    await page.keyboard.up('Control');
  }
  await page.keyboard.type(text);
}

/** Puts `text` on the clipboard and pastes it over everything in the editor, as a person does (needs clipboard permission). */
export async function pasteIntoEditor(page, text) {
  await page.evaluate((t) => navigator.clipboard.writeText(t), text);
  await openEditor(page);
  await page.focus(EDITOR);
  await page.keyboard.down('Control');
  await page.keyboard.press('KeyA');
  await page.keyboard.up('Control');
  await page.keyboard.press('KeyV', { commands: ['Paste'] });
}

/** The line numbers that show a compile-error marker in the editor's gutter (of the lines drawn). */
export async function errorMarkerLines(page) {
  return page.evaluate(() => {
    const top = (e) => Math.round(e.getBoundingClientRect().top);
    const numbers = new Map(
      [...document.querySelectorAll('.cm-lineNumbers .cm-gutterElement')].map((e) => [top(e), Number(e.textContent)]),
    );
    return [...document.querySelectorAll('.cm-lint-marker-error')].map((m) => numbers.get(top(m.closest('.cm-gutterElement'))));
  });
}

/** The line the editor's cursor is on (its highlighted line number). */
async function cursorLine(page) {
  return page.$eval('.cm-lineNumbers .cm-activeLineGutter', (e) => Number(e.textContent));
}

/**
 * Waits until the editor's cursor is on `line` (the gutter marks the active line once the editor
 * has scrolled there and drawn it, which may take an animation frame), and returns it.
 */
export async function waitForCursorLine(page, line) {
  await page
    .waitForFunction(
      (n) => Number(document.querySelector('.cm-lineNumbers .cm-activeLineGutter')?.textContent) === n,
      { polling: 50, timeout: 5000 },
      line,
    )
    .catch(() => {});
  return cursorLine(page);
}

/**
 * Records, from the page's start, each line the frame-time readout shows, in window.__readouts as
 * [text, the frame rate the page really reached then, ms since its first frame]: the rate from
 * when it drew each frame (the canvas's data-frame attribute), over the frames of the two seconds
 * up to the last one, taken over whichever run of the latest of them was fastest. The readout
 * counts its frames from the last time its rate started again (a new phase, or a frame that
 * follows a gap), which this cannot see: over the whole two seconds, a page slowed by a
 * neighbour's load draws slower than the readout's own, shorter, window says. Call before the
 * page loads.
 * @param {import('puppeteer-core').Page} page
 */
export async function recordReadouts(page) {
  await page.evaluateOnNewDocument(() => {
    /** @type {number[]} */
    const drawnAt = [];
    /** @type {Array<[string, number, number]>} */
    const samples = [];
    /** @type {any} */ (window).__readouts = samples;
    new MutationObserver((records) => {
      for (const record of records) {
        if (record.type === 'attributes') drawnAt.push(performance.now());
        else if (record.target instanceof Element && record.target.matches('#toolbar .fps')) {
          const last = drawnAt[drawnAt.length - 1] ?? 0;
          const recent = drawnAt.filter((x) => last - x <= 2000);
          let fps = 0;
          for (let k = 1; k < recent.length; k++) fps = Math.max(fps, (k * 1000) / (last - recent[recent.length - 1 - k]));
          samples.push([record.target.textContent, fps, drawnAt.length ? last - drawnAt[0] : -1]);
        }
      }
    }).observe(document, { subtree: true, childList: true, attributeFilter: ['data-frame'] });
  });
}
