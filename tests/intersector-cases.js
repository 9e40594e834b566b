// The hard cases for the GLSL intersectors, as data: one ray per case. Each case names the
// primitive and its parameters, the ray (origin, unit direction), what it must do, and why.
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
//
// All numbers are rounded to float32 before either side sees them (tests/intersectors.test.js),
// so the comparison measures the intersector's arithmetic, not the rounding of its inputs.

import { add, cross, dot, normalize, scale, sub } from '../src/reference/vec3.js';

/** A ray from `from` towards `to`. */
const aim = (from, to) => ({ ro: from, rd: normalize(sub(to, from)) });

/** A deterministic pseudo-random sequence in [0, 1), so the tables are the same every run. */
function sequence(seed) {
  let state = seed >>> 0;
  return () => {
    state = (Math.imul(state, 1664525) + 1013904223) >>> 0;
    return state / 4294967296;
  };
}

const plane = (name, ro, rd, expect, note, planeEq = [0, 1, 0, 0]) => ({ name, kind: 'plane', ro, rd, params: planeEq, expect, note });
const sphere = (name, ray, center, radius, expect, note) => ({ name, kind: 'sphere', ...ray, params: [...center, radius], expect, note });
const box = (name, ray, center, halfSize, expect, note) => ({ name, kind: 'box', ...ray, params: [...center, ...halfSize], expect, note });
const cone = (name, ray, pa, pb, ra, rb, expect, note) => ({ name, kind: 'cone', ...ray, params: [...pa, ...pb, ra, rb], expect, note });

// ---- plane ------------------------------------------------------------------------------------
const PLANE_CASES = [
  plane('plane: parallel ray above', [0, 1, 0], [1, 0, 0], 'miss', 'dot(n, rd) = 0: a miss, never 0/0 or inf'),
  plane(
    'plane: parallel ray on the plane',
    [0, 0, 0],
    [1, 0, 0],
    'miss',
    'origin on the plane and parallel: 0/0 in the textbook form; must be a clean miss',
  ),
  plane('plane: parallel ray on the plane, -0 direction', [3, 0, -2], [-1, -0, 0], 'miss', '-0 approach is still parallel'),
  plane('plane: nearly parallel, 1e-6', [0, 1, 0], normalize([1, -1e-6, 0]), 'hit', 't = 1e6: far but finite'),
  plane(
    'plane: nearly parallel, 1e-3',
    [0, 0.001, 0],
    normalize([1, -1e-3, 0]),
    'hit',
    'the eye a millimetre above the ground, looking at the horizon',
  ),
  plane(
    'plane: camera below, looking up',
    [0, -2, 0],
    normalize([0.3, 1, 0.2]),
    'hit',
    'hit from below: the plane normal as given (the shader flips it for shading)',
  ),
  plane('plane: camera below, looking down', [0, -2, 0], normalize([0.3, -1, 0.2]), 'miss', 'plane behind the ray'),
  plane('plane: straight down from high', [0.5, 1000, 0.5], [0, -1, 0], 'hit', 'perpendicular incidence'),
];

// ---- sphere -----------------------------------------------------------------------------------
function tangentRay(center, radius, impact, distance) {
  // A ray along +x passing at `impact` from the centre (offset in y), starting `distance` away.
  return { ro: [center[0] - distance, center[1] + impact, center[2]], rd: [1, 0, 0] };
}

