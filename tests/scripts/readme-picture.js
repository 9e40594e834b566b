// The README's pictures, made by the harness in headless Chromium on SwiftShader:
// - public/scene.png: the scene, rendered exactly as the tests render views (the default
//   controls, adaptive anti-aliasing among them, at time 0);
// - public/page.png: the page itself at 1280x800 (toolbar, canvas, the panel beside it, the
//   editor open), as a person sees it;
// - public/views.png: the shader's debug views (VIEW 0 to 5) side by side, three a row.
//
//   npm run picture        writes both

import path from 'node:path';
import { REPO_ROOT, rel } from '../harness/config.js';
import { assertNotBlank, writePng } from '../harness/images.js';
import { harnessContext, openPage, renderView } from '../harness/page.js';
import { withHarness } from '../harness/setup.js';

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
    await page.waitForFunction(() => window.raytracer, { polling: 50 }); // installed once the render worker runs
    await page.evaluate(() => window.raytracer.ready);
    const edit = await page.$('::-p-aria([name="Edit shader"])');
    if (edit) await edit.click();
    await page.evaluate(() => window.raytracer.readPixels()); // one more frame, with the editor open
    const pageFile = path.join(REPO_ROOT, 'public', 'page.png');
    await page.screenshot({ path: pageFile });
    if (errors.length) throw new Error(`the page logged errors:\n  ${errors.join('\n  ')}`);
    console.log(`wrote ${rel(pageFile)} (${PAGE_VIEWPORT.width}x${PAGE_VIEWPORT.height})`);
  } finally {
    await page.close();
  }
});
