// The benchmark's report (results.md, and the table in docs/benchmark.md): each renderer's
// results side by side, one table a size; the comparisons the CPU renderers are judged by (the
// project against its peers, the torus scene against the cone, adaptive against uniform); and
// each renderer's targets. Pure text from results.json's contents (results-file.js).

import { rendererLabel } from '../../src/headless/browser.js';
import { paretoFront } from './chart.js';
import { RENDERER_TITLES } from './renderer-set.js';
import {
  PLAIN,
  SCENES_GROUP,
  STANDALONE,
  adaptiveSamples,
  evaluateAdaptiveTargets,
  evaluateRendererTargets,
  evaluateSceneTargets,
  evaluateTargets,
  sceneVariant,
  uniformSamples,
} from './targets.js';

/** @typedef {import('./results-file.js').Entry} Entry */
/** @typedef {import('./results-file.js').ResultsByRenderer} ResultsByRenderer */

/** The renderers of a results file in the order a report shows them: the CPU ones first. */
export function rendererOrder(results) {
  const known = Object.keys(RENDERER_TITLES);
  return Object.keys(results).sort((a, b) => known.indexOf(a) - known.indexOf(b));
}

const title = (name) => RENDERER_TITLES[name] ?? name;
const ms = (r) => `${r.medianMs.toFixed(1)} (${r.minMs.toFixed(1)}–${r.maxMs.toFixed(1)})`;
const times = (a, b) => `${(a / b).toFixed(2)}×`;
/** One value, or each renderer's where they differ as printed. */
const agreed = (values) => (new Set(values).size === 1 ? values[0] : values.join(' / '));

/** The entries of one renderer at one width, in the variants' order. @param {Entry[]} entries */
const atWidth = (entries, width) => entries.filter((r) => r.width === width);
/** The same scene as the default view's (the other scenes are other pictures). @param {Entry[]} entries */
const sameScene = (entries) => entries.filter((r) => r.group !== SCENES_GROUP);

/** The sizes measured, largest last. @param {ResultsByRenderer} results */
export function sizesOf(results) {
  const sizes = new Map();
  for (const { results: entries } of Object.values(results)) for (const r of entries) sizes.set(r.width, r.height);
  return [...sizes].sort((a, b) => a[0] - b[0]);
}

/**
 * One size's table: a row a variant, each renderer's median (min–max) beside the other's, how many
 * times faster the second renderer is, the error (one value where the renderers agree to the
 * digits shown) and whether the variant is on each renderer's Pareto front.
 * @param {ResultsByRenderer} results
 * @param {number} width
 */
export function sideBySideTable(results, width) {
  const names = rendererOrder(results);
  const rows = names.map((name) => atWidth(results[name].results, width));
  const fronts = rows.map((entries) => new Set(paretoFront(sameScene(entries)).map((r) => r.name)));
  const variants = [...new Set(rows.flatMap((entries) => entries.map((r) => r.name)))];
  const pair = names.length === 2;
  const header = [
    'variant',
    'spp',
    ...names.map((n) => `${title(n)} ms`),
    ...(pair ? [`faster on ${title(names[1])}`] : []),
    'RMSE',
    '>2/255',
    `Pareto (${names.map(title).join(', ')})`,
  ];
  const lines = [
    `| ${header.join(' | ')} |`,
    `|${header.map((_, i) => (i >= 2 && i < 2 + names.length + (pair ? 1 : 0) ? '---:|' : '---|')).join('')}`,
  ];
  for (const variant of variants) {
    const each = rows.map((entries) => entries.find((r) => r.name === variant));
    const any = each.find(Boolean);
    const extra = each.filter((r) => r?.extraSampleFraction !== undefined).map((r) => `${(100 * r.extraSampleFraction).toFixed(2)}%`);
    const spp = `${any.samplesPerPixel}${extra.length ? ` at edges (${agreed(extra)} of pixels)` : ''}`;
    const cells = [
      variant,
      spp,
      ...each.map((r) => (r ? ms(r) : '')),
      ...(pair ? [each[0] && each[1] ? times(each[0].medianMs, each[1].medianMs) : ''] : []),
      agreed(each.filter(Boolean).map((r) => r.rmse.toFixed(4))),
      agreed(each.filter(Boolean).map((r) => `${(100 * r.over2).toFixed(2)}%`)),
      any.group === SCENES_GROUP ? '' : fronts.map((front) => (front.has(variant) ? '●' : '·')).join(' '),
    ];
    lines.push(`| ${cells.join(' | ')} |`);
  }
  const floors = rows.map((entries, i) => {
    const floor = entries.find((r) => r.group === 'floor');
    return floor ? `${floor.medianMs.toFixed(1)} ms on ${title(names[i])}` : null;
  });
  if (floors.some(Boolean)) lines.push('', `Floor: the empty shader takes ${floors.filter(Boolean).join(', ')} at this size.`);
  return lines.join('\n');
}

