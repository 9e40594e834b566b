// A multipass shader out of the page and back (issue 13): "Copy for Shadertoy" and "Download
// .glsl" give the editor's tab ("NAME - Buffer A.glsl"), "Export JSON" the whole shader in
// Shadertoy's format, which loads back as the same shader (sameModel); "Copy link" carries a
// multipass shader in #source= and the page opens it identically; an edit of a multipass shader
// survives a reload (kept-source.js).
import { afterAll, describe, expect, test } from 'vitest';
import { disconnect } from '../support/page.js';
import { fromShadertoyJson } from '../../src/shadertoy/multipass-json.js';
import { sameModel } from '../../src/shadertoy/multipass.js';
import { allowClipboard, button, editorText, info } from '../support/page-helpers.js';
import { openEditor, typeInEditor, withControl, withPage, withServedDir } from '../support/page-helpers.js';
import { BUFFER_A, IMAGE, WITH_MEDIA, exportOf } from '../support/page-multipass-helpers.js'; // the shaders
import { dropFile, editorTabs, exportJsonFile, loadNotes, recordSaves, showTab, writeFiles } from '../support/page-multipass-helpers.js'; // the steps
import { hook } from '../support/hook.js';

afterAll(disconnect);

const SIZE = 'size=64x36&time=1';

const named = (page, name) => page.waitForFunction((n) => window.shaderEngine.info().fileName === n, { polling: 50 }, name);
const toast = (page) => page.$eval('#toast', (t) => t.textContent);

describe('a tab out', () => {
  test('"Copy for Shadertoy" and "Download .glsl" give the editor\'s tab, named after it', async () => {
    await withServedDir('mp-copy', async (dir, base) => {
      writeFiles(dir, { 'two.json': exportOf() });
      await withPage(async ({ page, context, goto }) => {
        await allowClipboard(page, context.baseUrl);
        await goto(`?shader=${base}/two.json&${SIZE}`);
        await showTab(page, 'Buffer A');
        const saves = await recordSaves(page);
        await (await button(page, 'Copy for Shadertoy')).click();
        await page.waitForFunction(() => document.getElementById('toast').textContent.startsWith('Copied'), { polling: 20 });
        expect(await toast(page)).toBe("Copied Buffer A of two.json (5 lines): paste it into Shadertoy's Buffer A tab");
        expect(await page.evaluate(() => navigator.clipboard.readText())).toBe(BUFFER_A);
        await (await button(page, 'Download .glsl')).click();
        await showTab(page, 'Image');
        await (await button(page, 'Download .glsl')).click();
        await page.waitForFunction(() => /** @type {any} */ (window).__saves.length === 2, { polling: 20 });
        expect(await saves()).toEqual([
          { name: 'two - Buffer A.glsl', text: BUFFER_A },
          { name: 'two - Image.glsl', text: IMAGE },
        ]);
      });
    });
  });

  test('a single-pass shader is copied and saved whole, as before', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`?shader=examples/pattern.glsl&${SIZE}`);
      const saves = await recordSaves(page);
      await (await button(page, 'Download .glsl')).click();
      await page.waitForFunction(() => /** @type {any} */ (window).__saves.length === 1, { polling: 20 });
      const [saved] = await saves();
      expect(saved.name).toBe('pattern.glsl');
      await openEditor(page);
      expect(saved.text).toBe(await editorText(page));
      // its JSON export is a one-tab shader that loads back as the same text
      const exported = await exportJsonFile(page);
      expect(exported.name).toBe('pattern.json');
      const { model } = fromShadertoyJson(exported.text);
      expect(model.common).toBeNull();
      expect(model.passes.map((p) => [p.name, p.code])).toEqual([['Image', saved.text]]);
    });
  });
});

