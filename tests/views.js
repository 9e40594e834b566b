// The render tests, as data. Each view is a page URL (query parameters) and a canvas size; its
// expected image is tests/golden/<name>.png (made by `npm run test:update`, never by hand).
//
// Query parameters (the page's contract): `time` fixes iTime and pauses; `mouse=x,y,z,w` sets
// iMouse in device pixels; `size=WxH` sets the canvas size in device pixels; any other NAME is
// a shader control from the control block of shaders/raytrace.glsl (tests/views.test.js checks
// that every such NAME exists there and that the value is inside its range).

import { coerceControlValue } from '../src/shadertoy/controls.js';

/** The canvas size of a view that gives none: the render views' and the hard views' (hard-views.js). */
export const DEFAULT_SIZE = [320, 180];

/** Parameters that belong to the page, not to the shader's control block. */
export const PAGE_PARAMS = new Set(['time', 'mouse', 'size']);

// Looking down at the ground from higher up, so the texture fills most of the frame.
const HIGH_CAMERA = { CAMERA_ORBIT: [30, 50] };

// A close look into the 5 cm gap between a mirror sphere and a mirror cube, where rays bounce
// back and forth: the only place in the scene where a 4th bounce changes many pixels (at the
// default reflectivities BOUNCES=4 and 3 differ in about 4 pixels of the default view).
const MIRROR_GAP = {
  SPHERE_CENTER: [-0.35, 0.8, -1.1],
  SPHERE_REFLECTIVITY: 0.9,
  CUBE_REFLECTIVITY: 0.9,
  CAMERA_TARGET: [0.45, 0.6, -1.1],
  CAMERA_ORBIT: [0, 12],
  CAMERA_DISTANCE: 4,
  FIELD_OF_VIEW: 15,
};

// The cone's apex in front of the cube's corner, from close by.
const EDGES_CLOSE_UP = { CAMERA_TARGET: [1.1, 0.9, 0], CAMERA_DISTANCE: 3, FIELD_OF_VIEW: 30 };

// `contrast` (optional): the same view with these parameters changed must differ from it in
// more than PAIR_MIN_FACTOR x MAX_DIFF_FRACTION of its pixels, so the view really tests what it
// sets (used where no other view of the table is that contrast).
export const VIEWS = [
  // Everything at the shader's defaults.
  { name: 'default', params: { time: 0 } },
  // A drag in progress, with Shadertoy's iMouse signs: xy = where the pointer is now, |zw| = where
  // the button went down; z > 0 while the button is held, w < 0 after the press frame.
  { name: 'orbit', params: { time: 0, mouse: [240, 120, 160, -90] } },
  { name: 'texture-stripes', params: { time: 0, TEXTURE: 0, ...HIGH_CAMERA } },
  { name: 'texture-checker', params: { time: 0, TEXTURE: 1, ...HIGH_CAMERA } },
  { name: 'bounces-0', params: { time: 0, BOUNCES: 0 } },
  { name: 'bounces-max', params: { time: 0, BOUNCES: 4, ...MIRROR_GAP }, contrast: { BOUNCES: 3 } },
  { name: 'no-shadows', params: { time: 0, SHADOWS: 0 } },
  { name: 'changed-control', params: { time: 0, CONE_HEIGHT: 2.6, LIGHT_POSITION: [-4, 5, 2] } },
  // Uniform supersampling, every pixel the 2x2 grid, on a close look at the cone and the cube
  // (edges, creases and shadow boundaries fill the frame).
  { name: 'aa', params: { time: 0, SAMPLES: 4, ADAPTIVE_AA: 0, ...EDGES_CLOSE_UP }, contrast: { SAMPLES: 1 } },
  // One sample per pixel (the default is adaptive anti-aliasing: pixels on an edge take the 4x4
  // grid, the others one sample) ...
  { name: 'one-sample', params: { time: 0, SAMPLES: 1 } },
  // ... and which pixels take the grid, over the picture in grey, coloured by the test that
  // marked them (the VIEW "Extra samples").
  { name: 'aa-pixels', params: { time: 0, VIEW: 5 } },
  // The other debug views: the first surface's normal, its distance, each object's flat colour,
  // the reflections each pixel's path traced.
  { name: 'view-normals', params: { time: 0, VIEW: 1 } },
  { name: 'view-depth', params: { time: 0, VIEW: 2 } },
  // (flatColours: a view of a few flat colours by design, the least it must show)
  { name: 'view-object', params: { time: 0, VIEW: 3 }, flatColours: 5 },
  { name: 'view-bounces', params: { time: 0, VIEW: 4 }, flatColours: 4 },
  // The eye under the ground: its underside, plain, where the cone's base and the cube's bottom
  // lie in its plane (they used to show through in speckles: issue 18).
  { name: 'below-ground', params: { time: 0, CAMERA_ORBIT: [30, -20] } },
  // The assignment's other new objects, each in the cone's place (SCENE): a cylinder, and a
  // torus that shows its hole and its inner wall.
  { name: 'scene-cylinder', params: { time: 0, SCENE: 1 } },
  { name: 'scene-torus', params: { time: 0, SCENE: 2 } },
];

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
// bounces-max); every other pair differs in more than 20% of its pixels. tests/render.test.js proves the tolerance can fail:
// every pair of distinct views, and each view against its `contrast`, must differ in more than
// PAIR_MIN_FACTOR times MAX_DIFF_FRACTION of their pixels, so each view shows something the
// tolerance could not hide.
// ------------------------------------------------------------------------------------------------
export const PIXEL_THRESHOLD = 0.05;
export const MAX_DIFF_FRACTION = 0.001;

// ------------------------------------------------------------------------------------------------
// The same goldens drawn by a second, independent rasterizer (SHADERPROOF_RENDERER=llvmpipe, `npm
// run test:llvmpipe`, run by CI): Mesa's llvmpipe, where SwiftShader drew them. Two rasterizers
// that agree are evidence that the picture is the shader's, not one rasterizer's. Measured on
// Chromium 156 with Mesa 22.3.6 (LLVM 15, AVX2): every view but one is within the SwiftShader
// tolerance above. The exception, by view:
//
//   aa-pixels   0.48% (276 of 57,600)   the "pixels with extra samples" view colours each pixel by
//               the number of samples adaptive anti-aliasing chose for it, a threshold on its
//               neighbours' contrast; at a silhouette the contrast sits on the threshold, and a
//               last-bit difference in a colour flips a pixel's count (the diff is speckles along
//               every edge, none in an area). The pictures themselves agree (`aa`, within 0.1%).
//               Allowed 1%: twice the measured, and still a tenth of the closest pair of views.
// ------------------------------------------------------------------------------------------------
/** @type {Record<string, Record<string, number>>} renderer → view → its MAX_DIFF_FRACTION */
export const RENDERER_MAX_DIFF_FRACTION = { llvmpipe: { 'aa-pixels': 0.01 } };
export const INCLUDE_AA = true;
export const PAIR_MIN_FACTOR = 10;

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