/**
 * The comparisons the renderers are judged by, at one size: a row each, one column a renderer
 * (the ratio, then the two medians).
 * @param {ResultsByRenderer} results
 * @param {number} width
 */
export function comparisonTable(results, width) {
  const names = rendererOrder(results);
  const COMPARISONS = [
    ['the project at 1 spp, against the standalone plain peer (time)', uniformSamples(1), STANDALONE],
    ['the project at 1 spp, against the spliced plain analytic peer (time)', uniformSamples(1), PLAIN],
    ['the torus scene, against the cone scene', sceneVariant(2), uniformSamples(1)],
    ['adaptive 16 at edges, against 1 spp', adaptiveSamples(16), uniformSamples(1)],
    ['adaptive 16 at edges, against uniform 16 spp', adaptiveSamples(16), uniformSamples(16)],
  ];
  const lines = [`| ratio of times | ${names.map(title).join(' | ')} |`, `|---|${names.map(() => '---:|').join('')}`];
  for (const [label, a, b] of COMPARISONS) {
    const cells = names.map((name) => {
      const entries = atWidth(results[name].results, width);
      const ra = entries.find((r) => r.name === a);
      const rb = entries.find((r) => r.name === b);
      return ra && rb ? `${times(ra.medianMs, rb.medianMs)} (${ra.medianMs.toFixed(1)} / ${rb.medianMs.toFixed(1)} ms)` : '';
    });
    lines.push(`| ${label} | ${cells.join(' | ')} |`);
  }
  return lines.join('\n');
}

/** How a renderer's figures were measured, in a sentence. @param {import('./results-file.js').Run | null} run */
function runSentence(run) {
  if (!run) return 'run not recorded';
  const load = run.loadAverage.map((l) => l.toFixed(1)).join(' at its start, ');
  return `${run.started.slice(0, 16).replace('T', ' ')} UTC, ${run.renderers.length > 1 ? `interleaved with ${run.renderers.length - 1} other renderer${run.renderers.length > 2 ? 's' : ''} round by round` : 'alone'}, ${run.cores} cores (${run.cpu}), load average ${load} at its end`;
}

/** A list of targets as markdown bullets. */
const bullets = (targets) => targets.map((t) => `- ${t.met ? 'met' : '**missed**'}: ${t.text}`);

/**
 * The whole report: how it was measured, the comparisons, each size's table, each renderer's
 * targets.
 * @param {ResultsByRenderer} results
 */
export function benchMarkdown(results) {
  const names = rendererOrder(results);
  const sizes = sizesOf(results);
  const [w, h] = sizes.find(([width]) => width === 640) ?? sizes[0];
  const first = results[names[0]];
  const { copies, frames, warmup } = first.run ?? { copies: 3, frames: 5, warmup: 2 };
  const sameRun = names.every((n) => results[n].run && results[n].run.started === first.run?.started);
  const out = [
    `Measured by \`npm run bench\`; median (min–max) of ${copies * frames} frames (${copies} compilations of each variant, ${frames} frames each after ${warmup} warm-up frames), all variants interleaved frame by frame${names.length > 1 ? (sameRun ? ', and the renderers round by round in the same run' : '; the renderers in separate runs') : ''}. Error against the converged float64 reference of the default scene (the other scenes: against their own).`,
    '',
    ...names.map((n) => {
      const entry = results[n].results[0];
      return `- ${title(n)}: ${rendererLabel(entry.renderer)}, ${entry.chromium}; ${runSentence(results[n].run)}.`;
    }),
    '',
    `### The comparisons at ${w}×${h}`,
    '',
    comparisonTable(results, w),
  ];
  for (const [width, height] of sizes) out.push('', `### ${width}×${height}`, '', sideBySideTable(results, width));
  for (const name of names) {
    const entries = results[name].results;
    const at = (width) => atWidth(entries, width);
    out.push(
      '',
      `### Targets on ${title(name)} at ${w}×${h}`,
      '',
      "Issue 44's, set for llvmpipe:",
      '',
      ...bullets(evaluateRendererTargets(at(w))),
      '',
      'At 1 sample per pixel:',
      '',
      ...bullets(evaluateTargets(sameScene(at(w)))),
      '',
      ...sizes.flatMap(([width, height]) => [
        `Adaptive anti-aliasing at ${width}×${height}:`,
        '',
        ...bullets(evaluateAdaptiveTargets(sameScene(at(width)))),
        '',
      ]),
      'The scenes:',
      '',
      ...bullets(evaluateSceneTargets(at(w))),
    );
  }
  return out.join('\n');
}
