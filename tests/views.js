// The render tests, as data. Each view is a page URL (query parameters) and a canvas size; its
// expected image is tests/golden/<name>.png (made by `npm run test:update`, never by hand).
//
// Query parameters (the page's contract): `time` fixes iTime and pauses; `mouse=x,y,z,w` sets
// iMouse in device pixels; `size=WxH` sets the canvas size in device pixels; any other NAME is
// a shader control from the control block of shaders/raytrace.glsl (tests/views.test.js checks
// that every such NAME exists there and that the value is inside its range).

export const DEFAULT_SIZE = [320, 180];

/** Parameters that belong to the page, not to the shader's control block. */
export const PAGE_PARAMS = new Set(['time', 'mouse', 'size']);

export const VIEWS = [
  // Everything at the shader's defaults.
  { name: 'default', params: { time: 0 } },
  // A drag in progress, with Shadertoy's iMouse signs: xy = where the pointer is now, |zw| = where
  // the button went down; z > 0 while the button is held, w < 0 after the press frame.
  { name: 'orbit', params: { time: 0, mouse: [240, 120, 160, -90] } },
  { name: 'texture-stripes', params: { time: 0, TEXTURE: 0 } },
  { name: 'texture-checker', params: { time: 0, TEXTURE: 1 } },
  { name: 'bounces-0', params: { time: 0, BOUNCES: 0 } },
  { name: 'bounces-max', params: { time: 0, BOUNCES: 4 } },
  { name: 'no-shadows', params: { time: 0, SHADOWS: 0 } },
  { name: 'changed-control', params: { time: 0, CONE_HEIGHT: 2.6, LIGHT_POSITION: [-4, 5, 2] } },
  { name: 'aa', params: { time: 0, SAMPLES: 4 } },
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
// Any real change (a control's default, a colour, the camera, a shading term, a bounce) moves
// thousands of pixels by far more than 13 levels. tests/render.test.js proves the tolerance can
// fail: every pair of distinct views must differ in at least PAIR_MIN_FACTOR times
// MAX_DIFF_FRACTION of their pixels, so each view shows something the others do not.
// ------------------------------------------------------------------------------------------------
export const PIXEL_THRESHOLD = 0.05;
export const MAX_DIFF_FRACTION = 0.001;
export const INCLUDE_AA = true;
export const PAIR_MIN_FACTOR = 10;

/** The page URL (path + query) of a view. */
export function viewQuery(view) {
  const [width, height] = view.size ?? DEFAULT_SIZE;
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
