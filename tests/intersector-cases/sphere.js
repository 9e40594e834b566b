// The sphere hard cases (see index.js for what each expectation means).

import { add, normalize, scale } from '../../src/reference/vec3.js';
import { aim, sequence } from './rays.js';

const sphere = (name, ray, center, radius, expect, note) => ({ name, kind: 'sphere', ...ray, params: [...center, radius], expect, note });

function tangentRay(center, radius, impact, distance) {
  // A ray along +x passing at `impact` from the centre (offset in y), starting `distance` away.
  return { ro: [center[0] - distance, center[1] + impact, center[2]], rd: [1, 0, 0] };
}

export const SPHERE_CASES = [
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
