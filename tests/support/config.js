// Where the harness finds and writes things, and the switches every part of it shares.
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const REPO_ROOT = fileURLToPath(new URL('../..', import.meta.url));
/** The render goldens: a `shaderproof test` folder (shaderproof.json, __references__/). */
export const GOLDEN_DIR = path.join(REPO_ROOT, 'tests', 'golden');
/** Failure images (actual, expected, diff): ignored by git. */
export const OUTPUT_DIR = path.join(REPO_ROOT, 'tests', 'output');
export const SHADER_FILE = path.join(REPO_ROOT, 'shaders', 'raytrace.glsl');
export const UPDATE_COMMAND = 'npm run test:update';
/** Goldens are written only when this is set (by `npm run test:update`): the runner's --update. */
export const UPDATING = process.env.UPDATE_GOLDENS === '1';

/**
 * The page's timeouts shortened for the tests that wait for one (src/shared/timeouts.js): a test
 * never waits out a production timeout. Opt-in per page (openPage's `timeouts`): an ordinary
 * page keeps the production ones, since under load a normal band of the raytracer can take
 * longer than half a second. compileHangMs stays above the raytracer's slowest first draw here
 * (the torus scene's, ~3.5 s alone, more under load) for the pages that draw it.
 */
export const SHORT_TIMEOUTS = Object.freeze({ loadMs: 1_500, hangMs: 500, compileHangMs: 8_000, workerStartMs: 2_000 });

/** A path as the messages show it: relative to the repository. */
export const rel = (file) => path.relative(REPO_ROOT, file);
