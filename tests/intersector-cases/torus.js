// The torus hard cases (see index.js for what each expectation means). The torus is where
// float32 closed forms fail: fake hits in the hole for near-axial rays, thin tubes losing
// 2 log2(R / r) bits in the quartic's constant term, eyes far away. Families of many rays each.

import { add, cross, normalize, scale, sub } from '../../src/reference/vec3.js';
import { aim, sequence, tilted } from './rays.js';

const torus = (name, ray, shape, expect, note, fields = {}) => ({
  name,
  kind: 'torus',
  ...ray,
  params: [...shape.center, ...shape.axis, shape.R, shape.r],
  expect,
  note,
  ...fields,
});

/** Torus with centre, axis (any length), core radius R and tube radius r. */
const shape = (center, axis, R, r) => ({ center, axis, R, r });
const T = shape([0, 0, 0], [0, 1, 0], 1, 0.25);
const at = (name, ray, expect, note, fields) => torus(name, ray, T, expect, note, fields);

/** Unit axis and two unit vectors across it. */
function frame(s) {
  const A = normalize(s.axis);
  const e1 = normalize(cross(A, Math.abs(A[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0]));
  return { A, e1, e2: cross(A, e1) };
}
/** The point of the surface at azimuth phi around the axis and angle theta around the tube. */
function surfacePoint(s, phi, theta) {
  const { A, e1, e2 } = frame(s);
  const radial = add(scale(e1, Math.cos(phi)), scale(e2, Math.sin(phi)));
  return add(s.center, add(scale(radial, s.R + s.r * Math.cos(theta)), scale(A, s.r * Math.sin(theta))));
}

export const TORUS_CASES = [
  at('torus: straight down the axis', { ro: [0, 5, 0], rd: [0, -1, 0] }, 'miss', 'through the hole: no root, no fake ring hit'),
  at('torus: straight down the axis, -0 components', { ro: [0, 5, 0], rd: [-0, -1, -0] }, 'miss', 'a = 0 exactly'),
  at('torus: straight down the axis from 1e4', { ro: [0, 1e4, 0], rd: [0, -1, 0] }, 'miss', 'far and axial'),
  at('torus: straight down through the tube', { ro: [1, 5, 0], rd: [0, -1, 0] }, 'hit', 't = 4.75, normal +axis'),
  at('torus: straight down at the inner equator', { ro: [0.75, 5, 0], rd: [0, -1, 0] }, 'agree', 'touches the inner equator'),
  at('torus: straight down at the outer equator', { ro: [0, 5, -1.25], rd: [0, -1, 0] }, 'agree', 'touches the outer equator'),
  at('torus: equatorial through the centre', { ro: [-5, 0, 0], rd: [1, 0, 0] }, 'hit', 'roots at 5 -+ (R +- r): the first at 3.75'),
  at('torus: equatorial from the centre', { ro: [0, 0, 0], rd: [1, 0, 0] }, 'hit', 'from the hole: t = R - r, normal towards the axis'),
  at('torus: equatorial from the centre, diagonal', { ro: [0, 0, 0], rd: normalize([-1, 0, 1]) }, 'hit', 't = 0.75'),
  at('torus: from the hole over the tube', { ro: [0, 0, 0], rd: normalize([1, 1, 0]) }, 'miss', 'out of the hole at 45 degrees'),
  at('torus: from the hole into the tube', { ro: [0, 0, 0], rd: normalize([1, 0.2, 0]) }, 'hit', 'the inner wall, shallow'),
  at('torus: origin on the core circle, up', { ro: [1, 0, 0], rd: [0, 1, 0] }, 'hit', 'inside the tube: t = r'),
  at('torus: origin on the core circle, along the ring', { ro: [1, 0, 0], rd: [0, 0, 1] }, 'hit', 'tangent to the core: t = 0.75'),
  at('torus: origin in the tube', { ro: [1.1, 0.1, -0.05], rd: normalize([-0.3, 0.5, 0.8]) }, 'hit', 'the far side of the tube'),
  at('torus: behind the ray', { ro: [0, 0, 5], rd: [0, 0, 1] }, 'miss', 'every root at t < 0'),
];

// Tangent to the outer equator, grazing the top circle: at and around tangency.
for (const offset of [0, 1e-3, 1e-5, -1e-5, -1e-3]) {
  TORUS_CASES.push(
    at(`torus: tangent to the outer equator, offset ${offset}`, { ro: [-5, 0, 1.25 + offset], rd: [1, 0, 0] }, 'agree', 'double root'),
    at(`torus: grazing the top circle, offset ${offset}`, { ro: [-5, 0.25 + offset, 0.5], rd: [1, 0, 0] }, 'agree', 'two double roots'),
  );
}
// Tangent to the inner equator at (0, 0, 0.75), whose outward normal points at the axis: tangent
// directions (cos a, sin a, 0). Above 30 degrees the ray touches the tube from the hole and leaves;
// below it, it runs inside the tube on both sides of the point, so the first root is the entry.
for (const degrees of [10, 25, 35, 60, 90]) {
  const a = (degrees * Math.PI) / 180;
  const dir = [Math.cos(a), Math.sin(a), 0];
  for (const offset of [0, 1e-5, -1e-5]) {
    TORUS_CASES.push(
      at(
        `torus: tangent to the inner equator at ${degrees} deg, offset ${offset}`,
        { ro: sub([0, 0, 0.75 + offset], scale(dir, 3)), rd: dir },
        'agree',
        degrees > 30 ? 'touches from the hole' : 'runs through the tube',
      ),
    );
  }
}
// Origin on the surface, into the tube and out of it.
{
  const p = surfacePoint(T, 0.7, 2.2);
  const n = normalize(sub(p, surfacePoint({ ...T, r: 0 }, 0.7, 0)));
  TORUS_CASES.push(
    at(
      'torus: origin on the surface, going in',
      { ro: p, rd: normalize(add(scale(n, -1), [0.1, 0.2, 0])) },
      'surface',
      'far side or t ~ 0',
    ),
    at('torus: origin on the surface, going out', { ro: p, rd: normalize(add(n, [0.2, 0, 0.1])) }, 'agree', 't ~ 0 or a miss'),
  );
}
// The horn torus (r = R): its hole closes to the centre point. Fat tori (r -> R): a tiny hole.
{
  const horn = shape([0, 0, 0], [0, 1, 0], 1, 1);
  const any = { checkNormal: false };
  TORUS_CASES.push(
    torus('torus horn: down the axis', { ro: [0, 5, 0], rd: [0, -1, 0] }, horn, 'agree', 'touches the centre only', any),
    torus('torus horn: beside the axis', { ro: [1e-3, 5, 0], rd: [0, -1, 0] }, horn, 'hit', 'enters at y ~ 0.045'),
  );
  const fat = shape([0, 0, 0], [0, 1, 0], 1, 0.999);
  for (const [offset, expect] of [
    [0, 'miss'],
    [5e-4, 'miss'],
    [2e-3, 'hit'],
  ]) {
    TORUS_CASES.push(
      torus(`torus r=0.999: down at ${offset} from the axis`, { ro: [offset, 5, 0], rd: [0, -1, 0] }, fat, expect, 'hole radius 1e-3'),
    );
  }
}

// ---- families ---------------------------------------------------------------------------------
// Rays from `distance` away, each aimed at a random surface point (half of them; a first hit
// that may be on another part) or at a random point of the bounding box (hits, misses, grazes).
function aimedFamily(label, s, distance, count, seed) {
  const random = sequence(seed);
  const { A, e1, e2 } = frame(s);
  const cases = [];
  for (let i = 0; i < count; i++) {
    const box = () =>
      add(
        s.center,
        add(
          scale(A, 1.2 * s.r * (2 * random() - 1)),
          add(scale(e1, 1.2 * (s.R + s.r) * (2 * random() - 1)), scale(e2, 1.2 * (s.R + s.r) * (2 * random() - 1))),
        ),
      );
    const target = i % 2 ? surfacePoint(s, 2 * Math.PI * random(), 2 * Math.PI * random()) : box();
    const from = add(s.center, scale(normalize([random() - 0.5, random() - 0.5, random() - 0.5]), distance));
    cases.push(torus(`${label} #${i}`, aim(from, target), s, 'agree', `${label}: must agree outside the rounding band`, { family: label }));
  }
  return cases;
}
/**
 * `count` cases of one family: each made by `make(random, frame, around)` from the family's own
 * random sequence, `around` a unit vector across the axis at a random angle (drawn first).
 */
function family(count, seed, s, make) {
  const random = sequence(seed);
  const f = frame(s);
  return Array.from({ length: count }, () => {
    const phi = 2 * Math.PI * random();
    return make(random, f, add(scale(f.e1, Math.cos(phi)), scale(f.e2, Math.sin(phi))));
  });
}
const member = (label, i, ray, s, expect, note) => torus(`${label} #${i}`, ray, s, expect, note, { family: label });

// Near-axial rays: from the axis at distance 2 to 1e3, down the axis tilted by `tilt(random)`,
// offset from the axis by up to `offset` R.
function axialFamily(label, s, tilt, offset, count, seed) {
  return family(count, seed, s, (random, { A, e1 }, across) => {
    const height = s.R * 10 ** (0.3 + 2.7 * random());
    const ro = add(s.center, add(scale(A, height), scale(across, offset * s.R * random())));
    const rd = tilted(scale(A, -1), tilt(random), normalize(cross(A, add(across, scale(e1, random())))));
    return { ro, rd };
  }).map((ray, i) => member(label, i, ray, s, 'agree', `${label}: must agree outside the rounding band`));
}
// Rays in the equatorial plane through the centre (tilted by up to 1e-6), from `distance`: the
// roots are at distance -+ (R + r) and -+ (R - r).
function equatorialFamily(label, s, distance, count, seed) {
  return family(count, seed, s, (random, { e1 }, around) => {
    const dir = tilted(around, 1e-6 * random(), e1);
    return { ro: sub(s.center, scale(dir, distance)), rd: dir };
  }).map((ray, i) => member(label, i, ray, s, 'hit', `${label}: roots at -+(R +- r)`));
}
// Origins inside the tube (or in the hole), random directions.
function originFamily(label, s, inTube, count, seed) {
  return family(count, seed, s, (random, { A }, radial) => {
    const theta = 2 * Math.PI * random();
    const depth = inTube ? 0.95 * s.r * Math.sqrt(random()) : 0.95 * (s.R - s.r) * Math.sqrt(random());
    const ro = inTube
      ? add(s.center, add(scale(radial, s.R + depth * Math.cos(theta)), scale(A, depth * Math.sin(theta))))
      : add(s.center, add(scale(radial, depth), scale(A, 2 * s.r * (random() - 0.5))));
    return { ro, rd: normalize([random() - 0.5, random() - 0.5, random() - 0.5]) };
  }).map((ray, i) => member(label, i, ray, s, inTube ? 'hit' : 'agree', label));
}

const thin2 = shape([0, 0, 0], [0, 1, 0], 1, 1e-2);
const thin3 = shape([0, 0, 0], [0, 1, 0], 1, 1e-3);
/** The families on which a plain closed-form quartic is shown to fail (tests/browser/intersectors.test.js). */
export const NAIVE_TORUS_FAMILIES = ['torus from 1e3', 'torus thin r=1e-3', 'torus near-axial, tilt 0 to 1e-6'];
TORUS_CASES.push(
  ...axialFamily('torus near-axial, tilt 0 to 1e-6', T, (random) => (random() < 0.2 ? 0 : 10 ** (-9 + 3 * random())), 0.5, 100, 21),
  ...axialFamily('torus near-axial, tilt 1e-6 to 0.3', T, (random) => 10 ** (-6 + 5.5 * random()), 0.2, 100, 22),
  ...axialFamily('torus near-axial, r=0.999', shape([0, 0, 0], [0, 1, 0], 1, 0.999), (random) => 10 ** (-9 + 6 * random()), 2e-3, 100, 23),
  ...equatorialFamily('torus equatorial through the centre from 1e3', T, 1e3, 50, 24),
  ...equatorialFamily('torus equatorial through the centre from 1e4', T, 1e4, 50, 25),
  ...aimedFamily('torus from 1e3', T, 1e3, 100, 26),
  ...aimedFamily('torus from 1e4', T, 1e4, 100, 27),
  ...aimedFamily('torus centred at 1e3, seen from 5', shape([1e3, -1e3, 500], [0, 1, 0], 1, 0.25), 5, 100, 28),
  ...aimedFamily('torus thin r=1e-2', thin2, 3, 100, 29),
  ...aimedFamily('torus thin r=1e-3', thin3, 3, 100, 30),
  ...aimedFamily('torus thin r=1e-3 from 1e3', thin3, 1e3, 100, 31),
  ...aimedFamily('torus fat r=0.9', shape([0, 0, 0], [0, 1, 0], 1, 0.9), 4, 100, 32),
  ...aimedFamily('torus fat r=0.999', shape([0, 0, 0], [0, 1, 0], 1, 0.999), 4, 100, 33),
  ...aimedFamily('torus any axis', shape([0.3, -0.2, 0.5], [1, 2, -0.5], 2, 0.5), 8, 100, 34),
  ...aimedFamily('torus large (R=1e3) from 2e3', shape([0, 0, 0], [0.2, 1, 0.1], 1e3, 100), 2e3, 100, 35),
  ...aimedFamily('torus small (R=1e-2) from 1', shape([0.5, 0.5, 0.5], [0, 0, 1], 1e-2, 2.5e-3), 1, 100, 36),
  ...originFamily('torus origins in the tube', T, true, 100, 37),
  ...originFamily('torus origins in the hole', T, false, 100, 38),
  ...originFamily('torus thin r=1e-3, origins in the tube', thin3, true, 50, 39),
);
