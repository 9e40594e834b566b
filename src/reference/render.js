// The float64 reference renderer: shaders/raytrace.glsl's scene, camera, shading and output
// transform, in JavaScript doubles. It reads the control defaults and the material constants
// from the shader's own text (its object ids too), so the two cannot drift apart silently.
//
// Two modes:
// - 'same-rays': the shader's own sample positions and texture filter, so the difference to the
//   shader's image is arithmetic error alone (with adaptive anti-aliasing, which pixels took extra
//   samples is the shader's decision, read from its "Extra samples" debug view);
// - 'converged': many stratified, jittered samples per pixel and the texture point-sampled, so
//   the difference is the shader's total error, aliasing included;
// - 'progressive': the first N samples of the progressive raytracer's own sequence
//   (progressiveJitter of src/raytracer/progressive.js), point-sampled as 'converged' is, so N
//   still frames of the progressive shader compare with it sample for sample.

import { parseControls, parseConstants, controlDefaults, coerceControlValue } from '../shadertoy/controls.js';
import { intersectPlane, intersectSphere, intersectBox, intersectCone } from './intersectors.js';
import { intersectCylinder } from './cylinder.js';
import { intersectTorus } from './torus.js';
import { add, sub, scale, addScaled, dot, length, normalize, reflect, mix } from './vec3.js';
import { PATTERNS, filteredPattern, groundFootprint } from './texture.js';
import { progressiveJitter } from '../raytracer/progressive.js';

const DEG = Math.PI / 180;
/** The shader's object ids (its `const int ID_*` lines; ID_OBJECT: SCENE's cone, cylinder or torus). */
const OBJECT_IDS = ['ID_NONE', 'ID_GROUND', 'ID_SPHERE', 'ID_CUBE', 'ID_OBJECT'];
const GROUND = [0, 1, 0, 0];

/**
 * The values a render uses: the shader's control defaults with `overrides` applied (coerced as
 * the page coerces URL values; unknown names throw), and its material constants.
 * @param {string} shaderSource
 * @param {Record<string, unknown>} [overrides]
 * @returns {Record<string, any>} values by name
 */
export function referenceSettings(shaderSource, overrides = {}) {
  const controls = parseControls(shaderSource);
  const values = controlDefaults(controls);
  for (const [name, value] of Object.entries(overrides)) {
    const control = controls.find((c) => c.name === name);
    if (!control) throw new Error(`reference: unknown control ${name}`);
    const coerced = coerceControlValue(control, value);
    if (coerced === undefined) throw new Error(`reference: bad value ${JSON.stringify(value)} for ${name}`);
    values[name] = coerced;
  }
  return { ...parseConstants(shaderSource), ...values };
}

/**
 * The new object of a scene (the shader's SCENE): its intersector, colour, reflectivity, its
 * radius of curvature as a mirror at a point, and whether a ray leaving it can meet it again.
 */
function sceneObject(s) {
  if (s.SCENE === 1) {
    const top = add(s.CYLINDER_BASE, [0, s.CYLINDER_HEIGHT, 0]);
    return {
      intersect: (ro, rd) => intersectCylinder(ro, rd, s.CYLINDER_BASE, top, s.CYLINDER_RADIUS),
      color: s.CYLINDER_COLOR,
      reflectivity: s.CYLINDER_REFLECTIVITY,
      mirrorRadius: () => s.CYLINDER_RADIUS,
      reenters: false,
    };
  }
  if (s.SCENE === 2) {
    const axis = dot(s.TORUS_AXIS, s.TORUS_AXIS) > 0 ? s.TORUS_AXIS : [0, 1, 0];
    const [major, minorWanted] = s.TORUS_RADII;
    const minor = Math.min(minorWanted, major);
    return {
      intersect: (ro, rd) => intersectTorus(ro, rd, s.TORUS_CENTER, axis, major, minor),
      color: s.TORUS_COLOR,
      reflectivity: s.TORUS_REFLECTIVITY,
      mirrorRadius: () => minor,
      reenters: true,
    };
  }
  const apex = add(s.CONE_BASE, [0, s.CONE_HEIGHT, 0]);
  return {
    intersect: (ro, rd) => intersectCone(ro, rd, s.CONE_BASE, apex, s.CONE_RADIUS, 0),
    color: s.CONE_COLOR,
    reflectivity: s.CONE_REFLECTIVITY,
    mirrorRadius: (p) => s.CONE_RADIUS * Math.max(1 - (p[1] - s.CONE_BASE[1]) / s.CONE_HEIGHT, 0),
    reenters: false,
  };
}

