// Getting shaders in and pictures out, through the page's own widgets in the real browser: the
// editor (a pasted shader, a broken one), a dropped .glsl file or image, channel images, the
// clipboard ("Copy for Shadertoy", "Copy link") and downloads (".glsl", "Screenshot").
// (Failures and the dev server's reload: page-lifecycle.test.js.)
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { afterAll, describe, expect, test } from 'vitest';
import { composeImageShader } from '../../src/shadertoy/header.js';
import { makeImage, readPng, sameImage, writePng } from '../support/images.js';
import { disconnect } from '../support/page.js';
import { renderRawShader } from '../support/raw-webgl/raw-webgl.js';
import {
  allowClipboard,
  button,
  EDITOR,
  editorText,
  errorMarkerLines,
  EXAMPLES_DIR,
  exampleSource,
  info,
  overlayText,
  pasteIntoEditor,
  pixel,
  readPixels,
  solid,
  typeInEditor,
  withPage,
  withServedDir,
} from '../support/page-helpers.js';
import { captureDownloads } from '../support/downloads.js';
import { hook } from '../support/hook.js';

afterAll(disconnect);

const SIZE = 'size=160x90';
const PATTERN = `?shader=examples/pattern.glsl&${SIZE}&time=2`;

function allPixels(image, rgb) {
  for (let i = 0; i < image.width * image.height; i++) {
    const p = [image.data[i * 4], image.data[i * 4 + 1], image.data[i * 4 + 2]];
    if (p.some((v, c) => Math.abs(v - rgb[c]) > 1)) return false;
  }
  return true;
}

/** Drops files on the page as a person does from a file manager (CDP drag events). */
async function dropFiles(page, files) {
  const session = await page.createCDPSession();
  const data = { items: [], files, dragOperationsMask: 1 };
  for (const type of ['dragEnter', 'dragOver', 'drop']) await session.send('Input.dispatchDragEvent', { type, x: 300, y: 200, data });
  await session.detach();
}

/** A PNG file of one colour. */
function writeSolidPng(file, width, height, rgb) {
  writePng(
    file,
    makeImage(width, height, () => rgb),
  );
}

// ------------------------------------------------------------------------------------------------

describe('the editor', () => {
  // A broken line in the user's file must be reported with the user's line number, also when the
  // page puts a host control block (raymarch.glsl) between Shadertoy's header and the file.
  const BROKEN = [
    { name: 'pattern', find: 'float turn = ', error: 'undeclared' },
    { name: 'raymarch', find: 'float sphere = ', error: 'undeclared' },
  ];
  test.each(BROKEN.map((b) => [b.name, b]))(
    'pasting a broken %s.glsl names the right line and keeps the last image',
    async (name, broken) => {
      await withPage(async ({ page, context, goto }) => {
        await allowClipboard(page, context.baseUrl);
        await goto(`?shader=examples/${name}.glsl&${SIZE}&time=2`);
        const before = await readPixels(page);
        const lines = exampleSource(name).split('\n');
        const index = lines.findIndex((l) => l.includes(broken.find));
        lines[index] = lines[index].replace(broken.find, `${broken.find}notDeclaredAnywhere + `);
        const line = index + 1;

        await (await button(page, 'Edit shader')).click();
        await page.waitForSelector(EDITOR, { visible: true });
        expect(await editorText(page)).toBe(exampleSource(name));
        await pasteIntoEditor(page, lines.join('\n'));

        await page.waitForFunction(() => !(/** @type {HTMLElement} */ (document.querySelector('[role="alert"]')).hidden), { polling: 50 });
        const alert = await overlayText(page);
        expect(alert).toContain(`untitled:${line}:`); // a paste over everything is a shader of its own
        expect(alert).toContain('notDeclaredAnywhere');
        expect(alert).toContain(broken.error);
        expect(alert).toContain('still showing the last version that compiled');
        // the paste left it at the end; unwrapped, line `line` is on the first screen
        await (await button(page, 'Wrap')).click();
        await page.$eval('.cm-scroller', (s) => s.scrollTo(0, 0));
        await expect.poll(() => errorMarkerLines(page)).toContain(line);
        expect(sameImage(await readPixels(page), before), 'the previous image stays').toBe(true);

        // pasting a good shader runs it, and the alert goes
        await pasteIntoEditor(page, solid(10, 200, 30));
        await page.waitForFunction(() => /** @type {HTMLElement} */ (document.querySelector('[role="alert"]')).hidden, { polling: 50 });
        expect(allPixels(await readPixels(page), [10, 200, 30])).toBe(true);
        expect(await page.$$('.cm-lint-marker-error')).toHaveLength(0);
      });
    },
  );

  test('typing then Ctrl+Enter compiles; a shader without a control block empties the panel', async () => {
    await withPage(async ({ page, goto }) => {
      await goto(`?shader=examples/raymarch.glsl&${SIZE}&time=2`);
      const folders = () => page.$$eval('.lil-gui .lil-title', (els) => els.map((e) => e.textContent.trim()));
      expect(await folders()).toContain('Shader controls');
      expect(await page.$('::-p-aria([name="Twist (radians per unit)"])')).not.toBeNull();
      await (await button(page, 'Edit shader')).click();
      await page.focus(EDITOR);
      await page.keyboard.down('Control');
      await page.keyboard.press('KeyA');
      await page.keyboard.up('Control');
      await page.keyboard.press('Backspace');
      await typeInEditor(page, 'void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0, 0.0, 1.0, 1.0); }');
      expect(await editorText(page)).toBe('void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0, 0.0, 1.0, 1.0); }');
      await page.keyboard.down('Control');
      await page.keyboard.press('Enter');
      await page.keyboard.up('Control');
      await page.waitForFunction(
        () =>
          window.shaderEngine.info().origin === 'editor' &&
          !document.querySelector('.lil-gui .lil-title')?.parentElement.textContent.includes('Twist'),
      );
      await hook(page).readPixels(); // settles the compile
      expect(allPixels(await readPixels(page), [255, 0, 255])).toBe(true);
      expect(await folders()).not.toContain('Shader controls');
      expect((await info(page)).controls).toEqual({});
    });
  });
});

