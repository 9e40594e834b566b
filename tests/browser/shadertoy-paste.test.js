// The shader as Shadertoy runs it: shaders/raytrace.glsl inside Shadertoy's exact WebGL2 header,
// with NO host block (composeImageShader(source): what the site compiles when the file is
// pasted into an Image tab), compiled in a raw WebGL2 context (no three.js, no page code) and
// drawn as one fullscreen triangle at iTime 0 with iMouse zero. It must compile, draw a scene,
// and draw the same scene as the page's `default` view: same defaults, same pixels.
import fs from 'node:fs';
import { afterAll, expect, test } from 'vitest';
import { drawnBy, suiteRenderer } from '../../src/headless/renderers.js';
import { composeImageShader } from '../../src/shadertoy/header.js';
import { SHADER_FILE, rel } from '../support/config.js';
import { assertNotBlank, expectImagesMatch } from '../support/images.js';
import { disconnect, renderView } from '../support/page.js';
import { mapShaderLog, renderRawShader } from '../support/raw-webgl/raw-webgl.js';
import { VIEWS, viewSize } from '../support/tables/views.js';

afterAll(disconnect);

test('raytrace.glsl pasted into Shadertoy compiles and renders the default view', async () => {
  const source = fs.readFileSync(SHADER_FILE, 'utf8');
  const { code, firstSourceLine } = composeImageShader(source);
  const view = VIEWS.find((v) => v.name === 'default');
  const [width, height] = viewSize(view);

  const raw = await renderRawShader(code, { width, height });
  if (raw.stage) {
    const log = mapShaderLog(raw.log, { code, firstSourceLine, source, fileName: rel(SHADER_FILE) });
    throw new Error(`In Shadertoy's header with no host block, the shader fails to ${raw.stage}:\n${log}`);
  }
  expect(raw.glError, 'WebGL error after the draw').toBe(0);
  // drawn by the suite's renderer (SwiftShader, or llvmpipe in npm run test:llvmpipe), not another
  expect(drawnBy(suiteRenderer(), raw.renderer), raw.renderer).toBe(true);
  assertNotBlank(raw, 'raw Shadertoy render');

  const page = await renderView(view);
  expectImagesMatch('shadertoy-paste', raw, page, {
    actualLabel: 'the Shadertoy render',
    expectedLabel: `the page's default view (${page.url})`,
    hint: "The page does not render the shader's defaults as Shadertoy does.",
  });
});

// Every choice of the compile-time controls a person edits in the pasted file compiles in
// Shadertoy's header as it stands: each scene (SCENE) and each debug view (VIEW), the line of the
// control block changed as a person changes it there.
const CHOICES = [...[1, 2].map((scene) => ['SCENE', scene]), ...[1, 2, 3, 4, 5].map((view) => ['VIEW', view])];
test.each(CHOICES)('with #define %s %i, the pasted file compiles and draws in Shadertoy’s header', async (name, value) => {
  const source = fs.readFileSync(SHADER_FILE, 'utf8');
  const line = new RegExp(String.raw`^#define ${name} \d+`, 'm');
  expect(source).toMatch(line);
  const edited = source.replace(line, `#define ${name} ${value}`);
  const { code, firstSourceLine } = composeImageShader(edited);
  const raw = await renderRawShader(code, { width: 32, height: 18 });
  if (raw.stage)
    throw new Error(`${name} ${value}: ${mapShaderLog(raw.log, { code, firstSourceLine, source: edited, fileName: rel(SHADER_FILE) })}`);
  // the Object and Bounces views are a few flat colours by design
  assertNotBlank(raw, `${name} ${value}`, { minColours: name === 'VIEW' && (value === 3 || value === 4) ? 3 : 16 });
});