/** A scene tracer bound to one set of settings. */
function makeScene(s) {
  const missing = OBJECT_IDS.filter((name) => typeof s[name] !== 'number');
  if (missing.length) throw new Error(`reference: the shader has no ${missing.join(', ')}`);
  const { ID_NONE, ID_GROUND, ID_SPHERE, ID_CUBE, ID_OBJECT } = s;
  const object = sceneObject(s);
  const colors = { [ID_SPHERE]: s.SPHERE_COLOR, [ID_CUBE]: s.CUBE_COLOR, [ID_OBJECT]: object.color };
  const reflectivity = {
    [ID_GROUND]: s.GROUND_REFLECTIVITY,
    [ID_SPHERE]: s.SPHERE_REFLECTIVITY,
    [ID_CUBE]: s.CUBE_REFLECTIVITY,
    [ID_OBJECT]: object.reflectivity,
  };
  /** @type {Array<[number, (ro: number[], rd: number[]) => readonly number[]]>} */
  const objects = [
    [ID_GROUND, (ro, rd) => intersectPlane(ro, rd, GROUND)],
    [ID_SPHERE, (ro, rd) => intersectSphere(ro, rd, s.SPHERE_CENTER, s.SPHERE_RADIUS)],
    [ID_CUBE, (ro, rd) => intersectBox(ro, rd, s.CUBE_CENTER, s.CUBE_HALF_SIZE)],
    [ID_OBJECT, object.intersect],
  ];
  /** float64 needs no ulp scheme: a relative 1e-12 step off the surface is far below anything
   * float32 can resolve and far above float64's own rounding. @param {number[]} p @param {number[]} n @param {number} side */
  const offAlong = (p, n, side) => addScaled(p, n, side * 1e-12 * (1 + length(p)));
  /** Whether a ray leaving the surface of `id` may meet it again (the torus: the shader's reenters). */
  const reenters = (id) => id === ID_OBJECT && object.reenters;

  /**
   * The nearest hit from ro along rd, leaving out skipId. A hit whose point lies within the
   * shader's rounding band of the ground's plane, on a ray that meets the ground, is the ground's
   * (traceScene in the shader: a surface in the ground's plane is the ground, whatever the
   * rounding). The band is the shader's float32 one, in the shader's eye-relative terms.
   */
  function trace(ro, rd, skipId, eye) {
    let best = null;
    let ground = null;
    for (const [id, intersect] of objects) {
      if (id === skipId) continue;
      const h = intersect(ro, rd);
      if (id === ID_GROUND && h[0] > 0) ground = { t: h[0], n: [h[1], h[2], h[3]], id };
      if (h[0] > 0 && (!best || h[0] < best.t)) best = { t: h[0], n: [h[1], h[2], h[3]], id };
    }
    if (!ground || !best || best.id === ID_GROUND) return best; // (a ground hit is a hit: best is set)
    const fromEye = sub(ro, eye);
    const height = ro[1] + best.t * rd[1];
    const band = s.GROUND_BAND_ULPS * s.EPS32 * (ground.t + Math.max(...fromEye.map(Math.abs)) + Math.abs(eye[1]));
    return Math.abs(height) <= band ? ground : best;
  }

  function occluded(ro, rd, lightDist, skipId) {
    for (const [id, intersect] of objects) {
      if (id === skipId) continue;
      const t = intersect(ro, rd)[0];
      if (t > 0 && t < lightDist) return true;
    }
    return false;
  }

  /** Ground albedo at p for a footprint with extents [x, x, z, z] of its two spanning vectors (null: unfiltered). */
  function groundColor(p, footprint) {
    const u = s.SCENE_ORIGIN[0] + p[0];
    const v = s.SCENE_ORIGIN[2] + p[2];
    const pattern = s.TEXTURE === 0 ? PATTERNS.stripes : PATTERNS.checkers;
    const sx = footprint ? filteredPattern(pattern, u, footprint[0], footprint[1]) : pattern.at(u);
    if (s.TEXTURE === 0) return scale(s.STRIPE_COLOR, sx + s.STRIPE_OFFSET);
    const sz = footprint ? filteredPattern(pattern, v, footprint[2], footprint[3]) : pattern.at(v);
    return mix(s.CHECKER_LIGHT, s.CHECKER_DARK, sx + sz - 2 * sx * sz);
  }

  /** The light leaving a hit towards the viewer, and whether the light reaches the hit. */
  function shadeLocal(p, n, rd, id, albedo, inside) {
    const color = scale(albedo, s.AMBIENT);
    if (inside) return { color, lit: false };
    const toLight = sub(s.LIGHT_POSITION, p);
    const lightDist = length(toLight);
    const l = scale(toLight, 1 / lightDist);
    const facing = dot(n, l);
    if (facing <= 0) return { color, lit: false };
    if (s.SHADOWS && (reenters(id) ? occluded(offAlong(p, n, 1), l, lightDist, ID_NONE) : occluded(p, l, lightDist, id)))
      return { color, lit: false };
    const highlight = Math.max(dot(reflect(scale(l, -1), n), scale(rd, -1)), 0) ** s.SHININESS;
    const specular = s.SPECULAR * highlight;
    const lit = [
      color[0] + facing * albedo[0] + specular,
      color[1] + facing * albedo[1] + specular,
      color[2] + facing * albedo[2] + specular,
    ];
    return { color: lit, lit: true };
  }

  /**
   * Radiance along an eye ray from `eye`. With `differentials` ({dirDx, dirDy}: how the ray's
   * direction changes across its sample's footprint) the ground is filtered as the shader filters
   * it: over the eye ray's exact footprint, and over a ray cone of coneSpread for reflected rays.
   * Without, it is point-sampled. With `path` (an array), each ray's hit is pushed onto it as the
   * shader's path probe records it (src/raytracer/path-probe.js: PathRay).
   * @param {number[]} eye
   * @param {number[]} rd
   * @param {number} coneSpread
   * @param {{dirDx: number[], dirDy: number[]} | null} differentials
   * @param {Array<{id: number, t: number, normal: number[], lit: boolean | null, weight: number}> | null} [path]
   */
  function radiance(eye, rd, coneSpread, differentials, path = null) {
    let ro = eye;
    let color = [0, 0, 0];
    let throughput = 1;
    let coneWidth = 0;
    let skipId = ID_NONE;
    for (let bounce = 0; bounce <= s.BOUNCES; bounce++) {
      const hit = trace(ro, rd, skipId, eye);
      path?.push(
        hit
          ? { id: hit.id, t: hit.t, normal: hit.n, lit: null, weight: throughput }
          : { id: ID_NONE, t: Infinity, normal: [0, 0, 0], lit: null, weight: throughput },
      );
      if (!hit) return addScaled(color, mix(s.SKY_HORIZON, s.SKY_ZENITH, Math.min(Math.max(rd[1], 0), 1)), throughput);
      const { t, n, id } = hit;
      const inside = dot(rd, n) > 0;
      const p = addScaled(ro, rd, t);
      if (id === ID_GROUND) p[1] = 0;
      coneWidth += coneSpread * t;
      let footprint = null;
      if (differentials && bounce === 0) {
        // dp = t (dd - d (n.dd) / (n.d)) on the plane y = 0
        const along = (dd) => scale(sub(dd, scale(rd, dd[1] / rd[1])), t);
        const dpdx = along(differentials.dirDx);
        const dpdy = along(differentials.dirDy);
        footprint = [Math.abs(dpdx[0]), Math.abs(dpdy[0]), Math.abs(dpdx[2]), Math.abs(dpdy[2])];
      } else if (differentials) {
        const cone = groundFootprint(rd, coneWidth);
        footprint = [cone[0], 0, cone[1], 0];
      }
      const albedo = id === ID_GROUND ? groundColor(p, footprint) : colors[id];
      const { color: local, lit } = shadeLocal(p, n, rd, id, albedo, inside);
      if (path) path[path.length - 1].lit = lit;
      const mirror = reflectivity[id];
      if (bounce === s.BOUNCES || throughput * mirror < 1 / 255) return addScaled(color, local, throughput);
      color = addScaled(color, local, throughput * (1 - mirror));
      throughput *= mirror;
      if (id === ID_SPHERE) coneSpread += (2 * coneWidth) / s.SPHERE_RADIUS;
      if (id === ID_OBJECT) coneSpread += (2 * coneWidth) / Math.max(object.mirrorRadius(p), coneWidth);
      rd = reflect(rd, n);
      const again = inside || reenters(id);
      ro = again ? offAlong(p, n, inside ? -1 : 1) : p;
      skipId = again ? ID_NONE : id;
    }
    return color;
  }
  return { radiance };
}

