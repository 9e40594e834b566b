// `shaderproof` run as its users run it, a child process of its own: what it exits with and what
// it writes, whatever the exit code (a failure is an answer to check, not a throw).

import { execFile } from 'node:child_process';
import path from 'node:path';
import { promisify } from 'node:util';
import { REPO_ROOT } from './config.js';

const run = promisify(execFile);

/** The checkout's command line. */
const BIN = path.join(REPO_ROOT, 'bin', 'shaderproof.js');

/**
 * Runs `node bin args…` in `cwd`: { code, stdout, stderr }. Throws only where it could not run.
 * @param {string[]} args
 * @param {{cwd: string, timeout: number, bin?: string, env?: Record<string, string>}} options
 *   bin: another install's (BIN by default); env: added to this process's
 */
export async function runShaderproof(args, { cwd, timeout, bin = BIN, env = {} }) {
  try {
    const { stdout, stderr } = await run(process.execPath, [bin, ...args], { cwd, env: { ...process.env, ...env }, timeout });
    return { code: 0, stdout, stderr };
  } catch (error) {
    if (typeof error.code !== 'number') throw error;
    return { code: error.code, stdout: error.stdout, stderr: error.stderr };
  }
}
