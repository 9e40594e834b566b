// The four intersectors of shaders/raytrace.glsl, in float64: the ground truth the GLSL tests
// and the reference renderer measure the shader against. Same API: ray origin ro, unit
// direction rd; the result is [t, nx, ny, nz] with t the nearest hit with t > 0 and n the unit
// outward normal; a miss has t < 0; a ray starting inside a closed solid hits its far side.
//
// float64 carries 29 more bits than the shader, so these follow the plain derivations; where a
// form is still ill-conditioned in float64 (the cone parallel to a generator line), the same
// stable form as the shader is used, so truth stays truth on the hard cases.

import { dot, sub, addScaled, scale, normalize, length, cross } from './vec3.js';

export const MISS = Object.freeze([-1, 0, 0, 0]);

/** Plane dot(plane.xyz, p) + plane.w = 0 with unit normal plane.xyz; a parallel ray misses. */
export function intersectPlane(ro, rd, plane) {
  const n = [plane[0], plane[1], plane[2]];
  const approach = dot(n, rd);
  if (approach === 0) return MISS;
  const t = -(dot(n, ro) + plane[3]) / approach;
  return t > 0 && Number.isFinite(t) ? [t, ...n] : MISS;
}

/** Sphere |p - center| = radius: discriminant from the ray's perpendicular offset, stable roots. */
export function intersectSphere(ro, rd, center, radius) {
  const f = sub(ro, center);
  const b = dot(f, rd);
  const offAxis = addScaled(f, rd, -b);
  const disc = radius * radius - dot(offAxis, offAxis);
  if (disc < 0) return MISS;
  const q = -b - (b >= 0 ? 1 : -1) * Math.sqrt(disc);
  if (q === 0) return MISS;
  const c = dot(f, f) - radius * radius;
  const t0 = Math.min(c / q, q);
  const t1 = Math.max(c / q, q);
  const t = t0 > 0 ? t0 : t1;
  if (!(t > 0)) return MISS;
  return [t, ...normalize(addScaled(f, rd, t))];
}

/** Axis-aligned box by slabs; a zero direction component means inside that slab always or never. */
export function intersectBox(ro, rd, center, halfSize) {
  const o = sub(ro, center);
  let tEnter = -Infinity;
  let tExit = Infinity;
  let enterAxis = 0;
  let exitAxis = 0;
  for (let axis = 0; axis < 3; axis++) {
    if (rd[axis] === 0) {
      if (Math.abs(o[axis]) > halfSize[axis]) return MISS;
      continue;
    }
    const tA = (-halfSize[axis] - o[axis]) / rd[axis];
    const tB = (halfSize[axis] - o[axis]) / rd[axis];
    const tIn = Math.min(tA, tB);
    const tOut = Math.max(tA, tB);
    if (tIn > tEnter) {
      tEnter = tIn;
      enterAxis = axis;
    }
    if (tOut < tExit) {
      tExit = tOut;
      exitAxis = axis;
    }
  }
  if (tEnter > tExit || tExit <= 0) return MISS;
  const n = [0, 0, 0];
  if (tEnter > 0) {
    n[enterAxis] = rd[enterAxis] > 0 ? -1 : 1;
    return [tEnter, ...n];
  }
  n[exitAxis] = rd[exitAxis] > 0 ? 1 : -1;
  return [tExit, ...n];
}

/**
 * Closed capped cone from pa (radius ra) to pb (radius rb). Side: |w_perp|^2 = (ra + k y)^2 for
 * 0 <= y <= H (the range rejects the mirror nappe); roots c/q and q/a of a t^2 + 2bt + c = 0 with
 * q = -(b + sign(b) sqrt(b^2 - ac)), which stays exact as a -> 0 (ray parallel to a generator).
 */
export function intersectCone(ro, rd, pa, pb, ra, rb) {
  const axisVector = sub(pb, pa);
  const height = length(axisVector);
  const axis = scale(axisVector, 1 / height);
  const slope = (rb - ra) / height;
  const o = sub(ro, pa);
  const yo = dot(o, axis);
  const yd = dot(rd, axis);
  const oPerp = addScaled(o, axis, -yo);
  const dPerp = addScaled(rd, axis, -yd);
  const rOrigin = ra + slope * yo;

  let tBest = Infinity;
  let part = -1;
  const a = dot(dPerp, dPerp) - slope * slope * yd * yd;
  const b = dot(oPerp, dPerp) - slope * yd * rOrigin;
  const c = dot(oPerp, oPerp) - rOrigin * rOrigin;
  const disc = b * b - a * c;
  if (disc >= 0) {
    const q = -(b + (b >= 0 ? 1 : -1) * Math.sqrt(disc));
    for (const t of [q !== 0 ? c / q : -1, a !== 0 ? q / a : -1]) {
      const y = yo + t * yd;
      if (t > 0 && t < tBest && y >= 0 && y <= height) {
        tBest = t;
        part = 0;
      }
    }
  }
  if (yd !== 0) {
    const tBase = -yo / yd;
    const wBase = addScaled(oPerp, dPerp, tBase);
    if (tBase > 0 && tBase < tBest && dot(wBase, wBase) <= ra * ra) {
      tBest = tBase;
      part = 1;
    }
    const tTop = (height - yo) / yd;
    const wTop = addScaled(oPerp, dPerp, tTop);
    if (rb > 0 && tTop > 0 && tTop < tBest && dot(wTop, wTop) <= rb * rb) {
      tBest = tTop;
      part = 2;
    }
  }
  if (part < 0) return MISS;
  if (part === 1) return [tBest, ...scale(axis, -1)];
  if (part === 2) return [tBest, ...axis];
  const wPerp = addScaled(oPerp, dPerp, tBest);
  let radial;
  if (length(wPerp) > 1e-12 * (height + Math.max(ra, rb))) radial = normalize(wPerp);
  else if (length(dPerp) > 0) radial = scale(normalize(dPerp), -1);
  else radial = normalize(cross(axis, Math.abs(axis[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0]));
  return [tBest, ...normalize(addScaled(radial, axis, -slope))];
}
