// The four GLSL intersectors of shaders/raytrace.glsl, run in the browser on the hard cases of
// tests/intersector-cases.js and compared with their float64 versions (src/reference/).
//
// The shader file is compiled inside Shadertoy's header with a test `main` instead of
// Shadertoy's: it reads one ray per pixel from an RGBA32F table and writes vec4(t, n) to an
// RGBA32F target (EXT_color_buffer_float), which is read back as floats.

import fs from 'node:fs';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { SHADERTOY_HEADER } from '../src/shadertoy/header.js';
import { intersectPlane, intersectSphere, intersectBox, intersectCone } from '../src/reference/intersectors.js';
import { dot } from '../src/reference/vec3.js';
import { FAR_SPHERE_FAMILY, INTERSECTOR_CASES } from './intersector-cases.js';
import { SHADER_FILE } from './harness/config.js';
import { disconnect } from './harness/page.js';
import { evaluateFloatShader } from './harness/raw-webgl.js';

// ---- tolerances ---------------------------------------------------------------------------------
// u = 2^-24 is float32's unit roundoff: one correctly rounded operation on numbers of size S is
// off by at most u*S. The longest dependent chain from the inputs to t (the cone: origin shift,
// axis projections, the three coefficients, the discriminant, the root) has about 16 roundings,
// each on numbers no bigger than S = |ro - object| + the object's size; K = 32 allows each its
// full u*S twice over. SwiftShader's sqrt and division are correctly rounded (checked by the
// well-conditioned cases below passing at this bound, and reported by the test log).
const U = 2 ** -24;
const K = 32;
// Near tangency a root is ill-conditioned: an error e in the discriminant (~u S^2) moves t by
// about sqrt(e) = S sqrt(u). 'agree' cases, which include tangent rays, are held to that.
const tangentTolerance = (S) => K * U * S + Math.sqrt(K * U) * S;
// A normal is a difference of positions divided by a length: its angle error is about the
// position error (K u S) over the radius of curvature there (or exactly 0 for flat faces).

const KINDS = { plane: 0, sphere: 1, box: 2, cone: 3 };
const f32 = (v) => v.map((x) => Math.fround(x));

function reference(c) {
  const p = c.params;
  if (c.kind === 'plane') return intersectPlane(c.ro, c.rd, p);
  if (c.kind === 'sphere') return intersectSphere(c.ro, c.rd, p.slice(0, 3), p[3]);
  if (c.kind === 'box') return intersectBox(c.ro, c.rd, p.slice(0, 3), p.slice(3, 6));
  return intersectCone(c.ro, c.rd, p.slice(0, 3), p.slice(3, 6), p[6], p[7]);
}

/** Size of the numbers an intersector works with for this case. */
function caseScale(c) {
  const p = c.params;
  const dist = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
  // t = -(n.ro + w) / n.rd: its relative error is a few u, so the size that matters is t itself.
  if (c.kind === 'plane') return Math.hypot(...c.ro) + Math.abs(p[3]) + Math.max(reference(c)[0], 0);
  if (c.kind === 'sphere') return dist(c.ro, p.slice(0, 3)) + p[3];
  if (c.kind === 'box') return dist(c.ro, p.slice(0, 3)) + Math.hypot(p[3], p[4], p[5]);
  return dist(c.ro, p.slice(0, 3)) + dist(p.slice(0, 3), p.slice(3, 6)) + Math.max(p[6], p[7]);
}

