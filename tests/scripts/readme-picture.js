// The README's pictures, made by the harness in headless Chromium on SwiftShader:
// - public/scene.png: the scene, rendered exactly as the tests render views (the default
//   controls, adaptive anti-aliasing among them, at time 0);
// - public/page.png: the page itself at 1280x800 (toolbar, canvas, the panel beside it, the
//   editor open), as a person sees it;
// - public/views.png: the shader's debug views (VIEW 0 to 5) side by side, three a row;
// - public/inspector.png: the page at 1280x800 after "Compare with float64" (the heat map over
//   the canvas, its figures and legend), with Inspect on, a pixel on the sphere pinned (its
//   readout: float colour, path, float64 colour) and the magnifier over the map.
//
//   npm run picture        writes all four

import path from 'node:path';
import { REPO_ROOT, rel } from '../support/config.js';
import { assertNotBlank, writePng } from '../support/images.js';
import { harnessContext, openPage, renderView } from '../support/page.js';
import { withHarness } from '../support/setup.js';
import { hook } from '../support/hook.js';

const VIEW = { name: 'readme', params: { time: 0 }, size: [960, 540] };
const DEBUG_VIEW_SIZE = [320, 180];

/** Images of one size side by side, `columns` a row. */
function montage(images, columns) {
  const { width, height } = images[0];
  const rows = Math.ceil(images.length / columns);
  const out = { width: width * columns, height: height * rows, data: new Uint8Array(width * columns * height * rows * 4) };
  images.forEach((image, k) => {
    const [ox, oy] = [(k % columns) * width, Math.floor(k / columns) * height];
    for (let y = 0; y < height; y++) out.data.set(image.data.subarray(y * width * 4, (y + 1) * width * 4), ((oy + y) * out.width + ox) * 4);
  });
  return out;
}
const PAGE_VIEWPORT = { width: 1280, height: 800, deviceScaleFactor: 1 };
// Where the inspector's pixel and the magnifier are, as image coordinates u, v (-1 .. 1 of the
// height, from the centre, as eyeRay takes them): on the sphere, where its mirror shows the cube;
// and on the near ground, where the stripes' edges are the hottest pixels.
/** @type {[number, number]} */
const PINNED = [-0.25, 0.083];
/** @type {[number, number]} */
const MAGNIFIED = [0.55, -0.62];

/**
 * The pixel (y from the bottom) at image point (u, v) of a width x height canvas.
 * @param {[number, number]} point
 * @param {number} width
 * @param {number} height
 */
const pixelOf = ([u, v], width, height) => [Math.floor((u * height + width) / 2), Math.floor((v * height + height) / 2)];

await withHarness(async (context) => {
  const image = await renderView(VIEW);
  assertNotBlank(image, 'README picture');
  const sceneFile = path.join(REPO_ROOT, 'public', 'scene.png');
  writePng(sceneFile, image);
  console.log(`wrote ${rel(sceneFile)} (${image.width}x${image.height}, ${context.environment.renderer})`);

  const views = [];
  for (let view = 0; view <= 5; view++)
    views.push(await renderView({ name: `view-${view}`, params: { time: 0, VIEW: view }, size: DEBUG_VIEW_SIZE }));
  const viewsFile = path.join(REPO_ROOT, 'public', 'views.png');
  writePng(viewsFile, montage(views, 3));
  console.log(`wrote ${rel(viewsFile)}`);

  const { page, errors } = await openPage();
  try {
    await page.setViewport(PAGE_VIEWPORT);
    await page.goto(`${(await harnessContext()).baseUrl}/?time=0`, { waitUntil: 'load' });
    await page.waitForFunction(() => window.shaderEngine, { polling: 50 }); // installed once the render worker runs
    await hook(page).ready();
    const edit = await page.$('::-p-aria([name="Edit shader"])');
    if (edit) await edit.click();
    await hook(page).readPixels(); // one more frame, with the editor open
    const pageFile = path.join(REPO_ROOT, 'public', 'page.png');
    await page.screenshot({ path: pageFile });
    if (errors.length) throw new Error(`the page logged errors:\n  ${errors.join('\n  ')}`);
    console.log(`wrote ${rel(pageFile)} (${PAGE_VIEWPORT.width}x${PAGE_VIEWPORT.height})`);
  } finally {
    await page.close();
  }

  await inspectorPicture();
});

/** public/inspector.png: the comparison's heat map, the inspector's readout and its magnifier. */
async function inspectorPicture() {
  const { page, errors } = await openPage({ deterministic: false }); // the reference's time is real
  try {
    await page.setViewport(PAGE_VIEWPORT);
    await page.goto(`${(await harnessContext()).baseUrl}/?time=0`, { waitUntil: 'load' });
    await page.waitForFunction(() => window.shaderEngine, { polling: 50 });
    await hook(page).ready();
    const compared = await hook(page).compareWithFloat64();
    const { width, height } = compared;
    const [x, y] = pixelOf(PINNED, width, height);
    const readout = await hook(page).inspect(x, y);
    const box = await page.$eval('#view', (c) => {
      const r = c.getBoundingClientRect();
      return { left: r.left, top: r.top, width: r.width, height: r.height };
    });
    const [mx, my] = pixelOf(MAGNIFIED, width, height);
    await page.mouse.move(box.left + ((mx + 0.5) / width) * box.width, box.top + ((height - 1 - my + 0.5) / height) * box.height);
    await page.waitForFunction(() => !(/** @type {HTMLElement} */ (document.querySelector('.loupe-box')).hidden), { polling: 50 });
    const file = path.join(REPO_ROOT, 'public', 'inspector.png');
    await page.screenshot({ path: file });
    if (errors.length) throw new Error(`the page logged errors:\n  ${errors.join('\n  ')}`);
    const path0 = readout.path.rays.map((r) => r.object).join(' → ');
    console.log(
      `wrote ${rel(file)} (${width}x${height} compared in ${(compared.ms.total / 1000).toFixed(1)} s; pixel ${x}, ${y}: ${path0})`,
    );
  } finally {
    await page.close();
  }
}
