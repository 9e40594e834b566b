// What the intersector tests share: the primitives' kinds as the test shaders number them, their
// float64 twins (src/reference/), the tolerance model, and running the GLSL on a table of rays.
//
// A case is { kind, ro, rd, params } with params as the GLSL functions take them (8 numbers at
// most): plane (n, w), sphere (center, radius), box (center, halfSize), cone (pa, pb, ra, rb),
// cylinder (pa, pb, radius), torus (center, axis, R, r).

import fs from 'node:fs';
import { SHADERTOY_HEADER } from '../../../src/shadertoy/header.js';
import { intersectPlane, intersectSphere, intersectBox, intersectCone } from '../../../src/reference/intersectors.js';
import { intersectCylinder } from '../../../src/reference/cylinder.js';
import { intersectTorus } from '../../../src/reference/torus.js';
import { SHADER_FILE } from '../config.js';
import { evaluateFloatShader } from '../raw-webgl/raw-webgl.js';

// ---- tolerances ---------------------------------------------------------------------------------
// u = 2^-24 is float32's unit roundoff: one correctly rounded operation on numbers of size S is
// off by at most u*S. The longest dependent chain from the inputs to t (the cone: origin shift,
// axis projections, the three coefficients, the discriminant, the root) has about 16 roundings,
// each on numbers no bigger than S = |ro - object| + the object's size; K = 32 allows each its
// full u*S twice over. The torus's t is a converged Newton iterate: its error is that of one
// evaluation of the distance g near the root (the shift, the frame, rho, |(rho - 1, y)|: fewer
// roundings than the cone's chain) over |g'|, so the same K u S holds for a transversal hit.
// SwiftShader's sqrt and division are correctly rounded (checked by the well-conditioned cases
// passing at this bound, and reported by the test log).
export const U = 2 ** -24;
export const K = 32;
// Near tangency a root is ill-conditioned: an error e in the discriminant (~u S^2) moves t by
// about sqrt(e) = S sqrt(u). 'agree' cases, which include tangent rays, are held to that.
const tangentTolerance = (S) => K * U * S + Math.sqrt(K * U) * S;
// A normal is a difference of positions divided by a length: its angle error is about the
// position error (K u S) over the radius of curvature there (or exactly 0 for flat faces).

export const KINDS = { plane: 0, sphere: 1, box: 2, cone: 3, cylinder: 4, torus: 5 };
export const f32 = (v) => v.map((x) => Math.fround(x));
const dist = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

/** The float64 answer [t, nx, ny, nz] for a case. */
export function reference(c) {
  const p = c.params;
  if (c.kind === 'plane') return intersectPlane(c.ro, c.rd, p);
  if (c.kind === 'sphere') return intersectSphere(c.ro, c.rd, p.slice(0, 3), p[3]);
  if (c.kind === 'box') return intersectBox(c.ro, c.rd, p.slice(0, 3), p.slice(3, 6));
  if (c.kind === 'cylinder') return intersectCylinder(c.ro, c.rd, p.slice(0, 3), p.slice(3, 6), p[6]);
  if (c.kind === 'torus') return intersectTorus(c.ro, c.rd, p.slice(0, 3), p.slice(3, 6), p[6], p[7]);
  return intersectCone(c.ro, c.rd, p.slice(0, 3), p.slice(3, 6), p[6], p[7]);
}

/** Size of the numbers an intersector works with for this case. */
export function caseScale(c) {
  const p = c.params;
  // t = -(n.ro + w) / n.rd: its relative error is a few u, so the size that matters is t itself.
  if (c.kind === 'plane') return Math.hypot(...c.ro) + Math.abs(p[3]) + Math.max(reference(c)[0], 0);
  if (c.kind === 'sphere') return dist(c.ro, p.slice(0, 3)) + p[3];
  if (c.kind === 'box') return dist(c.ro, p.slice(0, 3)) + Math.hypot(p[3], p[4], p[5]);
  if (c.kind === 'cylinder') return dist(c.ro, p.slice(0, 3)) + dist(p.slice(0, 3), p.slice(3, 6)) + p[6];
  // The torus: distance to the centre plus its outer radius R + r.
  if (c.kind === 'torus') return dist(c.ro, p.slice(0, 3)) + p[6] + p[7];
  return dist(c.ro, p.slice(0, 3)) + dist(p.slice(0, 3), p.slice(3, 6)) + Math.max(p[6], p[7]);
}