describe('dropping files on the page', () => {
  test('a .glsl file runs; an image goes into iChannel0', async () => {
    const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'raytracer-drop-'));
    try {
      const shader = path.join(dir, 'dropped-shader.glsl');
      // left half: the channel's colour; right half: iChannelResolution[0].xy / 255
      fs.writeFileSync(
        shader,
        'void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n' +
          '    vec2 uv = fragCoord / iResolution.xy;\n' +
          '    fragColor = uv.x < 0.5 ? texture(iChannel0, uv) : vec4(iChannelResolution[0].xy / 255.0, 0.0, 1.0);\n' +
          '}\n',
      );
      const image = path.join(dir, 'orange.png');
      writeSolidPng(image, 6, 4, [250, 140, 20]);
      await withPage(async ({ page, goto }) => {
        await goto(PATTERN);
        await dropFiles(page, [shader]);
        await page.waitForFunction(() => window.shaderEngine.info().fileName === 'dropped-shader.glsl');
        expect(await info(page)).toMatchObject({ origin: 'file', fileName: 'dropped-shader.glsl' });
        let frame = await readPixels(page);
        expect(pixel(frame, 20, 45)).toEqual([0, 0, 0]); // an empty channel is black
        expect(pixel(frame, 140, 45)).toEqual([0, 0, 0]); // ... of size 0 x 0
        expect(await editorText(page)).toBe(fs.readFileSync(shader, 'utf8'));

        await dropFiles(page, [image]);
        await page.waitForFunction(() => document.getElementById('toast').textContent.includes('orange.png'));
        frame = await readPixels(page);
        expect(pixel(frame, 20, 45)).toEqual([250, 140, 20]);
        expect(pixel(frame, 140, 45)).toEqual([6, 4, 0]);
      });
    } finally {
      fs.rmSync(dir, { recursive: true, force: true });
    }
  });

  test('the panel loads an image into a channel, and ?iChannel1= loads one from the URL', async () => {
    await withServedDir('test-channel', async (dir, base) => {
      writeSolidPng(path.join(dir, 'blue.png'), 3, 5, [20, 60, 240]);
      fs.writeFileSync(
        path.join(dir, 'channels.glsl'),
        'void mainImage(out vec4 c, in vec2 f) {\n    c = f.x < 80.0 ? texture(iChannel1, vec2(0.5)) : texture(iChannel2, vec2(0.5));\n}\n',
      );
      const local = path.join(dir, 'green.png');
      writeSolidPng(local, 2, 2, [30, 220, 90]);
      await withPage(async ({ page, goto }) => {
        await goto(`?shader=${base}/channels.glsl&${SIZE}&time=0&iChannel1=${base}/blue.png`);
        await page.waitForFunction(() => document.querySelector('.lil-gui').textContent.includes('iChannel1… (3×5)'));
        expect(pixel(await readPixels(page), 20, 45)).toEqual([20, 60, 240]);
        expect(pixel(await readPixels(page), 120, 45)).toEqual([0, 0, 0]);
        // Controls → Channels → "Load file into iChannel2…" opens a file chooser
        await page.evaluate(() =>
          [.../** @type {NodeListOf<HTMLElement>} */ (document.querySelectorAll('.lil-gui .lil-title'))]
            .find((t) => t.textContent.trim() === 'Channels')
            .click(),
        );
        await new Promise((r) => setTimeout(r, 600)); // the folder's opening animation
        const [chooser] = await Promise.all([page.waitForFileChooser(), (await button(page, 'Load file into iChannel2…')).click()]);
        await chooser.accept([local]);
        await page.waitForFunction(() => document.querySelector('.lil-gui').textContent.includes('iChannel2… (2×2)'));
        expect(pixel(await readPixels(page), 120, 45)).toEqual([30, 220, 90]);
        expect(await hook(page).shareUrl()).toContain(`iChannel1=${base}/blue.png`);
        await (await button(page, 'Clear iChannel1')).click();
        await page.waitForFunction(() => !document.querySelector('.lil-gui').textContent.includes('(3×5)'));
        expect(pixel(await readPixels(page), 20, 45)).toEqual([0, 0, 0]);
      });
    });
  });
});

