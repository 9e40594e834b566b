// The cone hard cases (see index.js for what each expectation means).

import { add, normalize, scale, sub } from '../../src/reference/vec3.js';
import { aim, tilted } from './rays.js';

const cone = (name, ray, pa, pb, ra, rb, expect, note) => ({ name, kind: 'cone', ...ray, params: [...pa, ...pb, ra, rb], expect, note });

// A pointed cone standing on the ground: base centre (0, 0, 0), radius 1, apex (0, 2, 0).
const C = { pa: [0, 0, 0], pb: [0, 2, 0], ra: 1, rb: 0 };
const coneCase = (name, ray, expect, note, fields = {}) => ({ ...cone(name, ray, C.pa, C.pb, C.ra, C.rb, expect, note), ...fields });
// At the apex the surface has no normal: any finite unit normal is right.
const AT_APEX = { checkNormal: false };
// A point on the generator line at angle phi, height fraction s (0 base rim, 1 apex).
const generatorPoint = (phi, s) => [(1 - s) * Math.cos(phi), 2 * s, (1 - s) * Math.sin(phi)];
// The generator direction (from the rim up to the apex) at angle phi.
const generatorDir = (phi) => normalize(sub(C.pb, generatorPoint(phi, 0)));

export const CONE_CASES = [
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
