// What the toolbar, the notes and the popovers cover (issue 36, items 9 and 10), measured with the
// boxes the browser lays out, at every width from a phone's up and at short windows:
// - the toolbar keeps to one or two rows, each button's label on one line (icons with a tooltip
//   and an accessible name where labels do not fit; what does not fit at all in a "More" menu),
//   and every row of the panel can be scrolled into view whole, clear of the toolbar;
// - the toast, the notes and the Record popover lie apart: the toast after a dropped file that is
//   not a shader is off the note that says why, the notes stack, and the popover is off the
//   shader's name in the toolbar.

import { afterAll, describe, expect, test } from 'vitest';
import { disconnect } from '../support/page.js';
import { sharePageAcrossTests, withPage } from '../support/page-helpers.js';
import { dropFile } from '../support/page-multipass-helpers.js';
import { hook } from '../support/hook.js';

sharePageAcrossTests();
afterAll(disconnect);

/** The viewports: a phone, a narrow window, the 800x600, laptops, a desktop; and short ones. */
const VIEWPORTS = [
  [390, 844],
  [390, 600],
  [600, 800],
  [800, 600],
  [1024, 768],
  [1024, 500],
  [1280, 800],
  [1920, 1080],
];

/** The raytracer (its panel is the longest), small and still. */
const QUERY = '?time=0&scale=0.25&SAMPLES=1';

/** Every action of the toolbar, by its accessible name. */
const ACTIONS = [
  'Play',
  'Restart',
  'Reset view',
  'Edit shader',
  'Copy for Shadertoy',
  'Download .glsl',
  'Export JSON',
  'Screenshot',
  'Record',
  'Inspect',
  'Compare with float64',
  'Fullscreen',
  'Copy link',
];

const overlaps = (a, b) => a.left < b.right - 0.5 && b.left < a.right - 0.5 && a.top < b.bottom - 0.5 && b.top < a.bottom - 0.5;
const inside = (inner, outer) =>
  inner.left >= outer.left - 0.5 && inner.top >= outer.top - 0.5 && inner.right <= outer.right + 0.5 && inner.bottom <= outer.bottom + 0.5;

/** The toolbar as laid out: its box, its controls' boxes, the labels' lines, each button's names. */
const toolbarGeometry = (page) =>
  page.evaluate(() => {
    const box = (/** @type {Element} */ e) => {
      const r = e.getBoundingClientRect();
      return { left: r.left, top: r.top, right: r.right, bottom: r.bottom, height: r.height };
    };
    const shown = (/** @type {Element} */ e) => e.getClientRects().length > 0 && getComputedStyle(e).visibility !== 'hidden';
    const toolbar = /** @type {HTMLElement} */ (document.getElementById('toolbar'));
    const controls = [...toolbar.querySelectorAll('button, select, input, .name, .fps')].filter(shown);
    return {
      viewport: { left: 0, top: 0, right: innerWidth, bottom: innerHeight },
      toolbar: box(toolbar),
      controls: controls.map((c) => ({ what: c.getAttribute('aria-label') ?? c.className, ...box(c) })),
      buttons: [...toolbar.querySelectorAll('button')].filter(shown).map((b) => {
        const label = b.querySelector('.label');
        return {
          name: b.getAttribute('aria-label'),
          title: b.title,
          labelLines: label && shown(label) ? label.getClientRects().length : 0,
          ...box(b),
        };
      }),
      // every action is a button somewhere on the page (in the toolbar or its "More" menu)
      named: [...document.querySelectorAll('button[aria-label]')].map((b) => b.getAttribute('aria-label')),
    };
  });

/** Opens every folder of the panel (and the panel, closed on a phone), then waits for it to settle. */
async function openWholePanel(page) {
  await page.evaluate(() => {
    for (const title of document.querySelectorAll('#panel-dock .lil-gui.lil-closed > .lil-title'))
      /** @type {HTMLElement} */ (title).click();
  });
  let last = '';
  for (let i = 0; i < 40; i++) {
    await new Promise((r) => setTimeout(r, 150));
    const now = await page.$eval('#panel-dock', (d) => `${d.scrollHeight} ${d.clientHeight}`);
    if (now === last) return;
    last = now;
  }
}

