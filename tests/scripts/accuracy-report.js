// The accuracy table: every hard view (tests/support/tables/hard-views.js) and each scene's default view, rendered by the
// page in headless Chromium and compared with the float64 reference twice: with the same rays
// (arithmetic error alone) and converged (64 jittered samples per pixel, texture point-sampled:
// the total error, aliasing included). Each view is measured at one sample per pixel and with
// adaptive anti-aliasing (16 samples at edges; the same-ray reference takes its extra samples in
// the pixels the shader's "Extra samples" debug view marks). Writes
// tests/accuracy/results.json and the table between the accuracy markers in docs/numerics.md.
//
//   npm run accuracy            (about six minutes on two cores)

import fs from 'node:fs';
import path from 'node:path';
import { imageError } from '../../src/reference/error.js';
import { REPO_ROOT, SHADER_FILE } from '../support/config.js';
import { renderReferenceParallel } from '../support/reference/reference-threads.js';
import { measureSameRay } from '../support/reference/same-ray.js';
import { rendererLabel } from '../../src/headless/browser.js';
import { withHarness } from '../support/setup.js';
import { HARD_VIEWS, referenceView } from '../support/tables/hard-views.js';
import { DEFAULT_SIZE, viewSize } from '../support/tables/views.js';
import { replaceMarkedSection } from './readme-section.js';

const CONVERGED_SAMPLES_PER_AXIS = 8;
// The default view of each scene (SCENE: the cone, the cylinder, the torus), then the hard views.
const VIEWS = [
  { name: 'default', what: 'the default view', params: { time: 0 } },
  { name: 'scene-cylinder', what: 'the default view of the cylinder scene', params: { time: 0, SCENE: 1 } },
  { name: 'scene-torus', what: 'the default view of the torus scene', params: { time: 0, SCENE: 2 } },
  ...HARD_VIEWS,
];

const ADAPTIVE = { SAMPLES: 16, ADAPTIVE_AA: 1 };

const pct = (f) => `${(100 * f).toFixed(3)}%`;
const row = (name, settings, same, converged) =>
  `| ${name} | ${settings} | ${same.rmse.toExponential(1)} | ${same.maxAbs.toFixed(3)} | ${pct(same.over2)} | ${same.nonFinite} | ` +
  `${converged.rmse.toExponential(1)} | ${converged.psnr.toFixed(1)} | ${pct(converged.over1)} | ${pct(converged.over2)} |`;

/** The page's image and its errors against the same-ray reference and the view's converged one. */
async function measure(source, view, converged) {
  const { image, error, share } = await measureSameRay(source, view);
  return { same: error, converged: imageError(image, converged), share };
}

async function main() {
  const source = fs.readFileSync(SHADER_FILE, 'utf8');
  const results = [];
  const context = await withHarness(async (harness) => {
    for (const [i, view] of VIEWS.entries()) {
      const [width, height] = viewSize(view);
      process.stdout.write(`[${i + 1}/${VIEWS.length}] ${view.name}: 1 spp`);
      // The converged reference does not depend on the sampling controls (its samples are its
      // own): one per view serves both rows.
      const converged = await renderReferenceParallel(source, referenceView(view), {
        mode: 'converged',
        samplesPerAxis: CONVERGED_SAMPLES_PER_AXIS,
      });
      const one = await measure(source, { ...view, params: { ...view.params, SAMPLES: 1 } }, converged);
      process.stdout.write(', adaptive');
      const adaptiveView = { ...view, params: { ...view.params, ...ADAPTIVE } };
      const adaptive = await measure(source, adaptiveView, converged);
      const extraSampleFraction = adaptive.share ?? 0;
      console.log(' done');
      results.push({
        name: view.name,
        what: view.what,
        width,
        height,
        sameRays: one.same,
        converged: one.converged,
        adaptive: { ...ADAPTIVE, extraSampleFraction, sameRays: adaptive.same, converged: adaptive.converged },
      });
    }
    return harness;
  });

  const outDir = path.join(REPO_ROOT, 'tests', 'accuracy');
  fs.mkdirSync(outDir, { recursive: true });
  fs.writeFileSync(
    path.join(outDir, 'results.json'),
    JSON.stringify({ environment: context.environment, convergedSamples: CONVERGED_SAMPLES_PER_AXIS ** 2, results }, null, 2) + '\n',
  );
  const table = [
    `Measured by \`npm run accuracy\` at ${DEFAULT_SIZE.join('×')}, at 1 sample per pixel and with adaptive anti-aliasing (16 samples in the pixels it marks, their share in brackets), on ${rendererLabel(context.environment.renderer)} (${context.environment.chromium}).`,
    '',
    '| view | sampling | same-ray RMSE | same-ray max | same-ray >2/255 | NaN/Inf | converged RMSE | converged PSNR (dB) | converged >1/255 | converged >2/255 |',
    '|---|---|---|---|---|---|---|---|---|---|',
    ...results.flatMap((r) => [
      row(r.name, '1 spp', r.sameRays, r.converged),
      row('', `adaptive (${pct(r.adaptive.extraSampleFraction)})`, r.adaptive.sameRays, r.adaptive.converged),
    ]),
  ].join('\n');
  replaceMarkedSection(path.join(REPO_ROOT, 'docs', 'numerics.md'), 'accuracy', table);
  console.log(`\n${table}\n\nwrote tests/accuracy/results.json and the accuracy table in docs/numerics.md`);
}

await main();
