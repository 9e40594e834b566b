// The iq-style peers of the intersectors (tests/bench/peers/iq/: the closed forms a Shadertoy
// author writes from Inigo Quilez's published formulas) and how any set of intersectors is judged
// on the project's hard cases (tests/intersector-cases/) with the project's own verdict
// (judge() in tests/support/tables/intersector-kinds.js). Shared by the per-primitive benchmark (primitives.js)
// and its test (tests/browser/primitive-peers.test.js).
//
// A peer file is appended after shaders/raytrace.glsl; its #defines rename the project's calls in
// whatever follows (the test main of intersector-kinds.js, the timing main of primitives.js), so
// the same main text runs either side and nothing in the project is edited.

import fs from 'node:fs';
import { INTERSECTOR_CASES } from '../intersector-cases/index.js';
import { KINDS, f32, judge, reference, runCases, shaderSource } from '../support/tables/intersector-kinds.js';

/** The primitives, in the order of the table (the kinds of intersector-kinds.js). */
export const PRIMITIVE_KINDS = Object.keys(KINDS);

/** The iq-style peer of one primitive (kind as in KINDS). */
const iqPeer = (kind) => fs.readFileSync(new URL(`./peers/iq/${kind}.glsl`, import.meta.url), 'utf8');

/** The project's shader with the iq peers of `kinds` appended (their #defines then rename the calls that follow). */
export const withIqPeers = (kinds = PRIMITIVE_KINDS, source = shaderSource()) => [source, ...kinds.map(iqPeer)].join('\n');

/** The hard cases of one primitive, every number rounded to float32 (as tests/browser/intersectors.test.js does). */
const hardCases = (kind) =>
  INTERSECTOR_CASES.filter((c) => c.kind === kind).map((c) => ({ ...c, ro: f32(c.ro), rd: f32(c.rd), params: f32(c.params) }));

/**
 * Whether the ray starts inside the solid (or on its surface, heading in): the float64 reference
 * hits, and leaves the solid there (its outward normal points along the ray). The article's forms
 * say they "only work for a ray with origin outside of the primitive": the table counts these apart.
 */
function startsInside(c) {
  const want = reference(c);
  return want[0] > 0 && c.rd[0] * want[1] + c.rd[1] * want[2] + c.rd[2] * want[3] > 0;
}

/**
 * One case judged as the project's intersectors are (judge()), plus what judge() leaves to the
 * test of its own in intersectors.test.js: a hit with a NaN or infinity in it is wrong. `reason`
 * is null when right, else what was wrong first: 'hit/miss', 't', 'normal' or 'NaN'.
 * @returns {{reason: string | null, tTransversal: number}}
 */
function verdictOf(c, got) {
  const verdict = judge(c, got);
  const hit = got[0] > 0;
  const reason =
    hit && !Array.from(got).every(Number.isFinite)
      ? 'NaN'
      : verdict.failures.length === 0
        ? null
        : hit !== reference(c)[0] > 0
          ? 'hit/miss'
          : verdict.failures.some((f) => f.includes('|t error|'))
            ? 't'
            : 'normal';
  return { reason, tTransversal: verdict.tTransversal };
}

/**
 * What a set of intersectors gets wrong on the hard cases of each primitive: the project's
 * shader as it is, or with peers appended (`source`). One shader run for all primitives.
 * Per kind: the case count, how many are wrong (and of those from outside the solid), the
 * reasons, the worst t error on transversal hits in K u S, the names of the single cases that are
 * wrong, and per family of rays its size and how many of it are wrong.
 * @param {string} source
 * @param {string[]} [kinds]
 */
export async function judgeHardCases(source, kinds = PRIMITIVE_KINDS) {
  const perKind = kinds.map(hardCases);
  const results = await runCases(perKind.flat(), { source });
  let offset = 0;
  return Object.fromEntries(
    kinds.map((kind, k) => {
      const cases = perKind[k];
      const tally = {
        cases: cases.length,
        wrong: 0,
        outside: 0,
        wrongOutside: 0,
        reasons: {},
        worstTransversal: 0,
        wrongNames: [],
        families: {},
      };
      cases.forEach((c, i) => {
        const got = results.slice((offset + i) * 4, (offset + i) * 4 + 4);
        const { reason, tTransversal } = verdictOf(c, got);
        const outside = !startsInside(c);
        if (outside) tally.outside++;
        const family = c.family ? (tally.families[c.family] ??= { cases: 0, wrong: 0 }) : null;
        if (family) family.cases++;
        tally.worstTransversal = Math.max(tally.worstTransversal, tTransversal);
        if (!reason) return;
        tally.wrong++;
        if (outside) tally.wrongOutside++;
        tally.reasons[reason] = (tally.reasons[reason] ?? 0) + 1;
        if (family) family.wrong++;
        else tally.wrongNames.push(c.name);
      });
      offset += cases.length;
      return [kind, tally];
    }),
  );
}
