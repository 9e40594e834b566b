// The goldens' views (tests/golden/shaderproof.json, no browser): names, sizes, and every shader
// control a view sets must exist in the control block of shaders/raytrace.glsl with a value
// inside its range, so a renamed or re-ranged control fails here, loudly, instead of silently
// rendering the default; and the manifest's tolerance is the suite's (tests/support/tables/views.js).
import fs from 'node:fs';
import { describe, expect, test } from 'vitest';
import { parseControls } from '../../src/shadertoy/controls.js';
import { SHADER_FILE } from '../support/config.js';
import { allowedDiffPixels } from '../support/images.js';
import { GOLDEN_CASES, REFERENCES } from '../support/goldens.js';
import { MAX_DIFF_FRACTION, PIXEL_THRESHOLD, VIEWS, viewControlProblems, viewQuery, viewSize } from '../support/tables/views.js';
import { EXTRA_SAMPLES_VIEW, extraSamplesValues } from '../../src/raytracer/extra-samples.js';

describe('view table', () => {
  const controls = parseControls(fs.readFileSync(SHADER_FILE, 'utf8'));

  test('the shader has a control block', () => {
    expect(controls.length).toBeGreaterThan(0);
  });

  test('the harness reads the debug VIEW "Extra samples" by its number in the control block', () => {
    const view = controls.find((c) => c.name === 'VIEW');
    expect(view?.options?.find((o) => o.value === EXTRA_SAMPLES_VIEW.VIEW)?.label).toBe('Extra samples');
    expect(extraSamplesValues(controls), "the page's inspector finds it by its label").toEqual(EXTRA_SAMPLES_VIEW);
  });

  test('view names are unique file-name-safe words', () => {
    const names = VIEWS.map((v) => v.name);
    expect(new Set(names).size).toBe(names.length);
    for (const name of names) expect(name).toMatch(/^[a-z0-9][a-z0-9-]*$/);
  });

  test.each(VIEWS.map((v) => [v.name, v]))('%s: every control it sets exists and is in range', (_, view) => {
    expect(viewControlProblems(view, controls)).toEqual([]);
  });

  test.each(VIEWS.map((v) => [v.name, v]))('%s: size and time are fixed', (_, view) => {
    const [w, h] = viewSize(view);
    expect(Number.isInteger(w) && Number.isInteger(h) && w > 0 && h > 0).toBe(true);
    expect(w * h).toBeLessThanOrEqual(640 * 360); // SwiftShader is a CPU: keep the suite fast
    expect(view.params.time).toBe(0);
  });

  test('mouse values follow Shadertoy iMouse signs (z > 0 while held, w < 0 after the press frame)', () => {
    for (const view of VIEWS.filter((v) => v.params.mouse)) {
      const [x, y, z, w] = view.params.mouse;
      const [width, height] = viewSize(view);
      expect(x >= 0 && x <= width && y >= 0 && y <= height).toBe(true);
      expect(Math.abs(z) <= width && Math.abs(w) <= height).toBe(true);
      expect(z === 0 || w <= 0 || z > 0).toBe(true);
    }
  });

  test('viewQuery writes the page contract', () => {
    expect(viewQuery({ name: 'x', params: { time: 0, mouse: [1, 2, -3, -4], LIGHT_POSITION: [1, 2, 3] } })).toBe(
      '/?size=320x180&time=0&mouse=1,2,-3,-4&LIGHT_POSITION=1,2,3',
    );
    expect(viewQuery({ name: 'x', size: [64, 32], params: { BOUNCES: 0 } })).toBe('/?size=64x32&BOUNCES=0');
  });

  test('every golden image belongs to a view', () => {
    const views = new Set(VIEWS.map((v) => `${v.name}.png`));
    const stray = fs.existsSync(REFERENCES) ? fs.readdirSync(REFERENCES).filter((f) => f.endsWith('.png') && !views.has(f)) : [];
    expect(stray, `golden images without a view in tests/golden/shaderproof.json: delete them from ${REFERENCES}`).toEqual([]);
  });

  test("the runner reads the manifest's views as the harness does, with the suite's tolerance", () => {
    expect(GOLDEN_CASES.map((c) => c.name).sort()).toEqual(VIEWS.map((v) => v.name).sort());
    for (const testCase of GOLDEN_CASES) {
      const view = VIEWS.find((v) => v.name === testCase.name);
      const { width, height } = testCase.view.size;
      expect([width, height], testCase.name).toEqual(viewSize(view));
      expect(testCase.view.time, testCase.name).toBe(view.params.time);
      expect(testCase.file, testCase.name).toBe(SHADER_FILE);
      expect(testCase.tolerance, testCase.name).toEqual({ threshold: PIXEL_THRESHOLD, maxDiffPixels: allowedDiffPixels(width, height) });
    }
    // the one renderer's own: aa-pixels on llvmpipe, 1% of its pixels (the reason is in the manifest)
    const own = GOLDEN_CASES.filter((c) => Object.keys(c.rendererTolerance).length);
    expect(own.map((c) => [c.name, c.rendererTolerance])).toEqual([
      ['aa-pixels', { llvmpipe: { threshold: PIXEL_THRESHOLD, maxDiffPixels: 576 } }],
    ]);
  });

  test('the tolerance is small', () => {
    expect(PIXEL_THRESHOLD).toBeLessThanOrEqual(0.1);
    expect(MAX_DIFF_FRACTION).toBeLessThanOrEqual(0.005);
  });
});
