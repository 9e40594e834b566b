// Shared by the page's multipass tests (tests/page-multipass-*.test.js): a small multipass shader
// written here as Shadertoy exports it (Common, Buffer A feeding itself, Image reading A), ways to
// serve and drop it, and reading back what the page's editor and its "Export JSON" button hold.

import fs from 'node:fs';
import path from 'node:path';
import { EDITOR, button, openEditor } from './page-helpers.js';

export const COMMON = 'float halfOf(float x) { return 0.5 * x; }\n';
export const BUFFER_A = [
  'void mainImage(out vec4 fragColor, in vec2 fragCoord) {',
  '    vec4 last = texelFetch(iChannel0, ivec2(fragCoord), 0);',
  '    fragColor = vec4(last.r + 1.0, halfOf(1.0), 0.0, 1.0);',
  '}',
  '',
].join('\n');
export const IMAGE = [
  'void mainImage(out vec4 fragColor, in vec2 fragCoord) {',
  '    vec4 a = texture(iChannel0, fragCoord / iResolution.xy);',
  '    fragColor = vec4(fract(a.r / 256.0), a.g, halfOf(0.4), 1.0);',
  '}',
  '',
].join('\n');

const sampler = (filter = 'linear', wrap = 'clamp', vflip = 'true') => ({ filter, wrap, vflip, srgb: 'false', internal: 'byte' });
const bufferInput = (channel, filter) => ({
  id: '4dXGR8',
  filepath: '/media/previz/buffer00.png',
  previewfilepath: '/media/previz/buffer00.png',
  type: 'buffer',
  channel,
  sampler: sampler(filter),
  published: 1,
});

/**
 * The test shader as the site exports it today (string ids, `type`, `filepath`).
 * @param {{name?: string, common?: string, bufferA?: string, image?: string, extraPasses?: object[], imageInputs?: object[]}} [parts]
 */
export function exportOf({
  name = 'Two tabs',
  common = COMMON,
  bufferA = BUFFER_A,
  image = IMAGE,
  extraPasses = [],
  imageInputs = [],
} = {}) {
  return {
    Shader: {
      ver: '0.1',
      info: { id: 'tst001', name, username: 'tests', description: 'written for the page tests', tags: ['test'] },
      renderpass: [
        {
          inputs: [bufferInput(0, 'linear'), ...imageInputs],
          outputs: [{ id: '4dfGRr', channel: 0 }],
          code: image,
          name: 'Image',
          description: '',
          type: 'image',
        },
        {
          inputs: [bufferInput(0, 'nearest')],
          outputs: [{ id: '4dXGR8', channel: 0 }],
          code: bufferA,
          name: 'Buffer A',
          description: '',
          type: 'buffer',
        },
        { inputs: [], outputs: [], code: common, name: 'Common', description: '', type: 'common' },
        ...extraPasses,
      ],
    },
  };
}

/** A texture of the site's (which the page cannot have) on the Image pass's iChannel1, and a sound pass. */
export const WITH_MEDIA = {
  imageInputs: [
    {
      id: '4sf3Rn',
      filepath: '/media/a/0a40562379b63dfb89227e6d172f39fdce9022cba76623f1054a2c83d6c0ba5d.png',
      previewfilepath: '/media/ap/0a40562379b63dfb89227e6d172f39fdce9022cba76623f1054a2c83d6c0ba5d.png',
      type: 'texture',
      channel: 1,
      sampler: sampler('mipmap', 'repeat', 'false'),
      published: 1,
    },
  ],
  extraPasses: [
    {
      inputs: [],
      outputs: [{ id: '4dfGRn', channel: 0 }],
      code: 'vec2 mainSound(int samp, float time) { return vec2(0.0); }\n',
      name: 'Sound',
      description: '',
      type: 'sound',
    },
  ],
};

/** Writes files into a served folder: {name: text or object (as JSON)}. */
export function writeFiles(dir, files) {
  for (const [name, content] of Object.entries(files)) {
    fs.writeFileSync(path.join(dir, name), typeof content === 'string' ? content : JSON.stringify(content, null, 2));
  }
}

/** Drops a file with this text on the page, as a person drags one from the desktop. */
export async function dropFile(page, name, text, type = '') {
  await page.evaluate(
    (n, t, ty) => {
      const data = new DataTransfer();
      data.items.add(new File([t], n, { type: ty }));
      document.dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true, cancelable: true }));
    },
    name,
    text,
    type,
  );
}

/** The editor's tab names, and the selected one ([] and null when the tab bar is hidden). */
export async function editorTabs(page) {
  return page.evaluate(() => {
    const bar = /** @type {HTMLElement | null} */ (document.querySelector('.editor-tabs'));
    if (!bar || bar.hidden) return { names: [], selected: null };
    const tabs = [...bar.querySelectorAll('[role="tab"]')];
    return {
      names: tabs.map((t) => t.textContent),
      selected: tabs.find((t) => t.getAttribute('aria-selected') === 'true')?.textContent ?? null,
    };
  });
}

/** Opens the editor and shows a tab by clicking it. */
export async function showTab(page, name) {
  await openEditor(page);
  await page.click(`.editor-tabs [role="tab"][data-tab="${name}"]`);
  await page.waitForFunction((n) => document.getElementById('editor')?.dataset.tab === n, { polling: 20 }, name);
  await page.focus(EDITOR);
}

/**
 * Keeps what the page saves (the download links it clicks): their names and their text.
 * @returns {Promise<() => Promise<Array<{name: string, text: string}>>>}
 */
export async function recordSaves(page) {
  await page.evaluate(() => {
    const saved = [];
    /** @type {any} */ (window).__saves = saved;
    const click = HTMLAnchorElement.prototype.click;
    HTMLAnchorElement.prototype.click = function () {
      if (this.download) saved.push(fetch(this.href).then(async (r) => ({ name: this.download, text: await r.text() })));
      return click.call(this);
    };
  });
  return () => page.evaluate(() => Promise.all(/** @type {any} */ (window).__saves));
}

/** Clicks "Export JSON" and returns the file it saved: {name, text}. */
export async function exportJsonFile(page) {
  const saves = await recordSaves(page);
  await (await button(page, 'Export JSON')).click();
  await page.waitForFunction(() => /** @type {any} */ (window).__saves.length === 1, { polling: 20 });
  return (await saves())[0];
}

/** The page's notes on a loaded shader (load-notes.js): title, lines and kind; null when none shows. */
export async function loadNotes(page) {
  return page.evaluate(() => {
    const note = document.getElementById('load-notes');
    if (!note) return null;
    return {
      title: note.querySelector('strong')?.textContent ?? '',
      lines: [...note.querySelectorAll('li')].map((li) => li.textContent),
      kind: note.className,
    };
  });
}
