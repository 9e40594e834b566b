// The test runner's config (npm test passes it with --config). It is separate from vite.config.js
// (which serves the page from src/player/) so that the tests run from the repository root;
// tests/support/setup.js starts that page server itself.
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vitest/config';
import { findChrome } from '../src/headless/chrome-path.js';

// No Chromium, no test can run: say so and how to install one before vitest prints anything
// (its banner, then "No test files found" and a stack, if the global setup were left to fail).
// The config is read before vitest's first line; setup.js checks again for scripts.
try {
  findChrome();
} catch (error) {
  console.error(error.message);
  process.exit(1);
}

// The suite draws with SwiftShader, its goldens' renderer, unless SHADERPROOF_RENDERER names
// another (`npm run test:llvmpipe`); the command line the tests start inherits the same, so that
// its default (llvmpipe where Mesa is installed) does not change what the suite compares.
process.env.SHADERPROOF_RENDERER ||= 'swiftshader';

/** What both projects share. */
const COMMON = { environment: /** @type {const} */ ('node'), testTimeout: 120_000, hookTimeout: 120_000, teardownTimeout: 30_000 };

export default defineConfig({
  root: fileURLToPath(new URL('..', import.meta.url)),
  test: {
    projects: [
      // Node alone (tests/unit/): the contract, the runner's logic, the reference, the docs'
      // checks. No browser: their files run in parallel, on every core.
      { test: { ...COMMON, name: 'unit', include: ['tests/unit/**/*.test.js'] } },
      // Through headless Chromium (tests/browser/, and the benchmark's peers): one browser and
      // one page server for the whole run (tests/support/setup.js). SwiftShader uses every
      // core and the browser is shared: one file at a time.
      {
        test: {
          ...COMMON,
          name: 'browser',
          include: ['tests/browser/**/*.test.js', 'tests/bench/**/*.test.js'],
          globalSetup: ['tests/support/setup.js'],
          fileParallelism: false,
          maxWorkers: 1,
        },
      },
    ],
  },
});