/** The radius of curvature that turns a position error into a normal-angle error. */
function curvatureRadius(c) {
  if (c.kind === 'sphere') return c.params[3];
  if (c.kind === 'cone') return Math.max(c.params[6], c.params[7]);
  if (c.kind === 'cylinder') return c.params[6];
  // The torus's normal is (p - nearest core point) / r: a position error over the tube radius.
  if (c.kind === 'torus') return c.params[7];
  return Infinity;
}

/**
 * Whether the float64 decision (hit or miss) changes when the ray origin moves by the shader's
 * own rounding (K u S) in any axis direction: then float32 cannot be expected to resolve it.
 */
function inAmbiguityBand(c, S) {
  const hit = reference(c)[0] > 0;
  const step = K * U * S;
  for (let axis = 0; axis < 3; axis++) {
    for (const sign of [-1, 1]) {
      const ro = c.ro.slice();
      ro[axis] += sign * step;
      if (reference({ ...c, ro })[0] > 0 !== hit) return true;
    }
  }
  return false;
}

/** The GLSL call for each kind, on origin ro, direction rd, params p (0-3) and q (4-7). */
export const GLSL_CALLS = `
vec4 intersectKind(int kind, vec3 ro, vec3 rd, vec4 p, vec4 q, float tMax) {
    if (kind == ${KINDS.plane}) return intersectPlane(ro, rd, p, tMax);
    if (kind == ${KINDS.sphere}) return intersectSphere(ro, rd, p.xyz, p.w, tMax);
    if (kind == ${KINDS.box}) return intersectBox(ro, rd, p.xyz, vec3(p.w, q.xy), tMax);
    if (kind == ${KINDS.cone}) return intersectCone(ro, rd, makeCone(p.xyz, vec3(p.w, q.xy), q.z, q.w), tMax);
    if (kind == ${KINDS.cylinder}) return intersectCylinder(ro, rd, makeCylinder(p.xyz, vec3(p.w, q.xy), q.z), tMax);
    return intersectTorus(ro, rd, makeTorus(p.xyz, vec3(p.w, q.xy), q.z, q.w), tMax);
}
`;

const TEST_MAIN = `${GLSL_CALLS}
uniform highp sampler2D rayTable;  // 4 texels a case: (ro, kind), (rd, tMax), params 0-3, params 4-7
void main() {
    int i = int(gl_FragCoord.x);
    vec4 a = texelFetch(rayTable, ivec2(i, 0), 0);
    vec4 d = texelFetch(rayTable, ivec2(i, 1), 0);
    float tMax = d.w > 0.0 ? d.w : T_INFINITY;  // 0 in the table: no range end
    vec4 p = texelFetch(rayTable, ivec2(i, 2), 0);
    vec4 q = texelFetch(rayTable, ivec2(i, 3), 0);
    shadertoy_out_color = intersectKind(int(a.w), a.xyz, d.xyz, p, q, tMax);
}
`;

/** The shader file, or a version of it with `replace(source)` applied. */
export const shaderSource = (replace = (s) => s) => replace(fs.readFileSync(SHADER_FILE, 'utf8'));

/**
 * Runs cases (already rounded to float32) through the GLSL, each with its range end
 * tMax(case, i) (0: none), in the shader `source`. Resolves with 4 floats (t, n) a case.
 * @param {Array<{kind: string, ro: number[], rd: number[], params: number[]}>} cases
 * @param {{tMax?: (c: any, i: number) => number, source?: string}} [options]
 */
export function runCases(cases, { tMax = () => 0, source = shaderSource() } = {}) {
  const table = new Float32Array(cases.length * 4 * 4);
  const texel = (row, i, values) => table.set(values, (row * cases.length + i) * 4);
  cases.forEach((c, i) => {
    const p = [...c.params, 0, 0, 0, 0, 0, 0, 0, 0].slice(0, 8);
    texel(0, i, [...c.ro, KINDS[c.kind]]);
    texel(1, i, [...c.rd, tMax(c, i)]);
    texel(2, i, p.slice(0, 4));
    texel(3, i, p.slice(4, 8));
  });
  const code = SHADERTOY_HEADER + source + TEST_MAIN;
  return evaluateFloatShader(code, { width: cases.length, height: 1, table, tableHeight: 4, tableUniform: 'rayTable' });
}

