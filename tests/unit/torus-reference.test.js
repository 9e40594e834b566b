// The float64 torus (src/reference/torus.js) is the truth the GLSL torus is measured against,
// so it is checked here on its own, in Node (no browser), against a method that shares nothing
// with it: the first sign change of the exact distance to the tube, evaluated at world points
// ro + t rd, found by subdivision certified by a Lipschitz bound.
//
// g(p) = |(|p_perp| - R, y)| - r is a distance to a set (the core circle) minus r, so along a ray
// it changes by at most |rd| per unit of t. An interval [l, h] can hold a root only if
// |g(l)| + |g(h)| <= |rd| (h - l) (plus g's own rounding): every other interval is discarded, the
// rest halved, left half first, so the first interval with a sign change that survives holds the
// first root. Where g stays within its rounding of 0 without a sign change (a tangent ray touching
// to float64 precision), the touch is undecidable: such rays are counted and skipped.

import { describe, expect, it } from 'vitest';
import { intersectTorus } from '../../src/reference/torus.js';
import { add, addScaled, cross, dot, length, normalize, scale, sub } from '../../src/reference/vec3.js';
import { sequence, tilted } from '../intersector-cases/rays.js';

const EPS64 = 2 ** -53;

/** The exact signed distance of p to the tube, straight from the definition. */
function tubeDistance(p, torus) {
  const w = sub(p, torus.center);
  const y = dot(w, torus.A);
  return Math.hypot(length(addScaled(w, torus.A, -y)) - torus.R, y) - torus.r;
}

/**
 * @typedef {{center: number[], axis: number[], A: number[], R: number, r: number}} Torus
 *   A is the unit axis
 */

/**
 * The first t > 0 where the ray enters or leaves the tube: { t } (t < 0 for none), or
 * { touch: true } when a touch within rounding comes before any root.
 * @param {number[]} ro
 * @param {number[]} rd
 * @param {Torus} torus
 * @returns {{t?: number, touch?: boolean}}
 */
function certifiedFirstRoot(ro, rd, torus) {
  const g = (t) => tubeDistance(addScaled(ro, rd, t), torus);
  const lipschitz = length(rd) * (1 + 1e-12);
  const far = length(sub(ro, torus.center)) + torus.R + torus.r;
  const end = (far + torus.R) / length(rd);
  // g's rounding at world points of size up to |ro| + end: a few float64 roundings of those.
  const floor = 16 * EPS64 * (length(ro) + length(torus.center) + far + torus.R);
  const narrowest = 1e-13 * (far + torus.R + length(ro) + length(torus.center));
  const stack = [[0, end, g(0), g(end)]];
  let touch = -1;
  while (stack.length) {
    const [l, h, gl, gh] = stack.pop();
    const crosses = gl < 0 !== gh < 0;
    if (!crosses && Math.abs(gl) + Math.abs(gh) > lipschitz * (h - l) + 2 * floor) continue;
    if (h - l <= narrowest) {
      // No sign change this narrow: nothing, if g is above its rounding (an interval just short
      // of a root, which the Lipschitz bound cannot rule out); else g touches 0 within rounding,
      // which is a root only if a sign change follows at once (a root on a split point).
      if (!crosses) {
        if (touch < 0 && Math.max(Math.abs(gl), Math.abs(gh)) <= floor) touch = l;
        continue;
      }
      if (touch >= 0 && l - touch > 4 * narrowest) return { touch: true };
      let [a, b] = [l, h];
      for (let i = 0; i < 200 && b - a > 0; i++) {
        const m = 0.5 * (a + b);
        if (m <= a || m >= b) break;
        if (g(m) < 0 === gl < 0) a = m;
        else b = m;
      }
      return { t: 0.5 * (a + b) };
    }
    const m = 0.5 * (l + h);
    const gm = g(m);
    stack.push([m, h, gm, gh], [l, m, gl, gm]); // left half on top: searched first
  }
  return touch >= 0 ? { touch: true } : { t: -1 };
}