/** The radius of curvature that turns a position error into a normal-angle error. */
function curvatureRadius(c) {
  if (c.kind === 'sphere') return c.params[3];
  if (c.kind === 'cone') return Math.max(c.params[6], c.params[7]);
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

const TEST_MAIN = `
uniform highp sampler2D rayTable;  // 4 texels a case: (ro, kind), (rd, tMax), params 0-3, params 4-7
void main() {
    int i = int(gl_FragCoord.x);
    vec4 a = texelFetch(rayTable, ivec2(i, 0), 0);
    vec4 d = texelFetch(rayTable, ivec2(i, 1), 0);
    vec3 rd = d.xyz;
    float tMax = d.w > 0.0 ? d.w : T_MAX;  // 0 in the table: no range end
    vec4 p = texelFetch(rayTable, ivec2(i, 2), 0);
    vec4 q = texelFetch(rayTable, ivec2(i, 3), 0);
    int kind = int(a.w);
    vec4 hit;
    if (kind == ${KINDS.plane}) hit = intersectPlane(a.xyz, rd, p, tMax);
    else if (kind == ${KINDS.sphere}) hit = intersectSphere(a.xyz, rd, p.xyz, p.w, tMax);
    else if (kind == ${KINDS.box}) hit = intersectBox(a.xyz, rd, p.xyz, vec3(p.w, q.xy), tMax);
    else hit = intersectCone(a.xyz, rd, makeCone(p.xyz, vec3(p.w, q.xy), q.z, q.w), tMax);
    shadertoy_out_color = hit;
}
`;

describe('GLSL intersectors against float64', () => {
  // Every number rounded to float32 first: both sides see exactly the same inputs.
  const cases = INTERSECTOR_CASES.map((c) => ({ ...c, ro: f32(c.ro), rd: f32(c.rd), params: f32(c.params) }));
  let results;

  const code = SHADERTOY_HEADER + fs.readFileSync(SHADER_FILE, 'utf8') + TEST_MAIN;
  /**
   * Runs every case through the shader, each with its range end tMax(case, i) (0: none).
   * @param {(c: (typeof cases)[number], i: number) => number} [tMax]
   */
  const evaluate = (tMax = () => 0) => {
    const table = new Float32Array(cases.length * 4 * 4);
    const texel = (row, i, values) => table.set(values, (row * cases.length + i) * 4);
    cases.forEach((c, i) => {
      const p = [...c.params, 0, 0, 0, 0, 0, 0, 0, 0].slice(0, 8);
      texel(0, i, [...c.ro, KINDS[c.kind]]);
      texel(1, i, [...c.rd, tMax(c, i)]);
      texel(2, i, p.slice(0, 4));
      texel(3, i, p.slice(4, 8));
    });
    return evaluateFloatShader(code, { width: cases.length, height: 1, table, tableHeight: 4, tableUniform: 'rayTable' });
  };

  beforeAll(async () => {
    results = await evaluate();
  });
  afterAll(() => disconnect());

  it("the reference itself agrees with each case's written expectation", () => {
    const wrong = cases
      .filter((c) => ['hit', 'edge', 'surface'].includes(c.expect) !== reference(c)[0] > 0 && c.expect !== 'agree')
      .map((c) => `${c.name}: expected ${c.expect}, float64 says t = ${reference(c)[0]}`);
    expect(wrong).toEqual([]);
  });

  it('no NaN or infinity in any result', () => {
    const bad = cases.filter((c, i) => !results.slice(i * 4, i * 4 + 4).every(Number.isFinite)).map((c) => c.name);
    expect(bad).toEqual([]);
  });

  const ratios = { t: 0, angle: 0 };
  for (const [index, c] of INTERSECTOR_CASES.entries()) {
    const family = c.family ?? null;
    if (family && INTERSECTOR_CASES.findIndex((k) => k.family === family) !== index) continue; // a family is one test, at its first ray
    it(family ? `${family} (all rays)` : c.name, () => {
      const members = family ? cases.map((k, i) => [k, i]).filter(([k]) => k.family === family) : [[cases[index], index]];
      const failures = [];
      let inBand = 0;
      for (const [k, i] of members) {
        const got = results.slice(i * 4, i * 4 + 4);
        const want = reference(k);
        const S = caseScale(k);
        const hitGot = got[0] > 0;
        const hitWant = want[0] > 0;
        const say = (what) =>
          failures.push(
            `${k.name}: ${what} (got t=${got[0]} n=${got.slice(1).map((x) => x.toFixed(6))}, want t=${want[0]} n=${want.slice(1).map((x) => x.toFixed(6))}; ${k.note})`,
          );
        if (k.expect === 'agree' && hitGot !== hitWant && inAmbiguityBand(k, S)) {
          inBand++;
          continue;
        }
        // From an origin on the surface, a root within rounding of 0 is the surface itself:
        // float32 may report it (the shader never relies on it: it skips or offsets instead).
        if (k.expect === 'surface' && hitGot && got[0] <= K * U * S) continue;
        if (hitGot !== hitWant) {
          say(hitWant ? 'missed' : 'hit where float64 misses');
          continue;
        }
        if (!hitWant) continue;
        const tTol = k.expect === 'agree' ? tangentTolerance(S) : K * U * S;
        const dt = Math.abs(got[0] - want[0]);
        ratios.t = Math.max(ratios.t, dt / (K * U * S));
        if (dt > tTol) say(`|t error| ${dt.toExponential(2)} > ${tTol.toExponential(2)} (S = ${S.toPrecision(3)})`);
        const n = got.slice(1);
        const length = Math.hypot(...n);
        if (Math.abs(length - 1) > 4 * U * 8) say(`normal length ${length}`);
        if (k.expect === 'edge') {
          const axisAligned = n.filter((x) => x === 0).length === 2 && n.some((x) => Math.abs(x) === 1);
          if (!axisAligned) say('edge normal is not a single face normal');
          if (dot(n, k.rd) >= 0) say('edge normal does not face the ray');
          continue;
        }
        if (k.checkNormal === false) continue; // e.g. at the apex, where any finite unit normal is right
        const cosAngle = Math.min(1, dot(n, want.slice(1)) / length);
        const angle = Math.acos(cosAngle);
        const angleTol = (k.expect === 'agree' ? tangentTolerance(S) : K * U * S) / Math.min(curvatureRadius(k), S) + K * U;
        ratios.angle = Math.max(ratios.angle, angle / angleTol);
        if (angle > angleTol) say(`normal off by ${angle.toExponential(2)} rad > ${angleTol.toExponential(2)}`);
      }
      if (family) console.log(`${family}: ${members.length} rays, ${inBand} inside the rounding band`);
      expect(failures).toEqual([]);
    });
  }

  // The range end: a scene walk passes the nearest hit so far as tMax, a shadow ray the light's
  // distance. Each hit the shader finds must be dropped by a tMax just short of it (nothing
  // nearer exists) and come back unchanged with one just past it.
  it('tMax: a hit at or past the range end is a miss; one before it is unchanged', async () => {
    const hits = cases.map((c, i) => results[i * 4]).map((t) => (t > 0 ? t : 0));
    const short = await evaluate((c, i) => hits[i] * (1 - 2 ** -20));
    const past = await evaluate((c, i) => hits[i] * (1 + 2 ** -20));
    const wrong = [];
    cases.forEach((c, i) => {
      if (!hits[i]) return;
      if (short[i * 4] > 0) wrong.push(`${c.name}: t=${hits[i]} still hit with tMax just short of it (t=${short[i * 4]})`);
      const same = [0, 1, 2, 3].every((k) => past[i * 4 + k] === results[i * 4 + k]);
      if (!same) wrong.push(`${c.name}: tMax just past t=${hits[i]} changed the hit to ${past.slice(i * 4, i * 4 + 4)}`);
    });
    expect(hits.filter(Boolean).length).toBeGreaterThan(100);
    expect(wrong).toEqual([]);
  });

  // The family test must be able to fail: with the textbook discriminant b^2 - c spliced in, a
  // unit sphere seen from 1e4 gets many hit/miss decisions wrong (about one in six in a float32
  // emulation; see shaders/raytrace.glsl).
  it('catches the textbook sphere discriminant on the far-sphere family', async () => {
    const source = fs.readFileSync(SHADER_FILE, 'utf8');
    const start = source.indexOf('vec4 intersectSphere(');
    const end = source.indexOf('\n}\n', start) + 3;
    expect(start).toBeGreaterThan(0);
    const textbook = `vec4 intersectSphere(vec3 ro, vec3 rd, vec3 center, float radius, float tMax) {
    vec3 f = ro - center;
    float b = dot(f, rd);
    float disc = b * b - (dot(f, f) - radius * radius);
    if (disc < 0.0) return MISS;
    float t = -b - sqrt(disc);
    if (t <= 0.0) t = -b + sqrt(disc);
    return t > 0.0 && t < tMax ? vec4(t, normalize(f + t * rd)) : MISS;
}
`;
    const family = cases.filter((c) => c.family === FAR_SPHERE_FAMILY);
    const table = new Float32Array(family.length * 16);
    family.forEach((c, i) => {
      table.set([...c.ro, KINDS.sphere], i * 4);
      table.set([...c.rd, 0], (family.length + i) * 4);
      table.set(c.params, (2 * family.length + i) * 4);
    });
    const code = SHADERTOY_HEADER + source.slice(0, start) + textbook + source.slice(end) + TEST_MAIN;
    const got = await evaluateFloatShader(code, { width: family.length, height: 1, table, tableHeight: 4, tableUniform: 'rayTable' });
    const wrong = family.filter((c, i) => got[i * 4] > 0 !== reference(c)[0] > 0).length;
    console.log(`textbook sphere, r=1 from 1e4: ${wrong} of ${family.length} hit/miss decisions wrong`);
    expect(wrong / family.length).toBeGreaterThan(0.05);
  });

  // How close the worst case came to its tolerance: a bound far above every error is a bound
  // worth tightening.
  afterAll(() => {
    console.log(
      `intersectors: worst t error ${ratios.t.toFixed(3)} x (K u S); worst normal angle ${ratios.angle.toFixed(3)} x its tolerance`,
    );
  });
});
