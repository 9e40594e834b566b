// A multipass shader in the page's editor (issue 13): one tab per pass, each with its own text and
// undo history, Ctrl+Enter running every tab, compile errors in the tab they are in (and the
// error box's link that opens that tab at that line); loading Shadertoy's JSON export by
// ?shader=, by dropping the file and by pasting it, with a note (never a failure) for what the
// page cannot have, and a clear message for a file that is not a shader.
import { afterAll, describe, expect, test } from 'vitest';
import { disconnect } from '../support/page.js';
import { fromShadertoyJson } from '../../src/shadertoy/multipass-json.js';
import { allowClipboard, button, EDITOR, editorText, errorMarkerLines, info, openEditor } from '../support/page-helpers.js';
import {
  overlayText,
  pasteIntoEditor,
  typeInEditor,
  waitForCursorLine,
  withControl,
  withPage,
  withServedDir,
} from '../support/page-helpers.js';
import { BUFFER_A, COMMON, IMAGE, WITH_MEDIA, exportOf } from '../support/page-multipass-helpers.js'; // the shaders
import { dropFile, editorTabs, exportJsonFile, loadNotes, showTab, writeFiles } from '../support/page-multipass-helpers.js'; // the steps
import { hook } from '../support/hook.js';

afterAll(disconnect);

const SIZE = 'size=64x36&time=1';
const PATTERN = `?shader=examples/pattern.glsl&${SIZE}`;

const named = (page, name) => page.waitForFunction((n) => window.shaderEngine.info().fileName === n, { polling: 50 }, name);