/** Each row of the panel scrolled into view: its box, the dock's, the toolbar's. */
const panelRows = (page) =>
  page.evaluate(() => {
    const box = (/** @type {Element} */ e) => {
      const r = e.getBoundingClientRect();
      return { left: r.left, top: r.top, right: r.right, bottom: r.bottom };
    };
    const dock = /** @type {HTMLElement} */ (document.getElementById('panel-dock'));
    const rows = [...dock.querySelectorAll('.lil-controller, .lil-title')].filter((r) => r.getClientRects().length > 0);
    return rows.map((row) => {
      row.scrollIntoView({ block: 'nearest' });
      // the dock's client area: its box less its borders and scroll bars
      const d = box(dock);
      const client = { left: d.left + dock.clientLeft, top: d.top + dock.clientTop, right: 0, bottom: 0 };
      client.right = client.left + dock.clientWidth;
      client.bottom = client.top + dock.clientHeight;
      return {
        row: row.textContent?.trim().slice(0, 40),
        box: box(row),
        dock: client,
        toolbar: box(/** @type {Element} */ (document.getElementById('toolbar'))),
        viewport: { left: 0, top: 0, right: innerWidth, bottom: innerHeight },
      };
    });
  });

describe('the toolbar keeps to two rows of readable buttons and hides no panel row', () => {
  test.each(VIEWPORTS)('at %ix%i', async (width, height) => {
    await withPage(
      async ({ page, goto }) => {
        await goto(QUERY);
        const g = await toolbarGeometry(page);
        const where = `${width}x${height}`;
        const rowHeight = Math.max(...g.buttons.map((b) => b.height));
        for (const b of g.buttons) {
          expect(b.labelLines, `${where}: "${b.name}"'s label on one line`).toBeLessThanOrEqual(1);
          expect(b.height, `${where}: "${b.name}" one line high`).toBeLessThanOrEqual(34);
          if (b.labelLines === 0) {
            expect(b.name, `${where}: an icon button has a name`).toBeTruthy();
            expect(b.title, `${where}: "${b.name}" has a tooltip`).toBeTruthy();
          }
        }
        // rows: the distinct vertical centres of the controls
        const centres = [...new Set(g.controls.map((c) => Math.round((c.top + c.bottom) / 2 / 8)))];
        expect(centres.length, `${where}: rows of controls ${JSON.stringify(g.controls)}`).toBeLessThanOrEqual(2);
        expect(g.toolbar.height, `${where}: the toolbar's height`).toBeLessThanOrEqual(2 * rowHeight + 24);
        for (const c of g.controls) {
          expect(inside(c, g.toolbar), `${where}: ${c.what} inside the toolbar ${JSON.stringify(c)}`).toBe(true);
          expect(inside(c, g.viewport), `${where}: ${c.what} inside the window`).toBe(true);
        }
        for (const name of ACTIONS) expect(g.named, `${where}: a button named "${name}"`).toContain(name);

        await openWholePanel(page);
        const rows = await panelRows(page);
        expect(rows.length).toBeGreaterThan(20);
        expect(rows.map((r) => r.row)).toContain('Orbit speed (deg/s)');
        for (const r of rows) {
          const what = `${where}: the panel's row "${r.row}" ${JSON.stringify(r.box)}`;
          expect(inside(r.box, r.dock), `${what} whole in the panel ${JSON.stringify(r.dock)}`).toBe(true);
          expect(inside(r.box, r.viewport), `${what} in the window`).toBe(true);
          expect(overlaps(r.box, r.toolbar), `${what} clear of the toolbar ${JSON.stringify(r.toolbar)}`).toBe(false);
        }
      },
      { viewport: { width, height, deviceScaleFactor: 1 } },
    );
  });
});

/** The boxes of the toast, of each note (and its title), of the Record popover and of the shader's name. */
const messageBoxes = (page) =>
  page.evaluate(() => {
    const box = (/** @type {Element | null} */ e) => {
      if (!e || e.getClientRects().length === 0) return null;
      const r = e.getBoundingClientRect();
      return { left: r.left, top: r.top, right: r.right, bottom: r.bottom };
    };
    return {
      toast: box(document.getElementById('toast')),
      toastText: document.getElementById('toast')?.textContent,
      notes: [...document.querySelectorAll('#notes > *')].map((n) => ({ id: n.id, box: box(n), title: box(n.querySelector('strong')) })),
      record: box(document.querySelector('.record-dialog')),
      name: box(document.querySelector('#toolbar .name')),
      toolbar: box(document.getElementById('toolbar')),
      viewport: { left: 0, top: 0, right: innerWidth, bottom: innerHeight },
    };
  });

