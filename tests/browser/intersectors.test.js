// The six GLSL intersectors of shaders/raytrace.glsl, run in the browser on the hard cases of
// tests/intersector-cases/ and compared with their float64 versions (src/reference/).
//
// The shader file is compiled inside Shadertoy's header with a test `main` instead of
// Shadertoy's: it reads one ray per pixel from an RGBA32F table and writes vec4(t, n) to an
// RGBA32F target (EXT_color_buffer_float), which is read back as floats. The tolerance model
// (K u S, the tangent tolerance, the rounding band) is in tests/support/tables/intersector-kinds.js.

import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { FAR_SPHERE_FAMILY, INTERSECTOR_CASES, NAIVE_TORUS_FAMILIES } from '../intersector-cases/index.js';
import { disconnect } from '../support/page.js';
import { K, U, caseScale, f32, judge, reference, runCases, shaderSource } from '../support/tables/intersector-kinds.js';
import { NAIVE_TORUS, TEXTBOOK_SPHERE, replaceFunction } from '../support/tables/intersector-naive.js';
import { addScaled, dot, normalize, sub } from '../../src/reference/vec3.js';

/** The float64 signed distance of p to the torus of a case (params: centre, axis, R, r). */
function torusDistance(p, params) {
  const A = normalize(params.slice(3, 6));
  const w = sub(p, params.slice(0, 3));
  const y = dot(w, A);
  return Math.hypot(Math.hypot(...addScaled(w, A, -y)) - params[6], y) - params[7];
}