describe('tabs', () => {
  test('?shader=….json shows one tab per pass; each tab keeps its text and its undo; Ctrl+Enter runs them all', async () => {
    await withServedDir('mp-tabs', async (dir, base) => {
      writeFiles(dir, { 'two.json': exportOf() });
      await withPage(async ({ page, goto }) => {
        await goto(`?shader=${base}/two.json&${SIZE}`);
        expect((await info(page)).fileName).toBe('two.json');
        expect(await editorTabs(page)).toEqual({ names: ['Common', 'Buffer A', 'Image'], selected: 'Image' });
        expect(await loadNotes(page)).toBeNull(); // nothing it cannot have
        await openEditor(page);
        expect(await editorText(page)).toBe(IMAGE);
        await showTab(page, 'Common');
        expect(await editorText(page)).toBe(COMMON);
        await showTab(page, 'Buffer A');
        expect(await editorText(page)).toBe(BUFFER_A);

        // edits in two tabs, then Ctrl+Enter runs the whole shader
        await typeInEditor(page, '\n// edit A', 'end');
        await showTab(page, 'Image');
        await typeInEditor(page, '\n// edit I', 'end');
        await withControl(page, 'Enter');
        await named(page, 'two.json (edited)');
        await hook(page).ready();
        const { model } = fromShadertoyJson((await exportJsonFile(page)).text);
        expect(model.common).toBe(COMMON);
        expect(model.passes.find((p) => p.name === 'Buffer A')?.code).toBe(`${BUFFER_A}\n// edit A`);
        expect(model.passes.find((p) => p.name === 'Image')?.code).toBe(`${IMAGE}\n// edit I`);
        expect(model.passes.find((p) => p.name === 'Buffer A')?.channels[0]).toMatchObject({ kind: 'buffer', buffer: 'A' });

        // undo is per tab: undoing the Image tab leaves Buffer A's edit, and the other way round
        await page.focus(EDITOR);
        for (let i = 0; i < 10 && (await editorText(page)) !== IMAGE; i++) await withControl(page, 'KeyZ');
        expect(await editorText(page)).toBe(IMAGE);
        await showTab(page, 'Buffer A');
        expect(await editorText(page)).toBe(`${BUFFER_A}\n// edit A`);
        for (let i = 0; i < 10 && (await editorText(page)) !== BUFFER_A; i++) await withControl(page, 'KeyZ');
        expect(await editorText(page)).toBe(BUFFER_A);
        await showTab(page, 'Image');
        expect(await editorText(page)).toBe(IMAGE);

        // the arrow keys move along the tab list
        await page.focus('.editor-tabs [aria-selected="true"]');
        await page.keyboard.press('ArrowLeft');
        expect((await editorTabs(page)).selected).toBe('Buffer A');
        expect(await editorText(page)).toBe(BUFFER_A);
      });
    });
  });

  test('a single-pass shader shows no tab bar, as before', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(PATTERN);
      await openEditor(page);
      expect(await editorTabs(page)).toEqual({ names: [], selected: null });
    });
  });

  test('compile errors name the pass and its line; a click opens that tab at that line', async () => {
    const broken = BUFFER_A.replace('last.r + 1.0', 'last.r + notDeclaredHere');
    await withServedDir('mp-errors', async (dir, base) => {
      writeFiles(dir, { 'broken.json': exportOf({ bufferA: broken }) });
      await withPage(async ({ page, goto }) => {
        await goto(`?shader=${base}/broken.json&${SIZE}`, { expectReady: false });
        await page.waitForFunction(() => document.querySelectorAll('#overlay .error-line').length >= 1, { polling: 50 });
        const links = await page.$$eval('#overlay .error-line', (els) => els.map((e) => e.textContent));
        const at = links.findIndex((l) => l.startsWith('Buffer A:3: error:') && l.includes('notDeclaredHere'));
        expect(at, links.join('\n')).toBeGreaterThanOrEqual(0);
        expect(await overlayText(page)).toMatch(/^broken\.json did not compile/);

        // the editor is closed: the link opens it on Buffer A, at line 3, marked
        await (await page.$$('#overlay .error-line'))[at].click();
        await page.waitForSelector(EDITOR, { visible: true });
        expect((await editorTabs(page)).selected).toBe('Buffer A');
        expect(await waitForCursorLine(page, 3)).toBe(3);
        expect(await errorMarkerLines(page)).toContain(3);
        expect(await page.$eval('.editor-tabs [data-tab="Buffer A"]', (t) => t.classList.contains('has-errors'))).toBe(true);
        expect(await page.$eval('.editor-tabs [data-tab="Image"]', (t) => t.classList.contains('has-errors'))).toBe(false);
        await showTab(page, 'Image');
        expect(await page.$$('.cm-lint-marker-error')).toHaveLength(0);

        // fixed and run: the marks go
        await showTab(page, 'Buffer A');
        await pasteIntoEditor(page, BUFFER_A);
        await page.waitForFunction(() => document.getElementById('overlay').hidden, { polling: 50 });
        await named(page, 'broken.json (edited)'); // a paste over one tab is an edit of the shader, not "untitled"
        expect(await page.$eval('#toolbar .name', (e) => e.textContent)).toBe('broken.json (edited)');
        expect(await page.$$('.editor-tabs .has-errors')).toHaveLength(0);
        expect(await page.$$('.cm-lint-marker-error')).toHaveLength(0);

        // an error in the Common tab is the Common tab's, at its own line
        await showTab(page, 'Common');
        await pasteIntoEditor(page, `${COMMON}float brokenToo() { return undeclaredInCommon; }\n`);
        await page.waitForFunction(() => document.querySelectorAll('#overlay .error-line').length >= 1, { polling: 50 });
        const common = await page.$$eval('#overlay .error-line', (els) => els.map((e) => e.textContent));
        expect(
          common.filter((l) => l.startsWith('Common:2:')),
          common.join('\n'),
        ).toHaveLength(1); // once, not once per pass
        expect(
          common.some((l) => l.startsWith('Common:2: error:') && l.includes('undeclaredInCommon')),
          common.join('\n'),
        ).toBe(true);
        expect(await page.$eval('.editor-tabs [data-tab="Common"]', (t) => t.classList.contains('has-errors'))).toBe(true);
        expect(await errorMarkerLines(page)).toContain(2);
      });
    });
  });
});

