// The per-primitive table of npm run bench:primitives (primitives.js), as Markdown: speed against
// error per primitive, the project's intersector and its iq-style peer side by side.

const FORM_NAMES = { ours: 'ours', iq: 'iq-style' };
const REASON_ORDER = ['hit/miss', 't', 'normal', 'NaN'];

const percent = (part, whole) => `${((100 * part) / whole).toFixed(part && part < whole / 100 ? 1 : 0)}%`;
const ns = (x) => (Math.abs(x) < 10 ? x.toFixed(2) : x.toFixed(1));
const ms = (t) => `${t.median.toFixed(1)} ms, ${t.min.toFixed(1)}–${t.max.toFixed(1)}`;
const ratio = (x) => (x >= 1000 ? x.toExponential(1) : x.toPrecision(2));

/** "12 hit/miss, 3 t" from { 't': 3, 'hit/miss': 12 }. */
const reasons = (counts) =>
  REASON_ORDER.filter((r) => counts[r])
    .map((r) => `${counts[r]} ${r}`)
    .join(', ') || '–';

/** What one form gets wrong, family by family and case by case (the primitive's prefix dropped). */
function whereWrong(kind, tally) {
  const families = Object.entries(tally.families)
    .filter(([, f]) => f.wrong > 0)
    .map(([name, f]) => `${name.replace(`${kind} `, '')}: ${f.wrong} of ${f.cases}`);
  const single = tally.wrongNames.map((name) => name.replace(`${kind}: `, ''));
  return [...families, ...(single.length ? [`single cases: ${single.join('; ')}`] : [])].join('; ');
}

/**
 * @param {{timed: Array<{kind: string | null, form: string, ns: {median: number, min: number, max: number}, baselineMs: {median: number, min: number, max: number}, hitShare: number}>,
 *   errors: {ours: object, iq: object},
 *   setup: {width: number, height: number, calls: number, copies: number, frames: number, warmup: number, K: number},
 *   environment: string}} measured
 */
export function primitivesMarkdown({ timed, errors, setup, environment }) {
  const { width, height, calls, copies, frames, warmup, K } = setup;
  const rows = timed.filter((t) => t.kind);
  const ours = (kind) => rows.find((t) => t.kind === kind && t.form === 'ours');
  const table = rows.map((t) => {
    const e = errors[t.form][t.kind];
    const vsOurs = t.form === 'ours' ? '1×' : `${(t.ns.median / ours(t.kind).ns.median).toFixed(2)}×`;
    return [
      t.form === 'ours' ? `**${t.kind}**` : '',
      FORM_NAMES[t.form],
      `${ns(t.ns.median)} (${ns(t.ns.min)}–${ns(t.ns.max)})`,
      vsOurs,
      percent(Math.round(t.hitShare * 1000), 1000),
      `${e.wrong} of ${e.cases} (${percent(e.wrong, e.cases)})`,
      `${e.wrongOutside} of ${e.outside}`,
      reasons(e.reasons),
      ratio(e.worstTransversal),
    ];
  });
  const wrongLines = Object.keys(errors.iq)
    .filter((kind) => errors.iq[kind].wrong > 0)
    .map((kind) => `- **${kind}**: ${whereWrong(kind, errors.iq[kind])}.`);
  return [
    `Measured by \`npm run bench:primitives\` on ${environment}. **Time**: ${calls} calls a pixel at ${width}×${height}, each on its own ray (the pixel's eye ray moved within the pixel by the call index), every result summed into the colour; ns a call (= ms a million calls) is a frame's time less the median frame of the same loop with no intersector (${ms(timed[0].baselineMs)}), over the ${width}×${height}×${calls} calls of a frame. Median and min–max of ${copies * frames} frames (${copies} compilations of each program, ${frames} frames each after ${warmup} warm-up rounds), all programs interleaved frame by frame. **Error**: the primitive's hard cases (tests/intersector-cases/), judged by the verdict the project's intersectors are held to (tests/support/tables/intersector-kinds.js).`,
    '',
    '| primitive | intersector | ns a call: median (min–max) | time vs ours | timed rays that hit | hard cases wrong | of them from outside | wrong as | worst t error, transversal hits (× K u S) |',
    '|---|---|---|---|---|---|---|---|---|',
    ...table.map((cells) => `| ${cells.join(' | ')} |`),
    '',
    `*of them from outside*: the wrong cases among the rays that start outside the solid (iq's article: most of its forms "only work for a ray with origin outside of the primitive"). *wrong as*: what was wrong first: the hit/miss decision, t beyond its tolerance, the normal (direction or length), a NaN. *worst t error*: over the hits with |rd·n| ≥ 0.1 where both sides hit, in units of K u S (K = ${K}, u = 2^-24, S the case's size); the tolerance there is 1. The iq-style peers are in [tests/bench/peers/iq/](../tests/bench/peers/iq/), written from iq's formulas and adapted to the project's contract only (vec4(t, n), a miss t < 0, 0 < t < tMax; the sphere and box take their far root from inside, as the article's forms return it).`,
    '',
    'Where the iq-style forms go wrong:',
    '',
    ...wrongLines,
  ].join('\n');
}
