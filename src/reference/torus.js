// The torus of shaders/raytrace.glsl in float64, the ground truth its GLSL tests measure against;
// checked on its own against an independent root finder in tests/unit/torus-reference.test.js. Same
// API as the other twins: [t, nx, ny, nz], the nearest hit with t > 0 and the unit outward normal;
// a miss has t < 0; a ray starting inside the tube hits its far side.
//
// Derivation. In units of R, in the axis frame (unit axis A, y the axial coordinate, rho the
// distance from the axis), the solid torus is F(p) = (rho - 1)^2 + y^2 - k^2 <= 0, k = r / R. On
// a ray (|rd| = 1): y(t) = yo + yd t and rho(t)^2 = m2 + a (t - tc)^2, where a = |rd_perp|^2,
// tc = -(o_perp.rd_perp) / a is the closest approach to the axis and m2 the squared distance
// there. Since |p|^2 = rho^2 + y^2 is a quadratic with leading coefficient |rd|^2 = 1,
//   F(t) = |p(t)|^2 + 1 - k^2 - 2 rho(t),   F''(t) = 2 - 2 rho''(t) = 2 - 2 a m2 / rho(t)^3,
// so F is concave exactly where rho(t)^3 < a m2: an interval tc +- s, s = sqrt((rho_b^2 - m2) / a)
// with rho_b = (a m2)^(1/3), empty when m2 >= a^2. F' therefore rises on (-inf, tc - s], falls on
// [tc - s, tc + s] and rises on [tc + s, inf): one zero of F' at most on each piece. Those (at most
// three) critical points split the ray into four gaps on each of which F is monotone, so each
// gap holds at most one root, where F changes sign. This bounds the count (4) the quartic allows
// and finds every root without forming the quartic.
//
// Here each zero of F' and each root is found by bisection to full float64 precision (slow, and
// immune to the convergence questions of the shader's Newton iterations); roots are sign changes
// of g = |(rho - 1, y)| - k, the signed distance to the tube (same sign as F).

import { addScaled, cross, dot, length, normalize, scale, sub } from './vec3.js';
import { MISS } from './intersectors.js';

/** The parameter in [lo, hi] where a monotone f changes sign (to full precision). */
function bisect(f, lo, hi, insideLo) {
  let l = lo;
  let h = hi;
  for (let i = 0; i < 2200; i++) {
    const m = 0.5 * (l + h);
    if (m <= l || m >= h) break;
    if (f(m) < 0 === insideLo) l = m;
    else h = m;
  }
  return 0.5 * (l + h);
}

/**
 * The zero of F' on a piece where it is monotone (rising when `rises`), or the end of the piece
 * F' points past when it keeps one sign there. The tests are strict: where the ray crosses the
 * axis (m2 = 0), rho = |a|^(1/2) |t - tc| has a kink at tc, F' jumps there and reads 0 at tc
 * itself, which says nothing about either side; bisection finds the sign change instead.
 */
function criticalPoint(dF, lo, hi, rises) {
  const s = rises ? 1 : -1;
  if (s * dF(lo) > 0) return lo;
  if (s * dF(hi) < 0) return hi;
  return bisect((t) => s * dF(t), lo, hi, true);
}

/** The torus about `center` and `axis` (need not be unit), core radius R, tube radius r <= R. */
export function intersectTorus(ro, rd, center, axis, majorRadius, minorRadius) {
  const A = normalize(axis);
  const R = majorRadius;
  const k = minorRadius / R;
  const o = scale(sub(ro, center), 1 / R);
  const yo = dot(o, A);
  const yd = dot(rd, A);
  const oPerp = addScaled(o, A, -yo);
  const dPerp = addScaled(rd, A, -yd);
  const a = dot(dPerp, dPerp);
  const tc = a > 0 ? -dot(oPerp, dPerp) / a : 0;
  const m2 = dot(addScaled(oPerp, dPerp, tc), addScaled(oPerp, dPerp, tc));
  const rhoAt = (t) => Math.sqrt(m2 + a * (t - tc) * (t - tc));
  const g = (t) => Math.hypot(rhoAt(t) - 1, yo + yd * t) - k;
  const dF = (t) => {
    const rho = rhoAt(t);
    return yd * (yo + yd * t) + (rho > 0 ? (a * (t - tc) * (rho - 1)) / rho : 0);
  };

  // Roots lie inside the bounding sphere (radius 1 + k): its chord, widened past float64 rounding.
  // rd is unit only to the rounding of its inputs (float32 in the tests: 6e-8), which the chord
  // of a far ray (t ~ 1e4) would multiply: every formula here holds for any |rd|.
  const dd = dot(rd, rd);
  const bo = dot(o, rd) / dd;
  const off = addScaled(o, rd, -bo);
  const h2 = ((1 + k) * (1 + k) - dot(off, off)) / dd;
  if (h2 < 0) return MISS;
  const slack = 1e-12 * (1 + k + Math.abs(bo));
  const lo = Math.max(0, -bo - Math.sqrt(h2) - slack);
  const hi = -bo + Math.sqrt(h2) + slack;
  if (!(lo < hi)) return MISS;

  // F''/2 = |rd|^2 - a m2 / rho^3 for any |rd|.
  const rhoBend = Math.cbrt((a * m2) / dd);
  const spread = a > 0 ? Math.sqrt(Math.max(rhoBend * rhoBend - m2, 0) / a) : 0;
  const clip = (t) => Math.min(Math.max(t, lo), hi);
  const i1 = clip(tc - spread);
  const i2 = clip(tc + spread);
  const c1 = criticalPoint(dF, lo, i1, true);
  const c2 = criticalPoint(dF, i1, i2, false);
  const c3 = criticalPoint(dF, i2, hi, true);

  const ends = [lo, c1, c2, c3, hi];
  let t = -1;
  for (let i = 0; i < 4 && t < 0; i++) {
    const insideLeft = g(ends[i]) < 0;
    if (insideLeft === g(ends[i + 1]) < 0) continue;
    const root = bisect(g, ends[i], ends[i + 1], insideLeft);
    if (root > 0) t = root;
  }
  if (t < 0) return MISS;

  // The normal: the gradient of g, (rho - 1) times the radial unit vector plus y times the axis.
  // The radial direction is 0/0 only on the axis (the horn torus's centre): the one facing the ray.
  const pPerp = addScaled(oPerp, dPerp, t);
  let radial;
  if (length(pPerp) > 1e-12) radial = normalize(pPerp);
  else if (a > 0) radial = scale(normalize(dPerp), -1);
  else radial = normalize(cross(A, Math.abs(A[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0]));
  const n = normalize(addScaled(scale(radial, rhoAt(t) - 1), A, yo + yd * t));
  return [t * R, ...n];
}
