// The README's picture, rendered by the harness exactly as the tests render views: the page in
// headless Chromium on SwiftShader, default controls at time 0, 4 samples per pixel.
//
//   npm run picture        writes public/scene.png

import path from 'node:path';
import { REPO_ROOT, rel } from '../harness/config.js';
import { assertNotBlank, writePng } from '../harness/images.js';
import { renderView } from '../harness/page.js';
import { withHarness } from '../harness/setup.js';

const VIEW = { name: 'readme', params: { time: 0, SAMPLES: 4 }, size: [960, 540] };

await withHarness(async (context) => {
  const image = await renderView(VIEW);
  assertNotBlank(image, 'README picture');
  const file = path.join(REPO_ROOT, 'public', 'scene.png');
  writePng(file, image);
  console.log(`wrote ${rel(file)} (${image.width}x${image.height}, ${context.environment.renderer})`);
});
