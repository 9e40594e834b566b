// The page's editor (CodeMirror 6, src/studio/ui/editor.js) in the real browser: highlighting, bracket
// matching, search, undo, Tab that indents (and Esc then Tab that leaves), compile errors at
// their lines with a gutter marker and a link from the error box; edits kept across a reload
// (src/player/io/kept-source.js); and the name an edited or pasted shader goes by.
import { afterAll, describe, expect, test } from 'vitest';
import { disconnect } from '../support/page.js';
import {
  allowClipboard,
  button,
  EDITOR,
  editorText,
  errorMarkerLines,
  exampleSource,
  info,
  openEditor,
  overlayText,
  pasteIntoEditor,
  solid,
  typeInEditor,
  waitForCursorLine,
  withControl,
  withPage,
} from '../support/page-helpers.js';
import { hook } from '../support/hook.js';

afterAll(disconnect);

const PATTERN = '?shader=examples/pattern.glsl&size=160x90&time=2';

/** Records the file names the page saves (the download links it clicks). */
async function recordDownloads(page) {
  await page.evaluate(() => {
    const saved = [];
    /** @type {any} */ (window).__saved = saved;
    const click = HTMLAnchorElement.prototype.click;
    HTMLAnchorElement.prototype.click = function () {
      if (this.download) saved.push(this.download);
      return click.call(this);
    };
  });
  return () => page.evaluate(() => /** @type {any} */ (window).__saved.slice());
}

/** Whether the editor holds the focus. */
const editorFocused = (page) => page.$eval(EDITOR, (e) => e.contains(document.activeElement));

describe('the editor', () => {
  test('highlights GLSL, matches brackets, searches, undoes; Tab indents, Esc then Tab leaves', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(PATTERN);
      await openEditor(page);
      expect(await editorText(page)).toBe(exampleSource('pattern'));

      // highlighting: a type keyword and a number are in differently styled spans
      const styled = await page.$$eval('.cm-line span', (spans) => spans.map((s) => [s.textContent, s.className]));
      const classOf = (text) => styled.find(([t]) => t === text)?.[1];
      expect(classOf('void')).toBeTruthy();
      expect(classOf('vec2')).toBeTruthy();
      expect(classOf('void')).not.toBe(classOf('mainImage'));

      // Tab at the start of a new line indents it; the focus stays in the editor
      const before = await editorText(page);
      await typeInEditor(page, '\nint unused() { return 1; }', 'end');
      await page.keyboard.press('Home');
      await page.keyboard.press('Tab');
      expect(await editorFocused(page)).toBe(true);
      expect(await editorText(page)).toBe(`${before}\n    int unused() { return 1; }`);

      // bracket matching: the cursor after "{" marks both braces
      await page.keyboard.press('End');
      await page.keyboard.press('ArrowLeft');
      await page.waitForFunction(() => document.querySelectorAll('.cm-matchingBracket').length === 2, { polling: 20 });

      // undo takes the typing back; redo puts it again
      await withControl(page, 'KeyZ');
      await page.waitForFunction(() => window.shaderEngine.editorSource().includes('\nint unused'), { polling: 20 });
      for (let i = 0; i < 10 && (await editorText(page)) !== before; i++) await withControl(page, 'KeyZ');
      expect(await editorText(page)).toBe(before);

      // search: Ctrl+F opens the search field; the word is found
      await withControl(page, 'KeyF');
      await page.waitForSelector('.cm-search input[name="search"]', { visible: true });
      await page.keyboard.type('hash12');
      await page.keyboard.press('Enter');
      await page.waitForFunction(() => document.querySelectorAll('.cm-searchMatch').length >= 2, { polling: 20 });
      await page.keyboard.press('Escape'); // closes the search, back in the text
      await page.waitForFunction(() => !document.querySelector('.cm-search'), { polling: 20 });
      expect(await editorFocused(page)).toBe(true);

      // Esc, then Tab moves the focus on (out of the editor), as CodeMirror documents (with a
      // selection, the first Esc collapses it)
      await page.keyboard.press('ArrowRight');
      await page.keyboard.press('Escape');
      await page.keyboard.press('Tab');
      expect(await editorFocused(page)).toBe(false);
      expect(await editorText(page)).toBe(before);
    });
  });

  test('compile errors are diagnostics at their lines; clicking one in the error box goes there', async () => {
    await withPage(async ({ page, context, goto }) => {
      await allowClipboard(page, context.baseUrl);
      await goto('?shader=examples/raymarch.glsl&size=160x90&time=2');
      const lines = exampleSource('raymarch').split('\n');
      const index = lines.findIndex((l) => l.includes('float sphere = '));
      lines[index] = lines[index].replace('float sphere = ', 'float sphere = notDeclaredAnywhere + ');
      const second = lines.findIndex((l) => l.includes('weight *= 0.7;'));
      lines[second] = lines[second].replace('0.7', 'alsoUndeclared');
      const [first, last] = [index + 1, second + 1]; // the user's line numbers
      await pasteIntoEditor(page, lines.join('\n'));
      await page.waitForFunction(() => document.querySelectorAll('#overlay .error-line').length >= 2, { polling: 50 });

      // each message at its line, underlined, with the gutter's marker
      const underlined = () => page.$$eval('.cm-lintRange-error', (els) => els.map((e) => e.textContent).join('\n'));
      const links = await page.$$eval('#overlay .error-line', (els) => els.map((e) => e.textContent));
      expect(links.some((l) => l.startsWith(`untitled:${first}: error:`) && l.includes('notDeclaredAnywhere'))).toBe(true);
      expect(links.some((l) => l.startsWith(`untitled:${last}: error:`) && l.includes('alsoUndeclared'))).toBe(true);

      // with the editor closed, clicking a message opens it at that line
      await (await button(page, 'Close editor')).click();
      const toLast = await page.$$('#overlay .error-line');
      await toLast[links.findIndex((l) => l.startsWith(`untitled:${last}:`))].click();
      await page.waitForSelector(EDITOR, { visible: true });
      expect(await editorFocused(page)).toBe(true);
      expect(await waitForCursorLine(page, last)).toBe(last);
      expect(await errorMarkerLines(page)).toContain(last);
      expect(await underlined()).toContain('alsoUndeclared');
      const toFirst = await page.$$('#overlay .error-line');
      await toFirst[links.findIndex((l) => l.startsWith(`untitled:${first}:`))].click();
      expect(await waitForCursorLine(page, first)).toBe(first);
      expect(await errorMarkerLines(page)).toContain(first);
      expect(await underlined()).toContain('notDeclaredAnywhere');

      // a good shader clears them
      await pasteIntoEditor(page, solid(10, 200, 30));
      await page.waitForFunction(() => document.getElementById('overlay').hidden, { polling: 50 });
      expect(await page.$$('.cm-lint-marker-error')).toHaveLength(0);
    });
  });
});

