// The project's render goldens, run by `shaderproof test`'s own runner (src/runner/: the
// manifest, runCases, runCase, the guard) in the test process, as MapLibre runs its render
// tests: tests/golden/ is a `test` folder (shaderproof.json, __references__/), each of its cases
// is drawn on the engine page by a command-line session, and a vitest test of its own
// (tests/browser/render.test.js) fails with the runner's words and the paths of its images.
//
// The references are written by the runner's --update, which `npm run test:update`
// (UPDATE_GOLDENS=1) turns on, and by nothing else; always by SwiftShader (setup.js refuses
// another renderer), and `__references__/drawn-by.json` says what drew them. Another renderer
// (`npm run test:llvmpipe`) compares its pictures with SwiftShader's, each case at its manifest
// tolerance for that renderer where it gives one.

import fs from 'node:fs';
import path from 'node:path';
import { findCases, readManifest, REFERENCE_DIR, toleranceFor } from '../../src/runner/manifest.js';
import { runCases } from '../../src/runner/runner.js';
import { silenceLimitMs } from '../../src/runner/guard.js';
import { drawnByDifference, drawnByNow, readDrawnBy, writeDrawnBy } from '../../src/runner/drawn-by.js';
import { startSession } from '../../src/headless/session.js';
import { WATCHDOG_LIMITS } from '../../src/headless/watchdog/limits.js';
import { readPng } from '../../src/headless/png.js';
import { GOLDEN_DIR, OUTPUT_DIR, UPDATE_COMMAND, UPDATING, rel } from './config.js';
import { harnessContext } from './page.js';
import { sameImage } from './images.js';

/** Where a failed case's actual, reference and diff PNGs go (ignored by git). */
const GOLDEN_OUTPUT = path.join(OUTPUT_DIR, 'golden');
export const REFERENCES = path.join(GOLDEN_DIR, REFERENCE_DIR);

const manifest = readManifest(GOLDEN_DIR);
/**
 * The goldens' cases, as `shaderproof test tests/golden` reads them, in the manifest's order (the
 * runner sorts them by name): views that share a program (the same compile-time controls) follow
 * each other, so that the page compiles it once for them, not again after each other view.
 */
export const GOLDEN_CASES = findCases(GOLDEN_DIR, manifest).sort(
  (a, b) => Object.keys(manifest.cases).indexOf(a.name) - Object.keys(manifest.cases).indexOf(b.name),
);

/** @typedef {import('../../src/headless/session.js').Session} Session */

/** The session the cases are drawn on, kept from one case to the next; null once it is given up. */
let kept = /** @type {Promise<Session> | null} */ (null);
/** What draws, once known. @type {{renderer: string, chromium: string, rendererName: any, label: string} | null} */
let environment = null;
/** Whether --update wrote a reference in this run. */
let wrote = false;

/** The suite's renderer: SwiftShader, or $SHADERPROOF_RENDERER (`npm run test:llvmpipe`). */
async function renderer() {
  return (await harnessContext()).environment.rendererName;
}

/** The kept session, started on the suite's renderer when there is none. @returns {Promise<Session>} */
export function goldenSession() {
  kept ??= renderer().then((name) => startSession({ renderer: name }));
  return kept;
}

/**
 * A view of the kept session for runCases: its close leaves it open for the next case; its kill
 * (the runner gave a case up: its browser stopped answering) gives it up for good, and the next
 * case starts another.
 * @returns {Promise<Session>}
 */
async function sessionForRunner() {
  const session = await goldenSession();
  return {
    ...session,
    close: async () => {},
    kill: async () => {
      kept = null;
      await session.kill();
      await session.close();
    },
  };
}

/** Closes the kept session (afterAll), and with --update records what drew the references. */
export async function closeGoldens() {
  const session = kept && (await kept.catch(() => null));
  kept = null;
  await session?.close();
  if (UPDATING && wrote && environment) writeDrawnBy(REFERENCES, drawnByNow(environment));
}

/** Why a failure may be the renderer's and not the picture's, in a line, or ''. */
function drawnByNote() {
  if (!environment) return '';
  const recorded = readDrawnBy(REFERENCES);
  const now = drawnByNow(environment);
  const was = recorded?.renderer ?? 'swiftshader';
  if (was !== now.renderer)
    return (
      `\nThis run draws with ${now.renderer}, and the goldens are ${was}'s: if the diff shows only a rasterizer's rounding, ` +
      `give the case its own "${now.renderer}" tolerance in ${rel(path.join(GOLDEN_DIR, 'shaderproof.json'))} with the measurement; never regenerate the goldens on it.`
    );
  const differs = recorded ? drawnByDifference(recorded, now) : '';
  return differs
    ? `\nWhat draws differs from what drew the goldens (${differs}): if the diff shows only that, regenerate them with \`${UPDATE_COMMAND}\` here.`
    : '';
}

/**
 * Runs the case `name` through the runner (with --update under UPDATE_GOLDENS=1) and returns its
 * result; throws, with the runner's failures, the images' paths and what to do, when it failed.
 * @param {string} name
 * @returns {Promise<{result: import('../../src/runner/case.js').CaseResult, testCase: import('../../src/runner/manifest.js').TestCase}>}
 */
export async function runGolden(name) {
  const testCase = GOLDEN_CASES.find((c) => c.name === name);
  if (!testCase) throw new Error(`no case ${name} in ${rel(GOLDEN_DIR)}`);
  const before = UPDATING && fs.existsSync(testCase.reference) ? readPng(testCase.reference) : null;
  const rendererName = await renderer();
  (await goldenSession()).takeLogged(); // what an earlier case's page logged is that case's
  const { results, environment: drawnBy } = await runCases([testCase], {
    jobs: 1,
    start: sessionForRunner,
    silenceMs: silenceLimitMs(WATCHDOG_LIMITS[rendererName]),
    run: { update: UPDATING, out: GOLDEN_OUTPUT, thumbnails: false },
  });
  environment = drawnBy;
  const [result] = results;
  // no golden passes on a page that logged an error (the runner leaves that to the page's notes)
  const logged = kept ? (await kept).takeLogged() : [];
  if (logged.length) {
    result.ok = false;
    result.failures.push(`the page logged errors:\n    ${logged.join('\n    ')}`);
  }
  if (UPDATING && result.ok) {
    wrote = true;
    if (!before || !sameImage(before, readPng(testCase.reference)))
      console.log(`${before ? 'updated' : 'created'} ${rel(testCase.reference)}`);
  }
  if (result.ok) return { result, testCase };
  const files = Object.entries(result.files).map(([kind, file]) => `\n  ${`${kind}:`.padEnd(11)}${rel(path.join(GOLDEN_OUTPUT, file))}`);
  const { threshold, maxDiffPixels } = toleranceFor(testCase, rendererName);
  throw new Error(
    `${name} (${rel(testCase.reference)}, drawn by ${drawnBy.label}; tolerance: threshold ${threshold}, at most ${maxDiffPixels} pixels):\n  ` +
      `${result.failures.join('\n  ')}${files.join('')}\n` +
      `If the change is intended, run \`${UPDATE_COMMAND}\` and review the new goldens.${drawnByNote()}`,
  );
}