describe('output', () => {
  test('"Copy for Shadertoy" copies exactly the file, which compiles in Shadertoy\'s header', async () => {
    let copied;
    await withPage(async ({ page, context, goto }) => {
      await allowClipboard(page, context.baseUrl);
      await goto(`?shader=examples/raymarch.glsl&${SIZE}&time=2&TWIST=2`);
      await page.evaluate(() => navigator.clipboard.writeText('nothing yet'));
      await (await button(page, 'Copy for Shadertoy')).click();
      await page.waitForFunction(() => document.getElementById('toast').textContent.startsWith('Copied'));
      copied = await page.evaluate(() => navigator.clipboard.readText());
    });
    expect(copied).toBe(exampleSource('raymarch'));
    const raw = await renderRawShader(composeImageShader(copied).code, { width: 16, height: 9 });
    expect(raw.stage, raw.log).toBeUndefined();
  });

  test('"Download .glsl" saves the file; "Screenshot" saves the frame as a PNG at the canvas size or a chosen one', async () => {
    let downloads;
    await withPage(async ({ page, goto }) => {
      downloads = await captureDownloads(page);
      await goto(`?shader=examples/pattern.glsl&${SIZE}&time=2&mouse=30,40,-30,-40`);
      await (await button(page, 'Download .glsl')).click();
      const glsl = await downloads.next();
      expect(glsl.name).toBe('pattern.glsl');
      expect(fs.readFileSync(glsl.file, 'utf8')).toBe(exampleSource('pattern'));

      const frame = await readPixels(page);
      await (await button(page, 'Screenshot')).click();
      const shot = await downloads.next();
      expect(shot.name).toBe('pattern-t2.00-160x90.png');
      const png = readPng(shot.file);
      expect(sameImage(png, frame), 'the screenshot is the frame on the canvas').toBe(true);

      const choice = await page.$('::-p-aria([name="Screenshot size"][role="combobox"])');
      await choice.select('2× canvas');
      await (await button(page, 'Screenshot')).click();
      const big = await downloads.next();
      expect(big.name).toBe('pattern-t2.00-320x180.png');
      const bigPng = readPng(big.file);
      // the same view drawn at 320x180 (iMouse scaled with it)
      await goto('?shader=examples/pattern.glsl&size=320x180&time=2&mouse=60,80,-60,-80');
      expect(sameImage(bigPng, await readPixels(page)), 'the 2x screenshot is the view drawn at 2x').toBe(true);
    }).finally(() => downloads?.close());
  });

  test('"Copy link" reproduces the view: shader URL, controls, mouse, time, size', async () => {
    let link;
    let original;
    await withPage(async ({ page, context, goto }) => {
      await allowClipboard(page, context.baseUrl);
      await goto(`?shader=examples/raymarch.glsl&${SIZE}`); // playing, default controls
      await hook(page).setControls({ TWIST: 2.25, ALBEDO: [0.2, 0.5, 0.9] });
      // a real drag on the canvas
      const box = await page.evaluate(() => document.getElementById('view').getBoundingClientRect().toJSON());
      await page.mouse.move(box.left + 30.5, box.top + 20.5);
      await page.mouse.down();
      await page.mouse.move(box.left + 120.5, box.top + 50.5, { steps: 3 });
      await page.mouse.up();
      await page.keyboard.press('Space'); // pause where it is
      await page.waitForFunction(() => !window.shaderEngine.info().playing);
      await hook(page).setTime(3.5);
      original = await readPixels(page);
      await (await button(page, 'Copy link')).click();
      await page.waitForFunction(() => document.getElementById('toast').textContent.startsWith('Copied a link'));
      link = await page.evaluate(() => navigator.clipboard.readText());
      expect(link).toBe(await hook(page).shareUrl());
    });
    const url = new URL(link);
    expect(Object.fromEntries(url.searchParams)).toEqual({
      shader: 'examples/raymarch.glsl',
      size: '160x90',
      time: '3.5',
      mouse: '120,39,-30,-69',
      TWIST: '2.25',
      ALBEDO: '0.2,0.5,0.9',
    });
    await withPage(async ({ page, goto }) => {
      await goto(url.search);
      expect(sameImage(await readPixels(page), original), 'the link shows the same pixels').toBe(true);
    });
  });
});

test('the example shaders are where the page serves them', () => {
  for (const name of ['raymarch', 'pattern', 'inputs']) expect(fs.existsSync(path.join(EXAMPLES_DIR, `${name}.glsl`))).toBe(true);
});
