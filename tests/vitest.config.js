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

export default defineConfig({
  root: fileURLToPath(new URL('..', import.meta.url)),
  test: {
    environment: 'node',
    include: ['tests/**/*.test.js'],
    // Starts one headless Chromium (SwiftShader) and serves the built page for the whole run.
    globalSetup: ['tests/support/setup.js'],
    // The browser is shared and SwiftShader uses every core: one test file at a time.
    fileParallelism: false,
    maxWorkers: 1,
    testTimeout: 120_000,
    hookTimeout: 120_000,
    teardownTimeout: 30_000,
  },
});