describe('loading Shadertoy JSON', () => {
  test('media and passes the page cannot have are a note that blocks nothing, never a failure', async () => {
    await withServedDir('mp-media', async (dir, base) => {
      writeFiles(dir, { 'media.json': exportOf({ name: 'With media', ...WITH_MEDIA }) });
      await withPage(async ({ page, goto }) => {
        await goto(`?shader=${base}/media.json&${SIZE}`);
        const notes = await loadNotes(page);
        expect(notes?.kind).toBe('note');
        expect(notes?.title).toContain('media.json');
        expect(notes?.lines.some((l) => l.startsWith('Image, iChannel1:') && l.includes('texture') && l.includes('black'))).toBe(true);
        expect(notes?.lines.some((l) => l.startsWith('Sound'))).toBe(false); // the Sound tab plays (sound.js)
        expect(await overlayText(page)).toBeNull(); // nothing over the picture
        expect(await editorTabs(page)).toEqual({ names: ['Common', 'Buffer A', 'Image', 'Sound'], selected: 'Image' });
        // an edit of the same shader does not bring a closed note back
        await page.click('#load-notes button');
        await typeInEditor(page, '\n// edited', 'end');
        await withControl(page, 'Enter');
        await named(page, 'media.json (edited)');
        expect(await loadNotes(page)).toBeNull();
      });
    });
  });

  test('a ?shader= JSON file that is not a shader is refused naming the problem; the built-in one runs', async () => {
    await withServedDir('mp-bad', async (dir, base) => {
      writeFiles(dir, { 'notashader.json': { Shader: { info: { name: 'x' } } }, 'cut.json': '{"Shader": {"renderpass": [' });
      await withPage(async ({ page, goto }) => {
        await goto(`?shader=${base}/notashader.json&${SIZE}`);
        await page.waitForFunction(() => !document.getElementById('overlay').hidden, { polling: 50 });
        const text = await overlayText(page);
        expect(text).toContain(`Could not load ${base}/notashader.json`);
        expect(text).toContain('not a Shadertoy shader: no "renderpass" list');
        expect((await info(page)).origin).toBe('builtin');
        await goto(`?shader=${base}/cut.json&${SIZE}`);
        await page.waitForFunction(() => !document.getElementById('overlay').hidden, { polling: 50 });
        expect(await overlayText(page)).toContain('not JSON');
      });
    });
  });

  test('dropping a .json file loads it, by the name a paste of it gets; a broken one is a message naming the file', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(PATTERN);
      // an export that names no shader goes by its file's name
      await dropFile(page, 'nameless.json', JSON.stringify(exportOf({ name: '' })), 'application/json');
      await named(page, 'nameless.json');
      // one that does goes by the shader's own name, as the same export pasted does (below)
      await dropFile(page, 'dropped.json', JSON.stringify(exportOf({ name: 'Pasted one' })), 'application/json');
      await named(page, 'Pasted one');
      expect(await editorTabs(page)).toEqual({ names: ['Common', 'Buffer A', 'Image'], selected: 'Image' });
      expect((await info(page)).origin).toBe('file');

      await dropFile(page, 'broken.json', '{"Shader": {"renderpass": [{"type": "image"}]}}');
      await page.waitForFunction(() => document.getElementById('load-notes')?.className === 'error', { polling: 50 });
      const notes = await loadNotes(page);
      expect(notes?.title).toBe('Could not load broken.json');
      expect(notes?.lines.join('\n')).toMatch(/has no code/);
      expect((await info(page)).fileName).toBe('Pasted one'); // the shader running stays
    });
  });

  test('pasting a whole Shadertoy export into the editor loads that shader, by its own name', async () => {
    await withPage(async ({ page, context, goto }) => {
      await allowClipboard(page, context.baseUrl);
      await goto(PATTERN);
      await pasteIntoEditor(page, JSON.stringify(exportOf({ name: 'Pasted one' }), null, 2));
      await named(page, 'Pasted one');
      expect(await editorTabs(page)).toEqual({ names: ['Common', 'Buffer A', 'Image'], selected: 'Image' });
      expect(await editorText(page)).toBe(IMAGE);
      await hook(page).ready();

      await pasteIntoEditor(page, '{"renderpass": "no"}');
      await page.waitForFunction(() => document.getElementById('load-notes')?.className === 'error', { polling: 50 });
      expect((await loadNotes(page))?.lines.join('\n')).toMatch(/not a Shadertoy shader/);
      expect((await info(page)).fileName).toBe('Pasted one');
      expect(await button(page, 'Export JSON')).toBeTruthy();
    });
  });
});
