// The cylinder hard cases (see index.js for what each expectation means).

import { add, cross, normalize, scale, sub } from '../../src/reference/vec3.js';
import { aim, sequence, tilted } from './rays.js';

const cylinder = (name, ray, pa, pb, radius, expect, note, fields = {}) => ({
  name,
  kind: 'cylinder',
  ...ray,
  params: [...pa, ...pb, radius],
  expect,
  note,
  ...fields,
});

// An upright cylinder: base centre (0, 0, 0), top (0, 2, 0), radius 1.
const Y = { pa: [0, 0, 0], pb: [0, 2, 0], r: 1 };
const upright = (name, ray, expect, note) => cylinder(name, ray, Y.pa, Y.pb, Y.r, expect, note);

export const CYLINDER_CASES = [
  upright('cylinder: along the axis, inside the radius', { ro: [0.3, 5, 0.2], rd: [0, -1, 0] }, 'hit', 'a = 0: the top cap, t = 3'),
  upright('cylinder: along the axis from below', { ro: [-0.4, -3, 0.1], rd: [0, 1, 0] }, 'hit', 'a = 0: the base cap, normal -axis'),
  upright('cylinder: along the axis, -0 components', { ro: [0.3, 5, 0.2], rd: [-0, -1, -0] }, 'hit', '-0 must act as 0'),
  upright('cylinder: along the axis, outside the radius', { ro: [1.5, 5, 0], rd: [0, -1, 0] }, 'miss', 'a = 0 and c > 0: no root, no 0/0'),
  upright(
    'cylinder: along the axis, on the radius',
    { ro: [1, 5, 0], rd: [0, -1, 0] },
    'agree',
    'the ray lies in the side: it meets the closed solid at the top rim',
  ),
  upright('cylinder: along the axis, inside', { ro: [0.2, 1.2, -0.5], rd: [0, -1, 0] }, 'hit', 'from inside along the axis: the base cap'),
  upright('cylinder: perpendicular to the axis', { ro: [-5, 0.7, 0.2], rd: [1, 0, 0] }, 'hit', 'A.rd = 0: the side only'),
  upright(
    'cylinder: perpendicular, in the base plane',
    { ro: [-5, 0, 0.2], rd: [1, 0, 0] },
    'hit',
    'y = 0 on the whole ray: the side at its rim',
  ),
  upright('cylinder: perpendicular, in the top plane', { ro: [-5, 2, -0.3], rd: [1, 0, 0] }, 'hit', 'y = H on the whole ray'),
  upright('cylinder: perpendicular, just above the top', { ro: [-5, 2 + 1e-6, 0], rd: [1, 0, 0] }, 'miss', 'no cap plane crossing: a miss'),
  upright('cylinder: perpendicular, from inside', { ro: [0.1, 0.5, 0.2], rd: [0, 0, -1] }, 'hit', 'the far side, t = 1.2 - ...'),
  {
    ...upright(
      'cylinder: on the top rim, head on',
      aim([-3, 4, 0], [-1, 2, 0]),
      'hit',
      'enters exactly at the rim: the side root sits at y = H, the cap hit at |w| = r; one of them must be taken',
    ),
    normals: [
      [0, 1, 0],
      [-1, 0, 0],
    ],
  },
  {
    ...upright('cylinder: on the base rim, head on', aim([2, -2, 1], [0.6, 0, 0.8]), 'hit', 'the base rim from below and outside'),
    normals: [
      [0, -1, 0],
      [0.6, 0, 0.8],
    ],
  },
  upright('cylinder: rim, grazing in the top plane', { ro: [-5, 2, 1], rd: [1, 0, 0] }, 'agree', 'tangent to the rim circle'),
  upright('cylinder: origin inside', { ro: [0.1, 0.5, -0.1], rd: normalize([0.2, 0.3, 0.9]) }, 'hit', 'the far side from inside'),
  upright('cylinder: behind the ray', { ro: [0, 1, 5], rd: [0, 0, 1] }, 'miss', 'both roots negative'),
];

// Tangent to the side, at and around the tangent line.
for (const offset of [0, 1e-3, 1e-5, -1e-5, -1e-3]) {
  CYLINDER_CASES.push(
    upright(`cylinder: tangent to the side, offset ${offset}`, { ro: [-5, 1, 1 + offset], rd: [1, 0, 0] }, 'agree', 'disc ~ 0'),
  );
}