describe('the whole shader out and back', () => {
  test('"Export JSON" saves Shadertoy\'s format; dropped back on the page it is the same shader', async () => {
    const original = exportOf({ name: 'Round trip', ...WITH_MEDIA });
    await withServedDir('mp-export', async (dir, base) => {
      writeFiles(dir, { 'trip.json': original });
      await withPage(async ({ page, goto }) => {
        await goto(`?shader=${base}/trip.json&${SIZE}`);
        const first = await exportJsonFile(page);
        expect(first.name).toBe('trip.json');
        // the same shader as the file, every tab, channel, sampler and unsupported pass
        expect(sameModel(fromShadertoyJson(first.text).model, fromShadertoyJson(original).model)).toBe(true);
        expect(JSON.parse(first.text).Shader.info).toEqual(original.Shader.info);

        // back through the page: a single-pass shader first, then the export dropped on the page
        await hook(page).setSource('void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }');
        expect(await editorTabs(page)).toEqual({ names: [], selected: null });
        await dropFile(page, 'trip.json', first.text);
        await named(page, 'Round trip'); // an export goes by its shader's own name
        await hook(page).ready();
        expect(await editorTabs(page)).toEqual({ names: ['Common', 'Buffer A', 'Image', 'Sound'], selected: 'Image' });
        expect((await loadNotes(page))?.lines).toHaveLength(1); // the texture, again (the Sound tab plays)
        const second = await exportJsonFile(page);
        expect(sameModel(fromShadertoyJson(second.text).model, fromShadertoyJson(first.text).model)).toBe(true);
        expect(second.text).toBe(first.text);
      });
    });
  });

  test('"Copy link" carries an edited multipass shader; the link opens it identically', async () => {
    let link = '';
    let exported = '';
    await withServedDir('mp-link', async (dir, base) => {
      writeFiles(dir, { 'two.json': exportOf() });
      await withPage(async ({ page, goto }) => {
        await goto(`?shader=${base}/two.json&${SIZE}`);
        await showTab(page, 'Buffer A');
        await typeInEditor(page, '\n// shared edit', 'end');
        await withControl(page, 'Enter');
        await named(page, 'two.json (edited)');
        link = await hook(page).shareUrl();
        exported = (await exportJsonFile(page)).text;
      });
    });
    const url = new URL(link);
    expect(url.hash).toMatch(/^#source=[A-Za-z0-9_-]+&name=[^&]+$/);
    expect(url.searchParams.has('shader')).toBe(false);
    await withPage(async ({ page, goto }) => {
      await goto(url.search + url.hash);
      expect((await info(page)).fileName).toBe('two.json (edited)');
      expect((await info(page)).origin).toBe('editor');
      expect(await editorTabs(page)).toEqual({ names: ['Common', 'Buffer A', 'Image'], selected: 'Image' });
      await showTab(page, 'Buffer A');
      expect(await editorText(page)).toBe(`${BUFFER_A}\n// shared edit`);
      const again = (await exportJsonFile(page)).text;
      expect(sameModel(fromShadertoyJson(again).model, fromShadertoyJson(exported).model)).toBe(true);
      expect(again).toBe(exported);
    });
  });

  test('an edit of a multipass shader survives a reload, every tab; "Discard edits" goes back to the file', async () => {
    await withServedDir('mp-kept', async (dir, base) => {
      writeFiles(dir, { 'two.json': exportOf() });
      await withPage(async ({ page, goto }) => {
        await goto(`?shader=${base}/two.json&${SIZE}`);
        await showTab(page, 'Buffer A');
        await typeInEditor(page, '\n// kept A', 'end'); // not compiled: kept all the same
        await showTab(page, 'Common');
        await typeInEditor(page, '\n// kept common', 'end');
        await page.reload({ waitUntil: 'load' });
        await page.waitForFunction(() => window.shaderEngine, { polling: 50 });
        await hook(page).ready();
        expect(await page.$eval('#restored-note', (n) => n.textContent)).toContain('Restored two.json (edited)');
        expect((await info(page)).fileName).toBe('two.json (edited)');
        expect(await editorTabs(page)).toEqual({ names: ['Common', 'Buffer A', 'Image'], selected: 'Image' });
        await showTab(page, 'Buffer A');
        expect(await editorText(page)).toBe(`${BUFFER_A}\n// kept A`);
        await showTab(page, 'Common');
        expect(await editorText(page)).toMatch(/\/\/ kept common$/);
        // the channels came back too (the edit is of the text only)
        const { model } = fromShadertoyJson((await exportJsonFile(page)).text);
        expect(model.passes.find((p) => p.name === 'Image')?.channels[0]).toMatchObject({ kind: 'buffer', buffer: 'A' });

        await (await button(page, 'Discard edits')).click();
        await named(page, 'two.json');
        await showTab(page, 'Buffer A');
        expect(await editorText(page)).toBe(BUFFER_A);
        await page.reload({ waitUntil: 'load' });
        await page.waitForFunction(() => window.shaderEngine, { polling: 50 });
        await hook(page).ready();
        expect(await page.$('#restored-note')).toBeNull();
      });
    });
  });
});