describe('defect 4: the editor was a bare text box', () => {
  test('Tab indents in the editor, and edits survive a reload (with a note and a way back to the file)', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(PATTERN);
      const file = exampleSource('pattern');
      await typeInEditor(page, '\n// my edit', 'end');
      await page.keyboard.press('Home');
      await page.keyboard.press('Tab'); // indents instead of leaving the editor
      const edited = `${file}\n    // my edit`;
      expect(await editorText(page)).toBe(edited);

      // not compiled, and still kept
      await page.reload({ waitUntil: 'load' });
      await page.waitForFunction(() => window.shaderEngine, { polling: 50 });
      await hook(page).ready();
      expect(await editorText(page)).toBe(edited);
      expect(await info(page)).toMatchObject({ fileName: 'pattern.glsl (edited)', origin: 'editor', shaderUrl: 'examples/pattern.glsl' });
      const note = await page.waitForSelector('#restored-note', { visible: true });
      expect(await note.evaluate((n) => n.textContent)).toContain('pattern.glsl (edited)');

      // discard: back to the file, and nothing restored after the next reload
      await (await button(page, 'Discard edits')).click();
      await page.waitForFunction(() => window.shaderEngine.info().fileName === 'pattern.glsl', { polling: 50 });
      expect(await editorText(page)).toBe(file);
      expect(await page.$('#restored-note')).toBeNull();
      await page.reload({ waitUntil: 'load' });
      await page.waitForFunction(() => window.shaderEngine, { polling: 50 });
      await hook(page).ready();
      expect(await editorText(page)).toBe(file);
      expect(await page.$('#restored-note')).toBeNull();
      expect((await info(page)).fileName).toBe('pattern.glsl');
    });
  });
});

describe('defect 1: an edited or pasted shader kept the previous file name', () => {
  test('a pasted shader is "untitled", an edited one "NAME (edited)", everywhere the name shows', async () => {
    await withPage(async ({ page, context, goto }) => {
      await allowClipboard(page, context.baseUrl);
      await goto('?size=160x90&time=1'); // the built-in shaders/raytrace.glsl
      const saved = await recordDownloads(page);
      const shows = async (name) => {
        await page.waitForFunction((n) => window.shaderEngine.info().fileName === n, { polling: 50 }, name);
        expect(await page.$eval('#toolbar .name', (e) => e.textContent)).toBe(name);
        expect(await page.title()).toContain(name);
        expect(await page.$eval('.editor-title', (e) => e.textContent)).toBe(name);
      };

      // a paste over everything: "untitled", also in the error box of a broken one
      await pasteIntoEditor(page, solid(10, 20, 30).replace('fragColor =', 'fragColor = oops +'));
      await shows('untitled');
      await page.waitForFunction(() => !document.getElementById('overlay').hidden, { polling: 50 });
      const alert = await overlayText(page);
      expect(alert).toMatch(/^untitled did not compile/);
      expect(alert).toContain('untitled:2:');
      expect(alert).not.toContain('raytrace');
      await pasteIntoEditor(page, solid(10, 20, 30));
      await page.waitForFunction(() => document.getElementById('overlay').hidden, { polling: 50 });
      // the new shader's first frame is on the canvas (compiled is not yet drawn): the Screenshot is of it
      await hook(page).readPixels();
      await (await button(page, 'Download .glsl')).click();
      await (await button(page, 'Screenshot')).click();
      await page.waitForFunction(() => /** @type {any} */ (window).__saved.length === 2, { polling: 50 });
      const [glsl, png] = await saved();
      expect(glsl).toBe('untitled.glsl');
      // a paste over everything is a new shader: it starts at iTime 0 (Shadertoy's contract)
      expect(png).toMatch(/^untitled-t0\.00-160x90\.png$/);

      // an edit of the file: the file's name, marked as edited
      await page.reload({ waitUntil: 'load' });
      await page.waitForFunction(() => window.shaderEngine, { polling: 50 });
      await hook(page).ready();
      await (await button(page, 'Discard edits')).click(); // the paste was kept: back to the file
      await page.waitForFunction(() => window.shaderEngine.info().fileName === 'shaders/raytrace.glsl', { polling: 50 });
      const saved2 = await recordDownloads(page);
      await typeInEditor(page, '\n// edited', 'end');
      await withControl(page, 'Enter');
      await shows('raytrace.glsl (edited)');
      await (await button(page, 'Download .glsl')).click();
      await page.waitForFunction(() => /** @type {any} */ (window).__saved.length === 1, { polling: 50 });
      expect(await saved2()).toEqual(['raytrace-edited.glsl']);
    });
  });
});