/** Random tori and rays of every kind the GLSL tests use, rounded to float32 or not. */
function* trials(count, seed) {
  const random = sequence(seed);
  const unit = () => normalize([random() - 0.5, random() - 0.5, random() - 0.5]);
  const tubes = [1e-3, 1e-2, 0.1, 0.25, 0.5, 0.9, 0.999, 1];
  for (let i = 0; i < count; i++) {
    const R = 10 ** (4 * random() - 2);
    const axis = scale(unit(), 0.5 + random());
    /** @type {Torus} */
    const torus = { center: scale(unit(), R * 10 ** (3 * random())), axis, A: normalize(axis), R, r: R * tubes[i % tubes.length] };
    const e1 = normalize(cross(torus.A, Math.abs(torus.A[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0]));
    const e2 = cross(torus.A, e1);
    const phi = 2 * Math.PI * random();
    const radial = add(scale(e1, Math.cos(phi)), scale(e2, Math.sin(phi)));
    const theta = 2 * Math.PI * random();
    const normal = add(scale(radial, Math.cos(theta)), scale(torus.A, Math.sin(theta)));
    const onSurface = add(torus.center, add(scale(radial, R), scale(normal, torus.r)));
    const distance = R * 10 ** (4 * random());
    let ro;
    let rd;
    const kind = i % 6;
    if (kind === 0) {
      // From afar, at a random point of the bounding box.
      ro = add(torus.center, scale(unit(), distance + R + torus.r));
      rd = normalize(sub(add(torus.center, scale(unit(), 1.2 * (R + torus.r) * random())), ro));
    } else if (kind === 1) {
      // At a surface point (it may be hidden behind another part).
      ro = add(onSurface, scale(unit(), distance));
      rd = normalize(sub(onSurface, ro));
    } else if (kind === 2) {
      // Tangent at a surface point, nudged off it along the normal by 1e-9 to 1e-3 of r either way.
      const along = normalize(cross(normal, unit()));
      const touch = add(onSurface, scale(normal, torus.r * (random() < 0.5 ? -1 : 1) * 10 ** (-9 + 6 * random())));
      ro = sub(touch, scale(along, distance));
      rd = along;
    } else if (kind === 3) {
      // Near-axial: down the axis from afar, tilted by 0 to 1e-1, off the axis by up to R.
      ro = add(torus.center, add(scale(torus.A, distance + torus.r), scale(radial, R * random() * random())));
      rd = tilted(scale(torus.A, -1), random() < 0.1 ? 0 : 10 ** (-9 + 8 * random()), normalize(cross(torus.A, unit())));
    } else if (kind === 4) {
      // Equatorial, through the centre, tilted by up to 1e-6.
      rd = tilted(radial, 1e-6 * random(), e1);
      ro = sub(torus.center, scale(rd, distance + R + torus.r));
    } else {
      // From inside the tube or the hole.
      const depth = random();
      const inHole = random() < 0.5 && torus.r < R; // the horn torus has no hole
      ro = inHole
        ? add(torus.center, scale(radial, (R - torus.r) * depth))
        : add(torus.center, add(scale(radial, R), scale(normal, torus.r * depth)));
      rd = unit();
    }
    const rounded = i % 2 === 0;
    const f32 = (v) => (rounded ? v.map(Math.fround) : v);
    yield { kind, torus: { ...torus, center: f32(torus.center) }, ro: f32(ro), rd: f32(rd) };
  }
}

describe('the float64 torus against a certified root search', () => {
  it('finds the same first root as Lipschitz-certified subdivision on 6,000 rays', () => {
    const KINDS = ['far, random', 'at a surface point', 'tangent', 'near-axial', 'equatorial', 'from inside'];
    const stats = KINDS.map(() => ({ rays: 0, hits: 0, touches: 0, worst: 0 }));
    const wrong = [];
    for (const { kind, torus, ro, rd } of trials(6000, 7)) {
      const s = stats[kind];
      s.rays++;
      const certified = certifiedFirstRoot(ro, rd, torus);
      if (certified.touch) {
        s.touches++;
        continue;
      }
      const got = intersectTorus(ro, rd, torus.center, torus.axis, torus.R, torus.r);
      const size = length(sub(ro, torus.center)) + torus.R + torus.r;
      if (got[0] > 0 !== certified.t > 0) {
        wrong.push(`${KINDS[kind]}: twin t=${got[0]}, certified t=${certified.t} (R=${torus.R}, r=${torus.r}, ro=${ro}, rd=${rd})`);
        continue;
      }
      if (!(certified.t > 0)) continue;
      s.hits++;
      // The root's own conditioning: g's slope there (tangent rays are ill-conditioned).
      const slope =
        Math.abs(
          tubeDistance(addScaled(ro, rd, certified.t + 1e-7 * size), torus) -
            tubeDistance(addScaled(ro, rd, certified.t - 1e-7 * size), torus),
        ) /
        (2e-7 * size);
      const error = Math.abs(got[0] - certified.t) / size;
      s.worst = Math.max(s.worst, error * Math.max(slope, 1e-3));
      if (error * Math.max(slope, 1e-3) > 1e-12)
        wrong.push(
          `${KINDS[kind]}: twin t=${got[0]}, certified t=${certified.t}, relative error ${error.toExponential(2)}, slope ${slope.toExponential(2)}`,
        );
      // The normal: the unit gradient of the distance, p minus the nearest point of the core circle.
      const p = addScaled(ro, rd, got[0]);
      const w = sub(p, torus.center);
      const core = add(torus.center, scale(normalize(addScaled(w, torus.A, -dot(w, torus.A))), torus.R));
      const angle = Math.acos(Math.min(1, dot(normalize(sub(p, core)), got.slice(1))));
      if (angle > 1e-6 + (1e-12 * size) / torus.r)
        wrong.push(
          `${KINDS[kind]}: normal off by ${angle} rad (n=${got.slice(1)}, want ${normalize(sub(p, core))}, R=${torus.R}, r=${torus.r}, t=${got[0]}, ro=${ro}, rd=${rd}, centre=${torus.center}, axis=${torus.axis})`,
        );
    }
    stats.forEach((s, k) =>
      console.log(
        `${KINDS[k]}: ${s.rays} rays, ${s.hits} hits, ${s.touches} undecidable touches, worst |t error| x |g'| ${s.worst.toExponential(2)} of the scale`,
      ),
    );
    expect(wrong.slice(0, 20)).toEqual([]);
    // Not vacuous: touches (nearly all from the tangent rays, made to touch) are a small share,
    // and most rays that decide something hit.
    expect(stats.reduce((n, s) => n + s.touches, 0)).toBeLessThan(300);
    expect(stats.reduce((n, s) => n + s.hits, 0)).toBeGreaterThan(3000);
  });

  // Both against roots known in closed form (R = 2, r = 0.5, axis y, centre c).
  it('both give the closed-form roots of axis-aligned rays', () => {
    const c = [3, -1, 2];
    const torus = { center: c, axis: [0, 1, 0], A: [0, 1, 0], R: 2, r: 0.5 };
    const known = [
      { what: 'equatorial through the centre from 1e4', ro: add(c, [-1e4, 0, 0]), rd: [1, 0, 0], t: 1e4 - 2.5 },
      { what: 'from the centre', ro: c, rd: [0, 0, 1], t: 1.5 },
      { what: 'down through the tube', ro: add(c, [0, 7, 2]), rd: [0, -1, 0], t: 6.5 },
      { what: 'from the core circle along it', ro: add(c, [2, 0, 0]), rd: [0, 0, 1], t: Math.sqrt(2.5 * 2.5 - 4) },
      { what: 'down the axis', ro: add(c, [0, 7, 0]), rd: [0, -1, 0], t: -1 },
    ];
    for (const k of known) {
      const twin = intersectTorus(k.ro, k.rd, c, torus.axis, torus.R, torus.r)[0];
      const certified = certifiedFirstRoot(k.ro, k.rd, torus).t ?? -1;
      /** @type {Array<[string, number]>} */
      const answers = [
        ['twin', twin],
        ['certified', certified],
      ];
      for (const [who, t] of answers) {
        if (k.t < 0) expect(t, `${who}: ${k.what}`).toBeLessThan(0);
        else expect(Math.abs(t - k.t), `${who}: ${k.what}`).toBeLessThan(1e-12 * (1 + k.t));
      }
    }
  });
});