const SPHERE_CASES = [
  sphere(
    'sphere: tangent, impact r(1 - 1e-6)',
    tangentRay([0, 0, 0], 1, 1 - 1e-6, 5),
    [0, 0, 0],
    1,
    'hit',
    'disc = 2e-6 r^2: the perpendicular form resolves it',
  ),
  sphere('sphere: tangent, impact r(1 + 1e-6)', tangentRay([0, 0, 0], 1, 1 + 1e-6, 5), [0, 0, 0], 1, 'miss', 'disc = -2e-6 r^2'),
  sphere('sphere: origin inside', { ro: [0.2, -0.1, 0.3], rd: normalize([1, 2, 3]) }, [0, 0, 0], 1, 'hit', 'hits the far side'),
  sphere('sphere: origin at the centre', { ro: [2, 3, 4], rd: normalize([-1, 1, 0.5]) }, [2, 3, 4], 1.5, 'hit', 't = r'),
  sphere('sphere: behind the ray', { ro: [0, 0, 5], rd: [0, 0, 1] }, [0, 0, 0], 1, 'miss', 'both roots negative'),
  sphere(
    'sphere: huge, seen from close by',
    aim([0, 1e4 + 2, 0], [0.3, 0, 0.2]),
    [0, 0, 0],
    1e4,
    'hit',
    'radius 1e4, eye 2 above its surface: c = |f|^2 - r^2 cancels, the root c/q keeps it',
  ),
  sphere(
    'sphere: huge, grazing from close by',
    { ro: [0, 1e4 + 2, 0], rd: normalize([1, -0.0005, 0]) },
    [0, 0, 0],
    1e4,
    'agree',
    'a nearly tangent ray on a huge sphere',
  ),
];

// Origin on the surface: from a point on the sphere, one ray going out (miss) and one going in
// (hit the far side). Both rounded to float32, so "on" means within an ulp.
{
  const center = [0.3, 1.2, -0.4];
  const radius = 0.9;
  const n = normalize([0.4, 0.5, -0.2]);
  const p = add(center, scale(n, radius));
  SPHERE_CASES.push(
    sphere(
      'sphere: origin on the surface, going out',
      { ro: p, rd: normalize(add(n, [0.2, 0, 0.1])) },
      center,
      radius,
      'agree',
      'leaving the solid: t ~ 0 or a miss; a t of a few ulps may come either way, never a far hit',
    ),
    sphere(
      'sphere: origin on the surface, going in',
      { ro: p, rd: scale(n, -1) },
      center,
      radius,
      'surface',
      'through the centre: t = 2r, or the surface itself within rounding',
    ),
  );
}

// Far and tiny spheres, many rays each: the decisions the textbook b^2 - c gets wrong (about one
// in six for a unit sphere seen from 1e4) must all be right, outside the rounding band.
function sphereFamily(label, center, radius, distance, count, seed) {
  const random = sequence(seed);
  const cases = [];
  for (let i = 0; i < count; i++) {
    // Aim at a point in the plane through the centre, at up to 1.5 radii from it.
    const angle = 2 * Math.PI * random();
    const offset = 1.5 * radius * Math.sqrt(random());
    const target = add(center, [0, offset * Math.cos(angle), offset * Math.sin(angle)]);
    const from = add(center, [-distance, 0.1 * distance * (random() - 0.5), 0.1 * distance * (random() - 0.5)]);
    cases.push({
      ...sphere(`${label} #${i}`, aim(from, target), center, radius, 'agree', `${label}: hit/miss must agree outside the rounding band`),
      family: label,
    });
  }
  return cases;
}
/** The family of a unit sphere seen from 1e4, on which the textbook discriminant fails. */
export const FAR_SPHERE_FAMILY = 'sphere r=1 from 1e4';
SPHERE_CASES.push(
  ...sphereFamily(FAR_SPHERE_FAMILY, [3, 1, -2], 1, 1e4, 200, 1),
  ...sphereFamily('sphere r=1e-3 from 1e3', [0.5, 0.25, 0], 1e-3, 1e3, 200, 2),
);