/** The camera of mainImage: eye position and basis for a given time, mouse and resolution. */
export function referenceCamera(s, { width, height, time = 0, mouse = [0, 0, 0, 0] }) {
  let azimuthDeg = s.CAMERA_ORBIT[0] + s.ORBIT_SPEED * time;
  let elevationDeg = s.CAMERA_ORBIT[1];
  if (mouse[0] !== 0 || mouse[1] !== 0) {
    azimuthDeg += -360 * (mouse[0] / width - 0.5);
    elevationDeg += 180 * (mouse[1] / height - 0.5);
  }
  const azimuth = azimuthDeg * DEG;
  const elevation = Math.min(Math.max(elevationDeg, -89), 90) * DEG;
  const back = [Math.cos(elevation) * Math.sin(azimuth), Math.sin(elevation), Math.cos(elevation) * Math.cos(azimuth)];
  const right = [Math.cos(azimuth), 0, -Math.sin(azimuth)];
  const up = [-Math.sin(elevation) * Math.sin(azimuth), Math.cos(elevation), -Math.sin(elevation) * Math.cos(azimuth)];
  const eye = addScaled(s.CAMERA_TARGET, back, s.CAMERA_DISTANCE);
  return { eye, back, right, up, tanHalfFov: Math.tan(0.5 * s.FIELD_OF_VIEW * DEG) };
}

