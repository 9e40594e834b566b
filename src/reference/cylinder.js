// The capped cylinder of shaders/raytrace.glsl in float64, the ground truth its GLSL tests
// measure against. Same API as the other twins (src/reference/intersectors.js): ray origin ro,
// unit direction rd; [t, nx, ny, nz] with t the nearest hit with t > 0 and n the unit outward
// normal; a miss has t < 0; a ray starting inside the solid hits its far side.
//
// Derivation. With unit axis A = (pb - pa) / H, a point w = p - pa has axial coordinate y = A.w
// and radial offset w_perp = w - y A. The side is |w_perp| = r for 0 <= y <= H, the caps the discs
// y = 0 and y = H of radius r. On the ray, with o = ro - pa split the same way, the side is
//   a t^2 + 2 b t + c = 0,  a = |rd_perp|^2,  b = o_perp.rd_perp,  c = |o_perp|^2 - r^2,
// whose discriminant b^2 - a c equals a (r^2 - |v|^2), v = o_perp - (b / a) rd_perp (the projected
// ray's closest point to the axis). Roots c / q and q / a, q = -(b + sign(b) sqrt(b^2 - a c)).
// A ray along the axis (a = 0) meets only the caps; one perpendicular to it (A.rd = 0) only the
// side. float64 would survive the textbook forms on most rays; the stable ones are used anyway, so
// truth stays truth on the hard cases (a ray nearly along the axis, a thin cylinder far away).

import { addScaled, dot, length, normalize, scale, sub } from './vec3.js';
import { MISS } from './intersectors.js';

/** Closed capped cylinder of radius `radius` from pa to pb. */
export function intersectCylinder(ro, rd, pa, pb, radius) {
  const axisVector = sub(pb, pa);
  const height = length(axisVector);
  const axis = scale(axisVector, 1 / height);
  const o = sub(ro, pa);
  const yo = dot(o, axis);
  const yd = dot(rd, axis);
  const oPerp = addScaled(o, axis, -yo);
  const dPerp = addScaled(rd, axis, -yd);

  let tBest = Infinity;
  let part = -1;
  const a = dot(dPerp, dPerp);
  if (a > 0) {
    const b = dot(oPerp, dPerp);
    const c = dot(oPerp, oPerp) - radius * radius;
    const closest = length(addScaled(oPerp, dPerp, -b / a));
    const disc = a * (radius + closest) * (radius - closest);
    if (disc >= 0) {
      const q = -(b + (b >= 0 ? 1 : -1) * Math.sqrt(disc));
      for (const t of [q !== 0 ? c / q : -1, q / a]) {
        const y = yo + t * yd;
        if (t > 0 && t < tBest && y >= 0 && y <= height) {
          tBest = t;
          part = 0;
        }
      }
    }
  }
  if (yd !== 0) {
    for (const [cap, y] of [
      [1, 0],
      [2, height],
    ]) {
      const t = (y - yo) / yd;
      const w = addScaled(oPerp, dPerp, t);
      if (t > 0 && t < tBest && dot(w, w) <= radius * radius) {
        tBest = t;
        part = cap;
      }
    }
  }
  if (part < 0) return MISS;
  if (part === 1) return [tBest, ...scale(axis, -1)];
  if (part === 2) return [tBest, ...axis];
  return [tBest, ...normalize(addScaled(oPerp, dPerp, tBest))];
}