describe('notes, the toast and popovers cover nothing they are about', () => {
  test.each(VIEWPORTS)('at %ix%i', async (width, height) => {
    await withPage(
      async ({ page, goto }) => {
        // a value the page cannot use: a note; then a dropped file that is not a shader: a second note and a toast
        await goto(`${QUERY}&NO_SUCH=1`);
        await dropFile(page, 'notshader.json', '{"values": [1, 2, 3]}', 'application/json');
        await page.waitForFunction(() => document.getElementById('load-notes')?.className === 'error', { polling: 50 });
        const where = `${width}x${height}`;
        const m = await messageBoxes(page);
        expect(m.toastText).toBe('Could not load notshader.json');
        expect(m.toast && m.notes.length === 2, `${where}: the toast and two notes ${JSON.stringify(m)}`).toBe(true);
        const boxes = [{ id: 'toast', box: m.toast }, ...m.notes];
        for (const b of boxes) expect(inside(b.box, m.viewport), `${where}: ${b.id} in the window`).toBe(true);
        for (let i = 0; i < boxes.length; i++)
          for (let j = i + 1; j < boxes.length; j++)
            expect(
              overlaps(boxes[i].box, boxes[j].box),
              `${where}: ${boxes[i].id} ${JSON.stringify(boxes[i].box)} over ${boxes[j].id} ${JSON.stringify(boxes[j].box)}`,
            ).toBe(false);

        // the Record popover: off the shader's name and the toolbar, in the window, off the notes
        await page.$eval('#toolbar button[aria-label="Record"], button[aria-label="Record"]', (b) =>
          /** @type {HTMLElement} */ (b).click(),
        );
        const r = await messageBoxes(page);
        expect(r.record, `${where}: the Record popover is open`).not.toBe(null);
        expect(
          overlaps(r.record, r.name),
          `${where}: the popover ${JSON.stringify(r.record)} over the name ${JSON.stringify(r.name)}`,
        ).toBe(false);
        expect(overlaps(r.record, r.toolbar), `${where}: the popover over the toolbar ${JSON.stringify(r.toolbar)}`).toBe(false);
        expect(inside(r.record, r.viewport), `${where}: the popover in the window`).toBe(true);
        await page.keyboard.press('Escape');
      },
      { viewport: { width, height, deviceScaleFactor: 1 } },
    );
  });
});

// ---- a shader with a Sound tab (issue 45, item 9) ---------------------------------------------

