// The iq-style peers of the per-primitive table (tests/bench/peers/iq/, tests/bench/primitives.js)
// are working intersectors, so that the table's error figures are the formulas' and not a broken
// peer's: each compiles and gets plain rays right (hit or miss as float64 says, t and the normal
// close, at a tolerance loose enough for any float32 closed form). And the table can fail: on the
// project's hard cases, judged as the project's intersectors are, the closed-form torus and the
// textbook sphere get a large share wrong.

import { afterAll, describe, expect, it } from 'vitest';
import { disconnect } from '../support/page.js';
import { caseScale, f32, reference, runCases, shaderSource } from '../support/tables/intersector-kinds.js';
import { PRIMITIVE_KINDS, judgeHardCases, withIqPeers } from '../bench/primitive-peers.js';
import { normalize } from '../../src/reference/vec3.js';

/** A plain ray at a primitive (params as in intersector-kinds.js), and whether float64 says it hits. */
const ray = (name, kind, ro, rd, params, hits) => ({ name, kind, ro: f32(ro), rd: f32(normalize(rd)), params: f32(params), hits });
const UPRIGHT = [0, 0, 0, 0, 2, 0]; // pa, pb of the cone and the cylinder
const TORUS = [0, 0, 0, 0, 1, 0, 1, 0.25];
// Plain rays: from outside, transversal, no zero direction component (iq's box divides by it).
const EASY = [
  ray('plane from above', 'plane', [0.5, 3, 0.2], [0.1, -1, 0.05], [0, 1, 0, 0], true),
  ray('plane, looking up', 'plane', [0, 2, 0], [0.3, 1, 0.1], [0, 1, 0, 0], false),
  ray('sphere head on', 'sphere', [0.1, 0.2, -5], [0.01, 0.02, 1], [0, 0, 0, 1], true),
  ray('sphere passed by', 'sphere', [0, 2, -5], [0.01, 0.02, 1], [0, 0, 0, 1], false),
  ray('box, front face', 'box', [0.2, 0.1, -5], [0.05, 0.02, 1], [0, 0, 0, 1, 0.5, 0.75], true),
  ray('box, top face', 'box', [0.2, 4, 0.1], [0.05, -1, 0.02], [0, 0, 0, 1, 0.5, 0.75], true),
  ray('box passed by', 'box', [3, 0.1, -5], [0.05, 0.02, 1], [0, 0, 0, 1, 0.5, 0.75], false),
  ray('cone, side', 'cone', [-4, 0.7, 0.2], [1, 0.01, 0.02], [...UPRIGHT, 1, 0], true),
  ray('cone, base from below', 'cone', [0.3, -2, 0.1], [0.01, 1, 0.02], [...UPRIGHT, 1, 0], true),
  ray('cone passed by', 'cone', [-4, 3, 0.2], [1, 0.01, 0.02], [...UPRIGHT, 1, 0], false),
  ray('cylinder, side', 'cylinder', [-5, 0.7, 0.2], [1, 0.02, 0.01], [...UPRIGHT, 1], true),
  ray('cylinder, top from above', 'cylinder', [0.3, 5, 0.2], [0.02, -1, 0.01], [...UPRIGHT, 1], true),
  ray('cylinder passed by', 'cylinder', [-5, 3, 0.2], [1, 0.02, 0.01], [...UPRIGHT, 1], false),
  ray('torus, outer side', 'torus', [-5, 0.05, 0.03], [1, 0.001, 0.01], TORUS, true),
  ray('torus, tube from above', 'torus', [1, 3, 0.05], [0.01, -1, 0.02], TORUS, true),
  ray('torus passed over', 'torus', [-5, 2, 0.2], [1, 0.01, 0.02], TORUS, false),
];

/** What is wrong with a result on a plain ray, at 1e-4 of the case's size in t and 1e-3 in the normal's direction and length. */
function plainlyWrong(c, got) {
  const want = reference(c);
  if (got[0] > 0 !== want[0] > 0) return `hit ${got[0] > 0}, float64 ${want[0] > 0}`;
  if (!(want[0] > 0)) return null;
  if (!(Math.abs(got[0] - want[0]) <= 1e-4 * caseScale(c))) return `t = ${got[0]}, float64 ${want[0]}`;
  const length = Math.hypot(got[1], got[2], got[3]);
  const cos = (got[1] * want[1] + got[2] * want[2] + got[3] * want[3]) / length;
  const right = Math.abs(length - 1) <= 1e-3 && Math.acos(Math.min(1, cos)) <= 1e-3;
  return right ? null : `normal ${Array.from(got.slice(1))}, float64 ${want.slice(1)}`;
}

describe('iq-style peers of the intersectors (tests/bench/peers/iq/)', () => {
  afterAll(() => disconnect());

  it('the plain rays are what they say (float64)', () => {
    expect(EASY.filter((c) => reference(c)[0] > 0 !== c.hits).map((c) => c.name)).toEqual([]);
    expect(new Set(EASY.map((c) => c.kind))).toEqual(new Set(PRIMITIVE_KINDS));
  });

  it.each([
    ['the project', () => shaderSource()],
    ['the iq-style peers', () => withIqPeers()],
  ])('%s: every primitive compiles and gets the plain rays right', async (label, source) => {
    const got = await runCases(EASY, { source: source() });
    const wrong = EASY.map((c, i) => [c.name, plainlyWrong(c, got.slice(i * 4, i * 4 + 4))]).filter(([, why]) => why);
    expect(wrong).toEqual([]);
  });

  // The share the table reports for the iq-style forms, held to what it measured (51% of the
  // torus's 1,797 hard rays, 45% of the sphere's 409) with a wide margin.
  it('the table can fail: the closed-form torus and sphere get many hard cases wrong', async () => {
    const tally = await judgeHardCases(withIqPeers(['sphere', 'torus']), ['sphere', 'torus']);
    for (const [kind, t] of Object.entries(tally)) {
      console.log(`iq-style ${kind}: ${t.wrong} of ${t.cases} hard cases wrong (${JSON.stringify(t.reasons)})`);
    }
    expect(tally.torus.wrong / tally.torus.cases).toBeGreaterThan(0.2);
    expect(tally.sphere.wrong / tally.sphere.cases).toBeGreaterThan(0.1);
  });
});
