// The README's picture, rendered by the harness exactly as the tests render views: the page in
// headless Chromium on SwiftShader, default controls at time 0, 4 samples per pixel.
//
//   npm run picture        writes public/scene.png

import path from 'node:path';
import { REPO_ROOT, assertNotBlank, disconnect, renderView, startHarness, useHarness, writePng } from './harness.js';

const VIEW = { name: 'readme', params: { time: 0, SAMPLES: 4 }, size: [960, 540] };

const { context, close } = await startHarness();
useHarness(context);
try {
  const image = await renderView(VIEW);
  assertNotBlank(image, 'README picture');
  const file = path.join(REPO_ROOT, 'public', 'scene.png');
  writePng(file, image);
  console.log(`wrote ${path.relative(REPO_ROOT, file)} (${image.width}x${image.height}, ${context.environment.renderer})`);
} finally {
  await disconnect();
  await close();
}