// Nearly along the axis: a = |rd_perp|^2 = sin^2(tilt), where 1 - (A.rd)^2 would be rounding noise.
for (const tilt of [1e-7, 1e-6, 1e-4]) {
  // From just outside the radius, above the top, leaning in: it crosses the side below the rim.
  // (Starting tilt outside the radius, it reaches it after a distance of about 1, at y ~ 1.5.)
  const dir = tilted([0, -1, 0], tilt, [0, 0, -1]); // leaning towards -x
  const start = [1 + tilt, 2.5, 0];
  CYLINDER_CASES.push(
    {
      ...upright(
        `cylinder: nearly along the axis into the side, tilt ${tilt}`,
        { ro: start, rd: dir },
        'agree',
        'a ~ tilt^2: the side at t ~ 1, below the rim',
      ),
      grazing: tilt,
    },
    upright(
      `cylinder: nearly along the axis from inside, tilt ${tilt}`,
      { ro: [0.5, 1.5, 0.2], rd: tilted([0, -1, 0], tilt, normalize([1, 0, 1])) },
      'hit',
      'from inside, nearly along the axis: the base cap',
    ),
  );
}

// Origin on the surface: on the side and on the top cap, into the solid and out of it.
{
  const onSide = [Math.cos(0.4), 1.3, Math.sin(0.4)];
  const inward = [-Math.cos(0.4), 0, -Math.sin(0.4)];
  CYLINDER_CASES.push(
    upright(
      'cylinder: origin on the side, going in',
      { ro: onSide, rd: normalize(add(inward, [0, 0.3, 0.1])) },
      'surface',
      'far side, or t ~ 0',
    ),
    upright(
      'cylinder: origin on the side, going out',
      { ro: onSide, rd: normalize(sub([0, 0.3, 0.1], inward)) },
      'agree',
      't ~ 0 or a miss',
    ),
    upright('cylinder: origin on the top cap, going in', { ro: [0.3, 2, -0.2], rd: normalize([0.1, -1, 0.2]) }, 'surface', 'the far side'),
  );
}

// Families of rays, each aimed at a random point near the cylinder (up to a quarter of its height
// past either cap and 1.5 radii from the axis, so thin shapes are hit too), from random points at
// `distance` from its midpoint.
function cylinderFamily(label, pa, pb, radius, distance, count, seed) {
  const random = sequence(seed);
  const axis = normalize(sub(pb, pa));
  const across = [normalize(cross(axis, Math.abs(axis[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0]))];
  across.push(cross(axis, across[0]));
  const cases = [];
  for (let i = 0; i < count; i++) {
    const angle = 2 * Math.PI * random();
    const offset = 1.5 * radius * Math.sqrt(random());
    const along = add(pa, scale(sub(pb, pa), 1.5 * random() - 0.25));
    const target = add(along, add(scale(across[0], offset * Math.cos(angle)), scale(across[1], offset * Math.sin(angle))));
    const from = add(scale(add(pa, pb), 0.5), scale(normalize([random() - 0.5, random() - 0.5, random() - 0.5]), distance));
    cases.push(
      cylinder(`${label} #${i}`, aim(from, target), pa, pb, radius, 'agree', `${label}: must agree outside the rounding band`, {
        family: label,
      }),
    );
  }
  return cases;
}
{
  const axis = normalize([1, 2, -0.5]);
  const side = normalize(cross(axis, [0, 0, 1]));
  const pa = [0.3, -0.2, 0.5];
  CYLINDER_CASES.push(
    ...cylinderFamily('cylinder r=1 from 1e4', [0, 0, 0], [0, 2, 0], 1, 1e4, 100, 11),
    ...cylinderFamily('cylinder at 1e3, seen from 10', [1e3, -1e3, 500], [1e3, -998, 500], 1, 10, 100, 12),
    ...cylinderFamily('cylinder thin and long (r=1e-3, H=100)', [0, -50, 0], [0, 50, 0], 1e-3, 10, 100, 13),
    ...cylinderFamily('cylinder with an arbitrary axis', pa, add(pa, scale(axis, 3)), 0.7, 6, 100, 14),
    ...cylinderFamily('cylinder flat disc (H=1e-3)', [0, 0, 0], add([0, 0, 0], scale(tilted(axis, 0.3, side), 1e-3)), 2, 5, 100, 15),
  );
}