/** Deterministic jitter in [0, 1): a 32-bit integer hash of the pixel and sample (no Math.random). */
function jitter(x, y, i, axis) {
  let h = (x * 73856093) ^ (y * 19349663) ^ (i * 83492791) ^ (axis * 2654435761);
  h = Math.imul(h ^ (h >>> 16), 0x45d9f3b);
  h = Math.imul(h ^ (h >>> 16), 0x45d9f3b);
  return ((h ^ (h >>> 16)) >>> 0) / 4294967296;
}

/**
 * Renders the scene in float64.
 * @param {string} shaderSource the text of shaders/raytrace.glsl (controls and constants)
 * @param {object} view { width, height, time, mouse, controls: {NAME: value} }
 * @param {{mode?: 'same-rays'|'converged'|'progressive', samplesPerAxis?: number, samples?: number, rows?: [number, number], extraSamples?: Uint8Array}} [options]
 *   converged mode takes samplesPerAxis^2 jittered stratified samples per pixel (default 8: 64
 *   samples); progressive mode the first `samples` (default 64) of the progressive shader's
 *   sequence; rows = [first, end) renders only those rows (to split an image over threads);
 *   extraSamples (same-rays mode, adaptive anti-aliasing on): one byte a pixel, rows top to
 *   bottom, non-zero where the shader took the extra samples (its "Extra samples" debug
 *   view)
 * @returns {{width, height, rgb: Float64Array}} display values in [0, 1], 3 per pixel, rows
 *   top to bottom (as the page's readPixels returns them)
 */
export function renderReference(shaderSource, view, { mode = 'same-rays', samplesPerAxis = 8, samples = 64, rows, extraSamples } = {}) {
  const { width, height } = view;
  const s = referenceSettings(shaderSource, view.controls);
  const camera = referenceCamera(s, view);
  const { radiance } = makeScene(s);
  const progressive = mode === 'progressive';
  const converged = mode === 'converged' || progressive;
  if (!converged && mode !== 'same-rays') throw new Error(`reference: unknown mode ${mode}`);
  const gridPerAxis = converged ? samplesPerAxis : Math.round(Math.sqrt(s.SAMPLES));
  const adaptive = !converged && s.ADAPTIVE_AA === 1 && gridPerAxis > 1;
  // which pixels take the grid of samples; null: every pixel does
  const mask = adaptive ? extraSamples : null;
  if (adaptive && !mask) {
    throw new Error(
      'reference: adaptive anti-aliasing needs extraSamples, the pixels the shader gave extra samples (its "Extra samples" debug VIEW view)',
    );
  }
  const sample = makeSampler(camera, radiance, width, height, !converged && s.TEXTURE_FILTER === 1);
  const [firstRow, endRow] = rows ?? [0, height];
  const rgb = new Float64Array(width * (endRow - firstRow) * 3);
  for (let row = firstRow; row < endRow; row++) {
    const fy = height - 1 - row + 0.5; // fragCoord.y counts from the bottom
    for (let x = 0; x < width; x++) {
      const fx = x + 0.5;
      if (progressive) {
        const k = ((row - firstRow) * width + x) * 3;
        averageProgressive(rgb, k, samples, (i) => {
          const [jx, jy] = progressiveJitter(x, height - 1 - row, i);
          return sample(x + jx, height - 1 - row + jy, 1);
        });
        continue;
      }
      const grid = !mask || mask[row * width + x] !== 0;
      const perAxis = grid ? gridPerAxis : 1;
      const sum = [0, 0, 0];
      for (let i = 0; i < perAxis * perAxis; i++) {
        const jx = converged ? jitter(x, row, i, 0) : 0.5;
        const jy = converged ? jitter(x, row, i, 1) : 0.5;
        const c = sample(fx + ((i % perAxis) + jx) / perAxis - 0.5, fy + (Math.floor(i / perAxis) + jy) / perAxis - 0.5, 1 / perAxis);
        sum[0] += c[0];
        sum[1] += c[1];
        sum[2] += c[2];
      }
      const k = ((row - firstRow) * width + x) * 3;
      for (let ch = 0; ch < 3; ch++) rgb[k + ch] = Math.min(Math.max(sum[ch] / (perAxis * perAxis), 0), 1);
    }
  }
  return { width, height, rgb };
}