// ---- box --------------------------------------------------------------------------------------
const B = { center: [0, 0, 0], half: [1, 1, 1] };
const BOX_CASES = [
  box(
    'box: axis ray with +0 components',
    { ro: [-5, 0.5, 0.25], rd: [1, 0, 0] },
    B.center,
    B.half,
    'hit',
    'rd.y = rd.z = +0: inside those slabs for all t',
  ),
  box(
    'box: axis ray with -0 components',
    { ro: [5, 0.5, 0.25], rd: [-1, -0, -0] },
    B.center,
    B.half,
    'hit',
    '-0 must act as 0, not as -inf slabs',
  ),
  box('box: zero component, outside that slab', { ro: [-5, 1.5, 0], rd: [1, 0, 0] }, B.center, B.half, 'miss', 'never inside the y slab'),
  box(
    'box: origin on a slab plane, zero component',
    { ro: [-5, 1, 0], rd: [1, 0, 0] },
    B.center,
    B.half,
    'hit',
    'y = 1 exactly and rd.y = 0: (1 - 1) * inf = NaN in the naive form; the ray lies in the top face plane and the closed box counts it',
  ),
  box(
    'box: ray lying in a face plane',
    { ro: [-5, 0.3, 1], rd: [1, 0, -0] },
    B.center,
    B.half,
    'hit',
    'grazes along the z = 1 face: enters through the x = -1 face at its edge',
  ),
  box(
    'box: exact edge hit',
    aim([-3, -3, 0.2], [-1, -1, 0.2]),
    B.center,
    B.half,
    'edge',
    'hits the edge x = y = -1: the normal is one face normal, unit length',
  ),
  box(
    'box: exact corner hit',
    aim([-4, -4, -4], [-1, -1, -1]),
    B.center,
    B.half,
    'edge',
    'hits the corner: one face normal, never sqrt(2) or sqrt(3) long',
  ),
  box(
    'box: origin inside',
    { ro: [0.1, -0.2, 0.3], rd: normalize([0.3, 0.5, -0.8]) },
    B.center,
    B.half,
    'hit',
    'hits the far side with the exit face normal',
  ),
  box('box: origin inside, axis ray', { ro: [0.1, -0.2, 0.3], rd: [0, 0, -1] }, B.center, B.half, 'hit', 'exit through z = -1'),
  box('box: behind the ray', { ro: [0, 0, 5], rd: [0, 0, 1] }, B.center, B.half, 'miss', 'the whole box at t < 0'),
  box('box: far, thin', aim([1e3, 2e2, -3e2], [0.49, 0.0, 0.01]), [0.5, 0, 0], [0.01, 0.5, 0.5], 'hit', 'a thin slab seen from 1e3'),
];

// ---- cone -------------------------------------------------------------------------------------
// A pointed cone standing on the ground: base centre (0, 0, 0), radius 1, apex (0, 2, 0).
const C = { pa: [0, 0, 0], pb: [0, 2, 0], ra: 1, rb: 0 };
const coneCase = (name, ray, expect, note, fields = {}) => ({ ...cone(name, ray, C.pa, C.pb, C.ra, C.rb, expect, note), ...fields });
// At the apex the surface has no normal: any finite unit normal is right.
const AT_APEX = { checkNormal: false };
// A point on the generator line at angle phi, height fraction s (0 base rim, 1 apex).
const generatorPoint = (phi, s) => [(1 - s) * Math.cos(phi), 2 * s, (1 - s) * Math.sin(phi)];
// The generator direction (from the rim up to the apex) at angle phi.
const generatorDir = (phi) => normalize(sub(C.pb, generatorPoint(phi, 0)));

function tilted(dir, radians, axis) {
  // Rotate dir by `radians` about `axis` (unit), Rodrigues' formula.
  const c = Math.cos(radians);
  const s = Math.sin(radians);
  const k = axis;
  const kxv = cross(k, dir);
  const kdv = dot(k, dir);
  return normalize(dir.map((x, i) => x * c + kxv[i] * s + k[i] * kdv * (1 - c)));
}

