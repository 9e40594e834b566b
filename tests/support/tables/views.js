// Views of the page, as the harness draws them (tests/support/page.js renderView): each is a page
// URL (query parameters) and a canvas size. The render goldens' views are data of their own,
// tests/golden/shaderproof.json (a `shaderproof test` folder, run by tests/browser/render.test.js);
// VIEWS reads them here as the same kind of view, for the checks of tests/browser/views.test.js and the
// Shadertoy paste.
//
// Query parameters (the page's contract): `time` fixes iTime and pauses; `mouse=x,y,z,w` sets
// iMouse in device pixels; `size=WxH` sets the canvas size in device pixels; any other NAME is
// a shader control from the control block of shaders/raytrace.glsl (tests/browser/views.test.js checks
// that every such NAME exists there and that the value is inside its range).

import fs from 'node:fs';
import path from 'node:path';
import { coerceControlValue } from '../../../src/shadertoy/controls.js';
import { GOLDEN_DIR } from '../config.js';

/** The canvas size of a view that gives none: the render views' and the hard views' (hard-views.js). */
export const DEFAULT_SIZE = [320, 180];

/** Parameters that belong to the page, not to the shader's control block. */
export const PAGE_PARAMS = new Set(['time', 'mouse', 'size']);

/**
 * The goldens' views (tests/golden/shaderproof.json: each case's entry over the defaults, as the
 * runner reads them), as page views: { name, params: {time, mouse, ...set}, size }.
 * @returns {{name: string, params: Record<string, any>, size: [number, number]}[]}
 */
function goldenViews() {
  const manifest = JSON.parse(fs.readFileSync(path.join(GOLDEN_DIR, 'shaderproof.json'), 'utf8'));
  return Object.entries(manifest.cases).map(([name, own]) => {
    const entry = { ...manifest.defaults, ...own };
    const params = {
      ...(entry.time === undefined ? {} : { time: entry.time }),
      ...(entry.mouse === undefined ? {} : { mouse: entry.mouse }),
      ...entry.set,
    };
    const size = /** @type {[number, number]} */ (entry.size ? entry.size.split('x').map(Number) : DEFAULT_SIZE);
    return { name, params, size };
  });
}

/** The render goldens' views (tests/golden/shaderproof.json). */
export const VIEWS = goldenViews();

// ------------------------------------------------------------------------------------------------
// Tolerance for comparing a render with its golden (pixelmatch):
//
//   PIXEL_THRESHOLD = 0.05   per-pixel colour distance (pixelmatch's YIQ metric, 0..1) above
//                            which a pixel counts as different: about 13 of 255 levels of
//                            brightness. Same-build SwiftShader output is bit-identical; across
//                            Chromium/SwiftShader builds, transcendental functions (pow, exp,
//                            sin, sqrt) and rounding may move a colour by 1-3 levels. That stays
//                            well under the threshold.
//   MAX_DIFF_FRACTION = 0.001 at most 0.1% of the pixels (57 of 320x180) may exceed it. Those
//                            are rays that graze a silhouette or a shadow/texture boundary and
//                            land on the other side after a last-bit difference: a few isolated
//                            pixels, never an area.
//   INCLUDE_AA = true        every pixel counts. pixelmatch's anti-aliasing detector is meant for
//                            vector art; in a ray-traced image it would forgive exactly the edge
//                            pixels a moved object changes.
//
// Measured on Chromium 156 / SwiftShader: a render matches its golden bit for bit, and the
// Shadertoy-paste render matches the page's default view bit for bit. A real change is far
// outside the tolerance: the smallest differences between views are anti-aliasing on/off (1.4%
// of the default view), shadows on/off (3.4%) and the 4th bounce (3.3% of the mirror-gap view,
// bounces-max); every other pair differs in more than 20% of its pixels. tests/browser/render.test.js proves the tolerance can fail:
// every pair of distinct views, and each view against its contrast, must differ in more than
// ten times MAX_DIFF_FRACTION of their pixels, so each view shows something the tolerance could
// not hide. The goldens' manifest says the same tolerance in pixels (57 of 320x180), and a
// renderer's own where it needs one, with its reason (aa-pixels on llvmpipe);
// tests/browser/views.test.js checks that the two agree.
// ------------------------------------------------------------------------------------------------
export const PIXEL_THRESHOLD = 0.05;
export const MAX_DIFF_FRACTION = 0.001;

export const INCLUDE_AA = true;

/** The page URL (path + query) of a view. */
export function viewQuery(view) {
  const [width, height] = viewSize(view);
  const query = new URLSearchParams();
  query.set('size', `${width}x${height}`);
  for (const [name, value] of Object.entries(view.params)) {
    query.set(name, Array.isArray(value) ? value.join(',') : String(value));
  }
  // URLSearchParams encodes ',' as %2C; the page reads either, but plain commas read better in
  // failure messages and in a browser's address bar.
  return `/?${query.toString().replaceAll('%2C', ',')}`;
}

export function viewSize(view) {
  return view.size ?? DEFAULT_SIZE;
}

/**
 * What is wrong with the shader controls a view sets, given parseControls(shader): unknown names
 * (a renamed control), unreadable values, values outside the range (the page would clamp them).
 */
export function viewControlProblems(view, controls) {
  const byName = new Map(controls.map((c) => [c.name, c]));
  const problems = [];
  for (const [name, value] of Object.entries(view.params)) {
    if (PAGE_PARAMS.has(name)) continue;
    const control = byName.get(name);
    if (!control) {
      problems.push(`${view.name}: ${name} is not a control of shaders/raytrace.glsl (controls: ${[...byName.keys()].join(', ')})`);
      continue;
    }
    const coerced = coerceControlValue(control, value);
    if (coerced === undefined) problems.push(`${view.name}: ${name}=${value} is not a valid ${control.type}`);
    else if (JSON.stringify(coerced) !== JSON.stringify(value)) {
      problems.push(`${view.name}: ${name}=${JSON.stringify(value)} is outside its range; the page would use ${JSON.stringify(coerced)}`);
    }
  }
  return problems;
}