/**
 * Judges one case: the GLSL's [t, n] against the float64 twin, under the case's expectation
 * (tests/intersector-cases/index.js). Returns what is wrong (empty when right), whether a
 * disagreement was excused as inside the rounding band, and the errors as shares of their
 * tolerances.
 * @param {{kind: string, ro: number[], rd: number[], params: number[], expect: string, name?: string, note?: string, checkNormal?: boolean, grazing?: number, normals?: number[][]}} k
 * @param {ArrayLike<number>} got
 */
export function judge(k, got) {
  const want = reference(k);
  const S = caseScale(k);
  const hitGot = got[0] > 0;
  const hitWant = want[0] > 0;
  // tRatio: the t error in K u S; over transversal hits (|rd.n| >= 0.1) also as tTransversal,
  // since a grazing hit is ill-conditioned by 1 / |rd.n| and a tangent one more.
  const verdict = { failures: /** @type {string[]} */ ([]), inBand: false, tRatio: 0, tTransversal: 0, angleRatio: 0 };
  const n = Array.from(got).slice(1);
  const say = (what) =>
    verdict.failures.push(
      `${k.name}: ${what} (got t=${got[0]} n=${n.map((x) => x.toFixed(6))}, want t=${want[0]} n=${want.slice(1).map((x) => x.toFixed(6))}; ${k.note})`,
    );
  if (k.expect === 'agree' && hitGot !== hitWant && inAmbiguityBand(k, S)) {
    verdict.inBand = true;
    return verdict;
  }
  // From an origin on the surface, a root within rounding of 0 is the surface itself: float32
  // may report it (the shader never relies on it: it skips or offsets instead).
  if (k.expect === 'surface' && hitGot && got[0] <= K * U * S) return verdict;
  if (hitGot !== hitWant) {
    say(hitWant ? 'missed' : 'hit where float64 misses');
    return verdict;
  }
  if (!hitWant) return verdict;
  // A hit's t is conditioned by the angle at which the ray meets the surface: a position error e
  // across the surface moves the hit along the ray by e / |rd.n|. So an 'agree' case (which may
  // be tangent) is held to K u S / |rd.n| where that is below the tangent tolerance: a far family
  // (S = 1e4: tangent tolerance 14 units) would otherwise pass a transversal hit on a wrong root.
  // `grazing` states a small angle explicitly, and loosens a 'hit' case to K u S / sin(grazing).
  const incidence = Math.abs(k.rd[0] * want[1] + k.rd[1] * want[2] + k.rd[2] * want[3]) / Math.hypot(...k.rd);
  const conditioned = (K * U * S) / Math.max(incidence, Number.MIN_VALUE);
  const base = k.expect === 'agree' ? Math.max(K * U * S, Math.min(tangentTolerance(S), conditioned)) : K * U * S;
  const tTol = Math.max(base, k.grazing ? (K * U * S) / Math.sin(k.grazing) : 0);
  const dt = Math.abs(got[0] - want[0]);
  verdict.tRatio = dt / (K * U * S);
  if (incidence >= 0.1) verdict.tTransversal = verdict.tRatio;
  if (dt > tTol) say(`|t error| ${dt.toExponential(2)} > ${tTol.toExponential(2)} (S = ${S.toPrecision(3)})`);
  const length = Math.hypot(...n);
  if (Math.abs(length - 1) > 4 * U * 8) say(`normal length ${length}`);
  if (k.expect === 'edge') {
    const axisAligned = n.filter((x) => x === 0).length === 2 && n.some((x) => Math.abs(x) === 1);
    if (!axisAligned) say('edge normal is not a single face normal');
    if (n[0] * k.rd[0] + n[1] * k.rd[1] + n[2] * k.rd[2] >= 0) say('edge normal does not face the ray');
    return verdict;
  }
  if (k.checkNormal === false) return verdict; // e.g. at the apex, where any finite unit normal is right
  // On a rim, where two faces meet, either face's normal is right (`normals` lists them).
  const angleTo = (m) => Math.acos(Math.min(1, (n[0] * m[0] + n[1] * m[1] + n[2] * m[2]) / length));
  const angle = Math.min(...(k.normals ?? [want.slice(1)]).map(angleTo));
  const angleTol = tTol / Math.min(curvatureRadius(k), S) + K * U;
  verdict.angleRatio = angle / angleTol;
  if (angle > angleTol) say(`normal off by ${angle.toExponential(2)} rad > ${angleTol.toExponential(2)}`);
  return verdict;
}