/** A Shadertoy export with an Image tab and a Sound tab (a quiet tone). */
const SOUND_PROJECT = JSON.stringify({
  Shader: {
    ver: '0.1',
    info: { name: 'tone' },
    renderpass: [
      {
        inputs: [],
        outputs: [{ id: '4dfGRr', channel: 0 }],
        code: 'void mainImage(out vec4 c, in vec2 f) { c = vec4(0.2, 0.4, 0.6, 1.0); }',
        name: 'Image',
        description: '',
        type: 'image',
      },
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

/** A short line of the frame-time readout (frame-readout.js): whole in the line's room at any width. */
const SHORT_LINES = ['Paused'];
/**
 * Lines it shows while a shader compiles, starts or plays, the longest of each kind: whole in the
 * line's room where the toolbar is 800 px wide or more (a phone's line is cut short).
 */
const PLAYING_LINES = [
  'Compiling · 4 s',
  'GPU 1915.6 ms · 0.4 fps',
  '1508.5 ms between frames · 0.6 fps',
  'Drawing the first frame · 40%',
  'Not running · did not compile',
  'No frame for 12 s · may never finish',
];

/** The sound widgets, the frame-time line and the toolbar as laid out; which playing lines fit the line's room. */
const soundGeometry = (page, lines) =>
  page.evaluate((lines) => {
    const box = (/** @type {Element | null} */ e) => {
      if (!e || e.getClientRects().length === 0 || getComputedStyle(e).visibility === 'hidden') return null;
      const r = e.getBoundingClientRect();
      return { left: r.left, top: r.top, right: r.right, bottom: r.bottom, width: r.width };
    };
    const mute = document.querySelector('#toolbar button.sound-mute');
    const fps = /** @type {HTMLElement} */ (document.querySelector('#toolbar .fps'));
    const was = fps.textContent;
    // set and measured in one task: the readout cannot redraw it in between
    const whole = lines.map((line) => {
      fps.textContent = line;
      return [line, fps.scrollWidth <= fps.clientWidth];
    });
    fps.textContent = was;
    return {
      mute: box(mute),
      muteName: mute?.getAttribute('aria-label') ?? null,
      muteText: mute?.textContent ?? '',
      muteIcon: Boolean(mute?.querySelector('svg')),
      meter: box(document.querySelector('#toolbar .sound-meter')),
      fps: box(fps),
      whole,
      toolbar: box(document.getElementById('toolbar')),
      viewport: { left: 0, top: 0, right: innerWidth, bottom: innerHeight },
    };
  }, lines);

describe('a shader with a Sound tab: its mute button and level meter crowd nothing out', () => {
  test.each([
    [1280, 800],
    [800, 600],
    [390, 844],
  ])('at %ix%i', async (width, height) => {
    await withPage(
      async ({ page, goto }) => {
        await goto(QUERY);
        const result = await hook(page).setProject(SOUND_PROJECT);
        expect(result.ok, result.error).toBe(true);
        await page.waitForFunction(() => window.shaderEngine.soundState().available, { polling: 50 });
        const where = `${width}x${height}`;
        const s = await soundGeometry(page, [...SHORT_LINES, ...PLAYING_LINES]);
        expect(s.mute && s.meter && s.fps, `${where}: mute, meter and frame-time line shown ${JSON.stringify(s)}`).toBeTruthy();
        const shown = /** @type {Record<string, {left: number, top: number, right: number, bottom: number, width: number}>} */ ({
          mute: s.mute,
          meter: s.meter,
          fps: s.fps,
        });
        for (const [what, b] of Object.entries(shown)) {
          expect(inside(b, s.toolbar), `${where}: the ${what} inside the toolbar ${JSON.stringify(b)}`).toBe(true);
          expect(inside(b, s.viewport), `${where}: the ${what} inside the window ${JSON.stringify(b)}`).toBe(true);
        }
        expect(overlaps(s.mute, s.meter) || overlaps(s.meter, s.fps) || overlaps(s.mute, s.fps), `${where}: apart`).toBe(false);
        // the mute button: a name, and a drawn icon rather than an emoji a browser may lack a font for
        expect(s.muteName, `${where}: the mute button's accessible name`).toBe('Mute sound');
        expect(s.muteIcon, `${where}: the mute button's icon`).toBe(true);
        expect(s.muteText.trim(), `${where}: no text glyph in the mute button`).toBe('');
        // the frame-time line: its short lines whole at any width, its playing lines too from 800 px
        for (const [line, whole] of s.whole)
          if (SHORT_LINES.includes(line) || width >= 800) expect(whole, `${where}: "${line}" whole in ${JSON.stringify(s.fps)}`).toBe(true);

        // muted: the name stays, its state is aria-pressed
        await hook(page).setMuted(true);
        const muted = await page.$eval('#toolbar .sound-mute', (b) => [b.getAttribute('aria-label'), b.getAttribute('aria-pressed')]);
        expect(muted).toEqual(['Mute sound', 'true']);
        await hook(page).setMuted(false);
        // and the toolbar's own rules still hold: two rows, labels on one line, everything inside
        const g = await toolbarGeometry(page);
        const centres = [...new Set(g.controls.map((c) => Math.round((c.top + c.bottom) / 2 / 8)))];
        expect(centres.length, `${where}: rows of controls ${JSON.stringify(g.controls)}`).toBeLessThanOrEqual(2);
        for (const c of g.controls) expect(inside(c, g.toolbar), `${where}: ${c.what} inside the toolbar`).toBe(true);
      },
      { viewport: { width, height, deviceScaleFactor: 1 } },
    );
  });
});
