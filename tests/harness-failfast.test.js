// The harness fails fast and says why (issue 12): no Chromium is said before anything else.
import { spawn } from 'node:child_process';
import { expect, test } from 'vitest';
import { REPO_ROOT } from './harness/config.js';
import { INSTALL_HINT } from './harness/chrome-path.js';

/** npm test with no Chromium must stop well within this: it starts nothing. */
const NO_CHROME_TIMEOUT_MS = 60_000;

/** Runs `npm test` with `env` added; resolves with its exit code and everything it printed, in order. */
function npmTest(env) {
  return new Promise((resolve, reject) => {
    // the child must not take itself for a worker of this run
    const base = Object.fromEntries(Object.entries(process.env).filter(([k]) => !/^(VITEST|TEST$|NODE_ENV$)/.test(k)));
    const child = spawn('npm', ['test'], { cwd: REPO_ROOT, env: { ...base, ...env }, stdio: ['ignore', 'pipe', 'pipe'] });
    let output = '';
    child.stdout.on('data', (d) => (output += d));
    child.stderr.on('data', (d) => (output += d));
    const timer = setTimeout(() => {
      child.kill('SIGKILL');
      reject(new Error(`npm test with no Chromium still ran after ${NO_CHROME_TIMEOUT_MS} ms:\n${output}`));
    }, NO_CHROME_TIMEOUT_MS);
    child.on('error', reject);
    child.on('close', (code) => {
      clearTimeout(timer);
      resolve({ code, output });
    });
  });
}

test(
  'with CHROME_PATH naming no file, the first line npm test prints is the install hint',
  async () => {
    const { code, output } = await npmTest({ CHROME_PATH: '/nonexistent/chromium' });
    // npm's own lines (its warnings, "> name@version test", the command) come first; then ours
    const lines = output.split('\n').filter((line) => line.trim() && !/^(> |npm (warn|notice|error))/.test(line));
    expect(lines[0], output).toBe(`CHROME_PATH is /nonexistent/chromium, which does not exist. ${INSTALL_HINT}`);
    expect(code).not.toBe(0);
  },
  NO_CHROME_TIMEOUT_MS + 10_000,
);