const CONE_CASES = [
  coneCase(
    'cone: straight down at the apex',
    { ro: [0, 5, 0], rd: [0, -1, 0] },
    'hit',
    'the apex itself: t = 3, the normal must be finite and unit (0/0 in the gradient form)',
    AT_APEX,
  ),
  coneCase(
    'cone: through the apex, slanted',
    aim([2, 4, 1], [0, 2, 0]),
    'agree',
    'aimed at the apex from above the side: touches the cone at the apex only',
    AT_APEX,
  ),
  coneCase(
    'cone: through the apex from outside, into the side',
    aim([-3, 2.5, 0], [0, 2, 0]),
    'agree',
    'enters exactly at the apex',
    AT_APEX,
  ),
  coneCase('cone: perpendicular to the axis', { ro: [-4, 0.7, 0.2], rd: [1, 0, 0] }, 'hit', 'horizontal ray through the side'),
  coneCase('cone: perpendicular, tangent', { ro: [-4, 1, 0.5], rd: [1, 0, 0] }, 'agree', 'radius at y = 1 is 0.5: grazes the side'),
  coneCase(
    'cone: along the rim, side then cap',
    aim([-3, 0, 0.2], [0, 0, 0.2]),
    'agree',
    'in the base plane: the seam between side and cap',
  ),
  coneCase('cone: base cap from below', { ro: [0.3, -2, 0.1], rd: [0, 1, 0] }, 'hit', 'closed base: normal -axis'),
  coneCase('cone: origin inside', { ro: [0.1, 0.5, -0.1], rd: normalize([0.2, 0.3, 0.9]) }, 'hit', 'far side from inside'),
  coneCase(
    'cone: would hit the mirror nappe',
    aim([0.3, 5, 0], [0.6, 3.2, 0]),
    'miss',
    'the ray crosses the upper (mirror) nappe above the apex and passes beside the cone',
  ),
  coneCase(
    'cone: mirror nappe, then the real cone',
    aim([1.5, 4, 0], [-0.1, 0.5, 0]),
    'hit',
    'crosses the mirror nappe first: the first accepted root must be on the real cone',
  ),
];

// Parallel to a generator line: the quadratic's leading coefficient is 0 (or nearly). Rays start
// outside, offset from the generator line, and head along (or nearly along) it.
for (const [label, radians] of [
  ['exactly parallel', 0],
  ['tilted 1e-7', 1e-7],
  ['tilted 1e-6', 1e-6],
  ['tilted 1e-5', 1e-5],
]) {
  const phi = 0.7;
  const along = generatorDir(phi);
  const side = [-Math.sin(phi), 0, Math.cos(phi)];
  const dir = tilted(along, radians, side);
  // Start outside the cone, below and out from the rim, so the ray meets the side from outside.
  const start = sub(add(generatorPoint(phi, 0.3), scale([Math.cos(phi), 0, Math.sin(phi)], 0.2)), scale(along, 3));
  CONE_CASES.push(
    coneCase(
      `cone: parallel to a generator, ${label}`,
      { ro: start, rd: dir },
      'agree',
      'a -> 0: the root must come from c/q, not from a division by a',
    ),
  );
  const inside = sub(generatorPoint(phi, 0.3), scale([Math.cos(phi), 0, Math.sin(phi)], 0.1));
  CONE_CASES.push(
    coneCase(
      `cone: parallel to a generator from inside, ${label}`,
      { ro: inside, rd: dir },
      'hit',
      'from inside, running up along the side: the far side is at the apex region',
    ),
  );
}
// Grazing rays: nearly tangent to the side at mid height.
for (const offset of [1e-3, 1e-5, -1e-5, -1e-3]) {
  const r = 0.5 + offset; // the side's radius at y = 1 is 0.5
  CONE_CASES.push(
    coneCase(
      `cone: grazing at y = 1, offset ${offset}`,
      { ro: [-4, 1, r], rd: [1, 0, 0] },
      'agree',
      'ill-conditioned near tangency: must agree outside the band',
    ),
  );
}

export const INTERSECTOR_CASES = [...PLANE_CASES, ...SPHERE_CASES, ...BOX_CASES, ...CONE_CASES];