/**
 * The sample through image point (px, py) whose footprint is `footprint` pixels on a side (eyeRay
 * in the shader), its ground filtered over that footprint when `filter`; `path` (an array) gets
 * its rays.
 * @returns {(px: number, py: number, footprint: number, path?: object[] | null) => number[]}
 */
function makeSampler(camera, radiance, width, height, filter) {
  return (px, py, footprint, path = null) => {
    const u = (2 * px - width) / height;
    const v = (2 * py - height) / height;
    const toPoint = add(scale(camera.back, -1), scale(add(scale(camera.right, u), scale(camera.up, v)), camera.tanHalfFov));
    const dir = normalize(toPoint);
    if (!filter) return radiance(camera.eye, dir, 0, null, path);
    const step = (2 * camera.tanHalfFov * footprint) / height / length(toPoint);
    const across = (axis) => scale(sub(axis, scale(dir, dot(dir, axis))), step);
    const differentials = { dirDx: across(camera.right), dirDy: across(camera.up) };
    return radiance(camera.eye, dir, ((2 * camera.tanHalfFov) / height) * footprint, differentials, path);
  };
}

/**
 * One pixel of the same-ray reference, and the path of the ray through its centre (the
 * shader's first sample, the one the page's path probe records: src/raytracer/path-probe.js).
 * @param {string} shaderSource
 * @param {object} view as renderReference's
 * @param {number} x the pixel's column (fragCoord.x - 0.5)
 * @param {number} y its row counted from the bottom (fragCoord.y - 0.5)
 * @param {{extraSamples?: boolean}} [options] whether the shader gave this pixel the grid of extra
 *   samples (adaptive anti-aliasing on; with uniform supersampling every pixel takes the grid)
 * @returns {{rgb: number[], path: import('../raytracer/path-probe.js').PathRay[]}} rgb clamped to [0, 1], as renderReference's
 */
export function referencePixel(shaderSource, view, x, y, { extraSamples = false } = {}) {
  const s = referenceSettings(shaderSource, view.controls);
  const { radiance } = makeScene(s);
  const sample = makeSampler(referenceCamera(s, view), radiance, view.width, view.height, s.TEXTURE_FILTER === 1);
  const gridPerAxis = Math.round(Math.sqrt(s.SAMPLES));
  const perAxis = gridPerAxis > 1 && (s.ADAPTIVE_AA !== 1 || extraSamples) ? gridPerAxis : 1;
  const path = [];
  sample(x + 0.5, y + 0.5, 1, path);
  const sum = [0, 0, 0];
  for (let i = 0; i < perAxis * perAxis; i++) {
    const c = sample(x + ((i % perAxis) + 0.5) / perAxis, y + (Math.floor(i / perAxis) + 0.5) / perAxis, 1 / perAxis);
    for (let ch = 0; ch < 3; ch++) sum[ch] += c[ch];
  }
  return { rgb: sum.map((v) => Math.min(Math.max(v / (perAxis * perAxis), 0), 1)), path };
}

/**
 * Writes the clamped mean of n samples (sample(i) for i = 0..n-1) at rgb[k..k+2]: the progressive
 * shader's Image tab clamps the mean of its sums the same way.
 */
function averageProgressive(rgb, k, n, sample) {
  const sum = [0, 0, 0];
  for (let i = 0; i < n; i++) {
    const c = sample(i);
    sum[0] += c[0];
    sum[1] += c[1];
    sum[2] += c[2];
  }
  for (let ch = 0; ch < 3; ch++) rgb[k + ch] = Math.min(Math.max(sum[ch] / n, 0), 1);
}
