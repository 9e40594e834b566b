// Hard views, as data: each is rendered by the real page (float32 on SwiftShader) and by the
// float64 reference (src/reference/render.js) with the same rays, and compared with the error
// module (src/reference/error.js). Parameters are the page's URL contract (tests/support/tables/views.js).
//
// MAX_OVER_2: at most 0.01% of pixels may be off by more than 2/255 against the same-ray
// reference. With identical rays, what is left is float32 arithmetic: a ray that grazes a
// silhouette, a shadow edge or a stripe edge within rounding can land on the other side, and a
// 320x180 view has only a few hundred such pixels, of which a handful may flip. A view may raise
// its bound only with the reason written beside it.
//
// A hard view's size, like a render view's, is `size` or else DEFAULT_SIZE (views.js: viewSize).

import { viewSize } from './views.js';

export const MAX_OVER_2 = 1e-4;

/**
 * @typedef {object} HardView
 * @property {string} name
 * @property {string} what what makes it hard
 * @property {Record<string, any>} params the page's URL parameters (tests/support/tables/views.js)
 * @property {[number, number]} [size] the canvas size (default: DEFAULT_SIZE)
 * @property {boolean} [uniform] a one-colour picture is right for it (not checked for blankness)
 * @property {number} [maxOver2] a bound raised above MAX_OVER_2, with the reason beside it
 * @property {number} [adaptiveMaxOver2] the same, for adaptive anti-aliasing only
 */

/** @type {HardView[]} */
export const HARD_VIEWS = [
  {
    name: 'apex-from-above',
    what: "looking straight down at the cone's apex (elevation 90°: the camera basis must not degenerate, the apex normal is 0/0)",
    params: { time: 0, CAMERA_TARGET: [1.2, 1.7, 1.1], CAMERA_ORBIT: [30, 90], CAMERA_DISTANCE: 3 },
  },
  {
    name: 'horizon-1mm',
    what: 'the eye a millimetre above the ground, looking at the horizon (plane hits at grazing angles, footprints that grow without bound)',
    params: { time: 0, CAMERA_TARGET: [0, 0.001, 0], CAMERA_ORBIT: [30, 0] },
  },
  {
    name: 'telephoto-1e3',
    what: 'a telephoto view from 1e3 away (ray directions that differ by 2e-5 per pixel)',
    params: { time: 0, CAMERA_DISTANCE: 1000, FIELD_OF_VIEW: 0.35 },
    // With adaptive anti-aliasing each edge pixel (2.4% of this view) traces a 4x4 grid, so 16
    // times as many rays graze a silhouette within float32 rounding of its directions (2e-5 a
    // pixel here, 5e-6 a sub-sample), and each that lands on the other side moves its pixel by a
    // sixteenth of the edge's contrast, over 2/255 still: 12 pixels of 57,600 against 3 at one
    // sample. The same flips, not a new error: the bound for this view with adaptive sampling.
    adaptiveMaxOver2: 4e-4,
  },
  {
    name: 'scene-at-1e4',
    what: 'the whole scene moved to x = 1e4 (float32 spacing there is 2^-10: the stripes must stay stripes)',
    params: { time: 0, SCENE_ORIGIN: [10000, 0, 0] },
  },
  {
    name: 'scene-at-1e6',
    what: 'the scene moved to (1e6, 0, -1e6), where float32 spacing is 1/16: world coordinates would smear a stripe over 16 steps',
    params: { time: 0, SCENE_ORIGIN: [1000000, 0, -1000000] },
  },
  {
    name: 'inside-sphere',
    what: 'the eye inside the sphere (every primary ray starts inside a closed solid; reflections stay inside)',
    params: { time: 0, CAMERA_TARGET: [-1.3, 0.8, 0.3], CAMERA_DISTANCE: 0.4 },
    // The sphere is a closed opaque solid: no direct light reaches its inside, so every pixel is
    // the ambient term of its colour, seen directly or in its own mirror. Uniform is right here.
    uniform: true,
  },
  {
    name: 'facing-mirrors',
    what: 'the sphere and the cube as 90% mirrors facing each other, at the maximum bounce limit',
    params: { time: 0, SPHERE_CENTER: [-0.5, 0.8, -1.1], SPHERE_REFLECTIVITY: 0.9, CUBE_REFLECTIVITY: 0.9, BOUNCES: 4 },
  },
  {
    name: 'below-ground',
    what: "the eye under the ground: the cone's base and the cube's bottom lie in the ground's plane, and which is nearer is decided by rounding unless the ground wins the tie",
    params: { time: 0, CAMERA_ORBIT: [30, -20] },
  },
  {
    name: 'torus-far',
    what: 'the torus scene from 1e3 away (its quartic would lose most of its digits there; float32 spacing at 1e3 is 6e-5)',
    params: { time: 0, SCENE: 2, CAMERA_DISTANCE: 1000, FIELD_OF_VIEW: 0.35 },
    // 6 pixels of 57,600 over 2/255 where the cone's scene has 3 (telephoto-1e3): two where the
    // torus's silhouette or its shadow's edge lands on the other side, and four 3 or 4 levels
    // off in its reflections, whose start and normal carry the rounding of the 1e3 distance
    // (the reflection starts moved off the torus by 32 ulps of 1e3: 2e-3). Measured with the
    // starts moved by offsetAlong's 512 ulps instead: 0.67% of a closer view. One pixel over the
    // 0.01% bound; the bound for this view.
    maxOver2: 1.2e-4,
    // With adaptive anti-aliasing, as for telephoto-1e3: 16 times as many rays graze each edge
    // within rounding (20 pixels of 57,600 here, the same flips, not a new error).
    adaptiveMaxOver2: 4e-4,
  },
  {
    name: 'torus-thin',
    what: "a torus whose tube is 1% of its radius, close up (the expanded quartic loses 13 of float32's 24 bits at r = 1e-2 R)",
    params: { time: 0, SCENE: 2, TORUS_RADII: [0.55, 0.0055], CAMERA_TARGET: [1.2, 0.545, 1.1], CAMERA_DISTANCE: 2.2 },
  },
  {
    name: 'torus-grazing',
    what: "the eye in the torus's equatorial plane: rays tangent to its inner and outer equators and grazing its top and bottom circles",
    params: {
      time: 0,
      SCENE: 2,
      TORUS_AXIS: [0, 1, 0],
      TORUS_CENTER: [1.2, 0.5, 1.1],
      CAMERA_TARGET: [1.2, 0.5, 1.1],
      CAMERA_ORBIT: [30, 0],
      CAMERA_DISTANCE: 2.5,
    },
  },
  {
    name: 'cylinder-down-the-axis',
    what: "looking straight down the cylinder's axis (rays along the axis: a = 0 in its quadratic, only the caps can be hit)",
    params: { time: 0, SCENE: 1, CAMERA_TARGET: [1.2, 0.65, 1.1], CAMERA_ORBIT: [30, 90], CAMERA_DISTANCE: 3 },
  },
  {
    name: 'grazing-light',
    what: 'a light 0.3 above the ground and far to the side (shadow rays nearly parallel to the ground: acne territory)',
    params: { time: 0, LIGHT_POSITION: [-10, 0.3, 2] },
  },
];

/** The reference renderer's view description for a hard view (controls split from page params). */
export function referenceView(view) {
  const { time = 0, mouse = [0, 0, 0, 0], ...controls } = view.params;
  const [width, height] = viewSize(view);
  return { width, height, time, mouse, controls };
}
