// The hard cases for the GLSL intersectors, as data (one file a primitive): one ray per case.
// Each case names the primitive and its parameters, the ray (origin, unit direction), what it
// must do, and why.
//
// Expectations:
//   'hit'     the float64 reference hits; the shader must hit, with t and n within tolerance
//   'miss'    the reference misses; the shader must miss (t < 0), with no NaN
//   'agree'   the shader must agree with the reference on hit or miss, except inside the
//             ambiguity band that its own rounding cannot resolve (`band`, see below)
//   'surface' the origin lies on the surface (to float32 rounding) and the ray heads into the
//             solid: either the far side, or a root within rounding of 0 (the surface itself)
//   'edge'    a hit on an edge or corner: t within tolerance, the normal must be one of the
//             faces' normals there (unit length, never zero, NaN or sqrt(2) long)
//
// Optional fields:
//   family       cases made as one group of many rays (e.g. a far sphere seen by 200 rays) share
//                a family name and are checked, and reported, as one test
//   checkNormal  false where no normal direction is right (at the cone's apex any finite unit
//                normal is): t and the normal's length are checked, its direction is not
//   normals      where two faces meet (a cylinder's rim), the normals that are each right
//   grazing      the angle (radians) at which the ray meets the surface, when it is so small that
//                the hit is ill-conditioned: t is held to K u S / sin(grazing) as well
//
// All numbers are rounded to float32 before either side sees them (tests/browser/intersectors.test.js),
// so the comparison measures the intersector's arithmetic, not the rounding of its inputs.

import { PLANE_CASES } from './plane.js';
import { SPHERE_CASES } from './sphere.js';
import { BOX_CASES } from './box.js';
import { CONE_CASES } from './cone.js';
import { CYLINDER_CASES } from './cylinder.js';
import { TORUS_CASES } from './torus.js';

export { FAR_SPHERE_FAMILY } from './sphere.js';
export { NAIVE_TORUS_FAMILIES } from './torus.js';

export const INTERSECTOR_CASES = [...PLANE_CASES, ...SPHERE_CASES, ...BOX_CASES, ...CONE_CASES, ...CYLINDER_CASES, ...TORUS_CASES];
