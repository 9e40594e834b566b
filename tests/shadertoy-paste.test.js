// The shader as Shadertoy runs it: shaders/raytrace.glsl inside Shadertoy's exact WebGL2 header,
// with NO host block (composeImageShader(source): what the site compiles when the file is
// pasted into an Image tab), compiled in a raw WebGL2 context (no three.js, no page code) and
// drawn as one fullscreen triangle at iTime 0 with iMouse zero. It must compile, draw a scene,
// and draw the same scene as the page's `default` view: same defaults, same pixels.
import fs from 'node:fs';
import path from 'node:path';
import { afterAll, expect, test } from 'vitest';
import { composeImageShader } from '../src/shadertoy/header.js';
import {
  OUTPUT_DIR,
  REPO_ROOT,
  SHADER_FILE,
  allowedDiffPixels,
  assertNotBlank,
  compareImages,
  disconnect,
  mapShaderLog,
  renderRawShader,
  renderView,
  writePng,
} from './harness.js';
import { PIXEL_THRESHOLD, VIEWS, viewSize } from './views.js';

afterAll(disconnect);

test('raytrace.glsl pasted into Shadertoy compiles and renders the default view', async () => {
  const source = fs.readFileSync(SHADER_FILE, 'utf8');
  const { code, firstSourceLine } = composeImageShader(source);
  const view = VIEWS.find((v) => v.name === 'default');
  const [width, height] = viewSize(view);

  const raw = await renderRawShader(code, { width, height });
  if (raw.stage) {
    const log = mapShaderLog(raw.log, { firstSourceLine, source, fileName: path.relative(REPO_ROOT, SHADER_FILE) });
    throw new Error(`In Shadertoy's header with no host block, the shader fails to ${raw.stage}:\n${log}`);
  }
  expect(raw.glError, 'WebGL error after the draw').toBe(0);
  expect(raw.renderer).toMatch(/SwiftShader/i);
  assertNotBlank(raw, 'raw Shadertoy render');

  const page = await renderView(view);
  const { diffPixels, diff } = compareImages(raw, page);
  const allowed = allowedDiffPixels(width, height);
  const files = {
    shadertoy: path.join(OUTPUT_DIR, 'shadertoy-paste-actual.png'),
    page: path.join(OUTPUT_DIR, 'shadertoy-paste-page.png'),
    diff: path.join(OUTPUT_DIR, 'shadertoy-paste-diff.png'),
  };
  for (const file of Object.values(files)) fs.rmSync(file, { force: true });
  if (diffPixels > allowed) {
    writePng(files.shadertoy, raw);
    writePng(files.page, page);
    writePng(files.diff, diff);
    const rel = (f) => path.relative(REPO_ROOT, f);
    throw new Error(
      `The Shadertoy render and the page's default view (${page.url}) differ in ${diffPixels} pixels ` +
        `(threshold ${PIXEL_THRESHOLD}, at most ${allowed} allowed): the page does not render the shader's defaults ` +
        `as Shadertoy does.\n  shadertoy: ${rel(files.shadertoy)}\n  page:      ${rel(files.page)}\n  diff:      ${rel(files.diff)}`,
    );
  }
});