describe('GLSL intersectors against float64', () => {
  // Every number rounded to float32 first: both sides see exactly the same inputs.
  const cases = INTERSECTOR_CASES.map((c) => ({ ...c, ro: f32(c.ro), rd: f32(c.rd), params: f32(c.params) }));
  const at = (data, i) => data.slice(i * 4, i * 4 + 4);
  let results;

  beforeAll(async () => {
    results = await runCases(cases);
  });
  afterAll(() => disconnect());

  it("the reference itself agrees with each case's written expectation", () => {
    const wrong = cases
      .filter((c) => ['hit', 'edge', 'surface'].includes(c.expect) !== reference(c)[0] > 0 && c.expect !== 'agree')
      .map((c) => `${c.name}: expected ${c.expect}, float64 says t = ${reference(c)[0]}`);
    expect(wrong).toEqual([]);
  });

  it('no NaN or infinity in any result', () => {
    const bad = cases.filter((c, i) => !at(results, i).every(Number.isFinite)).map((c) => c.name);
    expect(bad).toEqual([]);
  });

  // Worst t error (in K u S) and normal angle (in its tolerance) per primitive and per family.
  const worst = {};
  const note = (key, v) => {
    worst[key] ??= { t: 0, transversal: 0, angle: 0 };
    worst[key].t = Math.max(worst[key].t, v.tRatio);
    worst[key].transversal = Math.max(worst[key].transversal, v.tTransversal);
    worst[key].angle = Math.max(worst[key].angle, v.angleRatio);
  };
  const say = (w) =>
    `worst t error ${w.t.toFixed(3)} x (K u S), ${w.transversal.toFixed(3)} over transversal hits; normal ${w.angle.toFixed(3)} x its tolerance`;
  for (const [index, c] of INTERSECTOR_CASES.entries()) {
    const family = c.family ?? null;
    if (family && INTERSECTOR_CASES.findIndex((k) => k.family === family) !== index) continue; // a family is one test, at its first ray
    it(family ? `${family} (all rays)` : c.name, () => {
      const members = family ? cases.map((k, i) => [k, i]).filter(([k]) => k.family === family) : [[cases[index], index]];
      const failures = [];
      let inBand = 0;
      let hits = 0;
      for (const [k, i] of members) {
        const verdict = judge(k, at(results, i));
        failures.push(...verdict.failures);
        if (verdict.inBand) inBand++;
        if (results[i * 4] > 0) hits++;
        note(k.kind, verdict);
        if (family) note(family, verdict);
      }
      if (family) {
        console.log(`${family}: ${members.length} rays, ${hits} hits, ${inBand} inside the rounding band; ${say(worst[family])}`);
      }
      expect(failures).toEqual([]);
    });
  }

  // A torus hit is a sign change of the distance g in a bracket, never a closed-form root: the
  // point it names must lie on the torus, to the shader's rounding (K u S), for every case.
  it('every torus hit lies on the torus (float64 distance within K u S)', () => {
    let worstRatio = 0;
    const off = [];
    cases.forEach((c, i) => {
      const t = results[i * 4];
      if (c.kind !== 'torus' || !(t > 0)) return;
      const g = Math.abs(torusDistance(addScaled(c.ro, c.rd, t), c.params));
      const ratio = g / (K * U * caseScale(c));
      worstRatio = Math.max(worstRatio, ratio);
      if (ratio > 1) off.push(`${c.name}: |g| = ${g.toExponential(2)} at t = ${t}`);
    });
    console.log(`torus hits: worst |g| ${worstRatio.toFixed(3)} x (K u S)`);
    expect(off).toEqual([]);
  });

  // The torus's two loops end when every gap has converged (SwiftShader runs a quad's 4 pixels
  // through every trip any of them needs): count the trips of each with counters spliced in.
  it('torus: the Newton loops end before their trip caps', async () => {
    const torus = cases.filter((c) => c.kind === 'torus');
    // each splice must find its place: a counter that is never set would count 0 trips and pass
    const splice = (text, from, to) => {
      const out = text.replace(from, to);
      if (out === text) throw new Error(`the torus's loops changed: ${from} is no longer in the shader; update this test`);
      return out;
    };
    const counting = shaderSource((s) => {
      let out = splice(
        s,
        'for (int trip = 1;; trip++) {\n        vec3 dF',
        'int critTrips = 0, rootTrips = 0;\n    for (int trip = 1;; trip++) {\n        critTrips = trip;\n        vec3 dF',
      );
      out = splice(
        out,
        'for (int trip = 1;; trip++) {\n        vec2 g',
        'for (int trip = 1;; trip++) {\n        rootTrips = trip;\n        vec2 g',
      );
      return splice(
        out,
        /return hitOrMiss\(all\(bvec4\(inBound, inRange,[^;]*;/,
        'return vec4(critTrips, rootTrips, all(bvec2(inBound, inRange)), 0.0);',
      );
    });
    const trips = await runCases(torus, { source: counting });
    const solved = torus.map((c, i) => at(trips, i)).filter((v) => v[2] > 0);
    const share = (stage, most) => solved.filter((v) => v[stage] <= most).length / solved.length;
    const worst = (stage) => Math.max(...solved.map((v) => v[stage]));
    console.log(
      `torus trips on ${solved.length} rays: F' ${(100 * share(0, 5)).toFixed(1)}% in 5 or fewer, worst ${worst(0)} (cap 12); g ${(100 * share(1, 5)).toFixed(1)}% in 5 or fewer, worst ${worst(1)} (cap 16)`,
    );
    expect(solved.length).toBeGreaterThan(1000);
    expect(share(0, 11)).toBeGreaterThan(0.99);
    expect(worst(1)).toBeGreaterThan(0);
    expect(worst(1)).toBeLessThan(16);
  });

  // The range end: a scene walk passes the nearest hit so far as tMax, a shadow ray the light's
  // distance. Each hit the shader finds must be dropped by a tMax just short of it (nothing
  // nearer exists) and come back unchanged with one just past it.
  it('tMax: a hit at or past the range end is a miss; one before it is unchanged', async () => {
    const hits = cases.map((c, i) => results[i * 4]).map((t) => (t > 0 ? t : 0));
    const short = await runCases(cases, { tMax: (c, i) => hits[i] * (1 - 2 ** -20) });
    const past = await runCases(cases, { tMax: (c, i) => hits[i] * (1 + 2 ** -20) });
    const wrong = [];
    cases.forEach((c, i) => {
      if (!hits[i]) return;
      if (short[i * 4] > 0) wrong.push(`${c.name}: t=${hits[i]} still hit with tMax just short of it (t=${short[i * 4]})`);
      const same = [0, 1, 2, 3].every((k) => past[i * 4 + k] === results[i * 4 + k]);
      if (!same) wrong.push(`${c.name}: tMax just past t=${hits[i]} changed the hit to ${at(past, i)}`);
    });
    expect(hits.filter(Boolean).length).toBeGreaterThan(100);
    expect(wrong).toEqual([]);
  });

  // The family test must be able to fail: with the textbook discriminant b^2 - c spliced in, a
  // unit sphere seen from 1e4 gets many hit/miss decisions wrong (about one in six in a float32
  // emulation; see shaders/raytrace.glsl).
  it('catches the textbook sphere discriminant on the far-sphere family', async () => {
    const family = cases.filter((c) => c.family === FAR_SPHERE_FAMILY);
    const source = shaderSource((s) => replaceFunction(s, 'vec4 intersectSphere(', TEXTBOOK_SPHERE));
    const got = await runCases(family, { source });
    const wrong = family.filter((c, i) => got[i * 4] > 0 !== reference(c)[0] > 0).length;
    console.log(`textbook sphere, r=1 from 1e4: ${wrong} of ${family.length} hit/miss decisions wrong`);
    expect(wrong / family.length).toBeGreaterThan(0.05);
  });

  // And for the torus: a plain closed-form quartic (Ferrari, Cardano's resolvent) spliced in
  // fails the same checks on a measurable share of the far, thin and near-axial families.
  it('catches the closed-form quartic torus on the far, thin and near-axial families', async () => {
    const family = cases.filter((c) => NAIVE_TORUS_FAMILIES.includes(c.family));
    const source = shaderSource((s) => replaceFunction(s, 'vec4 intersectTorus(', NAIVE_TORUS));
    const got = await runCases(family, { source });
    const shares = NAIVE_TORUS_FAMILIES.map((name) => {
      const members = family.map((c, i) => [c, i]).filter(([c]) => c.family === name);
      const wrong = members.filter(([c, i]) => judge(c, at(got, i)).failures.length > 0).length;
      const fake = members.filter(([c, i]) => got[i * 4] > 0 && !(reference(c)[0] > 0)).length;
      console.log(`closed-form torus, ${name}: ${wrong} of ${members.length} rays wrong (${fake} hits where float64 misses)`);
      return wrong / members.length;
    });
    expect(Math.min(...shares)).toBeGreaterThan(0.05);
  });

  afterAll(() => {
    for (const [key, w] of Object.entries(worst)) {
      if (!key.includes(' ')) console.log(`${key}: ${say(w)}`);
    }
  });
});
