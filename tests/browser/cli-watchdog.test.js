// The command line's watchdog counts the work of the browser's GPU process, not the wall clock
// (issue 50, part 3; src/headless/watchdog/gpu-time.js, band-watch.js): a finite frame whose GPU process is
// stopped (SIGSTOP) for seconds in its middle finishes, with the same bytes as without the stop,
// on each CPU renderer; a shader that never finishes fails `render` within the default watchdog
// at 320×180 and at 1280×720.

import { execFile } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { promisify } from 'node:util';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { renderShader } from '../../src/api/render.js';
import { startSession } from '../../src/headless/session.js';
import { readViewOptions } from '../../src/api/view-options.js';
import { cpuMs, findGpuProcess } from '../../src/headless/watchdog/gpu-time.js';
import { builtPage } from '../../src/headless/page-server.js';
import { findMesa } from '../../src/headless/renderers.js';
import { REPO_ROOT } from '../support/config.js';

const run = promisify(execFile);
const BIN = path.join(REPO_ROOT, 'bin', 'shaderproof.js');

let folder = '';
beforeAll(async () => {
  folder = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-watchdog-'));
  await builtPage();
});
afterAll(() => fs.rmSync(folder, { recursive: true, force: true }));

const write = (/** @type {string} */ name, /** @type {string} */ text) => {
  fs.writeFileSync(path.join(folder, name), text);
  return path.join(folder, name);
};

/** The CPU renderers here: SwiftShader always, llvmpipe where Mesa is. */
/** @type {('swiftshader' | 'llvmpipe')[]} */
const RENDERERS = findMesa().missing.length === 0 ? ['swiftshader', 'llvmpipe'] : ['swiftshader'];

/**
 * A finite frame of the same cost at every pixel: TRIPS trips of two sines each. At 128x72, about
 * 2 s of drawing on SwiftShader and on llvmpipe (given more trips: it is that much faster, and
 * under its loop limit of 65,535, past which it would not draw the frame at all) on a quiet
 * 2-core machine, in bands of a few rows.
 * @param {number} trips
 */
const finite = (trips) => `void mainImage(out vec4 c, in vec2 f) {
    float s = 0.0;
    for (int i = 0; i < ${trips}; i++) s += abs(sin(float(i) * 0.001 + f.x * 0.1 + f.y)) + abs(sin(float(i) * 0.002 - f.y));
    c = vec4(fract(s * 0.001), fract(s * 0.0001), f.x / iResolution.x, 1.0);
}
`;
const TRIPS = { swiftshader: 12_500, llvmpipe: 60_000 };

/** How long the GPU process is stopped: longer than the band watchdog the test runs with, on any clock. */
const STOP_MS = 5_000;
/** The test's watchdog: a band may cost 2 s (of CPU time), a compile 30 s. */
const LIMITS = { hangMs: 2_000, compileHangMs: 30_000 };

describe('a finite frame whose GPU process is stopped in its middle', () => {
  test.each(RENDERERS)('%s: finishes, with the same bytes as without the stop', async (renderer) => {
    const file = write(`finite-${renderer}.glsl`, finite(TRIPS[renderer]));
    const view = readViewOptions({ size: '128x72' }, { width: 128, height: 72 });
    let armed = false;
    /** @type {{pid: number, rows: number, height: number, cpuBefore: number | null, cpuAfter?: number | null} | null} */
    let stop = null;
    /** @type {Promise<void> | null} */
    let resumed = null;
    /** Lets a stopped process go on (if it is still there: a watchdog that gave up killed it). @param {number} pid */
    const resume = (pid) => {
      try {
        process.kill(pid, 'SIGCONT');
      } catch {
        // gone
      }
    };
    /** @param {import('../../src/headless/view.js').ViewProgress | null} state */
    const progress = (state) => {
      if (!armed || stop || !state || state.bands < 1 || state.rows >= state.height) return;
      const pid = findGpuProcess(process.pid);
      if (pid === null) throw new Error('no GPU process under this test process');
      process.kill(pid, 'SIGSTOP');
      const stopped = { pid, rows: state.rows, height: state.height, cpuBefore: cpuMs(pid) };
      stop = stopped;
      resumed = new Promise((resolve) =>
        setTimeout(() => {
          stopped.cpuAfter = cpuMs(pid);
          resume(pid);
          resolve();
        }, STOP_MS),
      );
    };
    const session = await startSession({ renderer, ...LIMITS, progress });
    try {
      const plain = await renderShader(session, file, view);
      armed = true;
      const started = Date.now();
      const held = await renderShader(session, file, view);
      const took = Date.now() - started;
      const { rows, height, cpuBefore, cpuAfter } = /** @type {any} */ (stop ?? {});
      expect(stop, 'the GPU process was stopped while the frame was under way').not.toBeNull();
      console.log(`${renderer}: stopped at ${rows}/${height} rows for ${STOP_MS} ms; the frame took ${took} ms`);
      expect(rows).toBeLessThan(height);
      expect(cpuAfter, 'a stopped process spends no CPU time').toBe(cpuBefore);
      expect(took).toBeGreaterThanOrEqual(STOP_MS);
      expect([held.width, held.height]).toEqual([plain.width, plain.height]);
      expect(Buffer.compare(Buffer.from(held.data), Buffer.from(plain.data)), 'the same bytes').toBe(0);
    } finally {
      const { pid } = /** @type {any} */ (stop ?? {});
      await resumed;
      if (pid) resume(pid);
      await session.close();
    }
  });
});

describe('a shader that never finishes fails render within the default watchdog', () => {
  // On SwiftShader: llvmpipe ends a loop after 65,535 trips (a matter of its own), so that a
  // shader without end finishes there, in bands the watchdog lets go on
  const ENDLESS =
    'void mainImage(out vec4 c, in vec2 f) { float s = 0.0; for (int i = 0; ; i++) { s += abs(sin(float(i) + f.x)); if (s < -1.0) break; } c = vec4(s); }\n';
  // the start (~8 s on a quiet 2-core machine), the compile, then a band's 5 s of CPU time (on
  // two cores, 2.5 s of the wall clock), and the kill: within 45 s on a quiet machine. A busy
  // one gives the GPU process less of the CPU, and the watchdog waits for its 5 s: beside other
  // work (load 19 to 22 here) it took 26 s and 43 s, so the bound grows with the load.
  const BOUND_S = 45 * Math.max(1, os.loadavg()[0] / os.cpus().length);
  test.each(['320x180', '1280x720'])('swiftshader at %s', async (size) => {
    write('endless.glsl', ENDLESS);
    const started = Date.now();
    const out = await run(
      process.execPath,
      [BIN, 'render', 'endless.glsl', '-o', 'endless.png', '--size', size, '--renderer', 'swiftshader'],
      {
        cwd: folder,
        timeout: 110_000,
      },
    ).then(
      () => ({ code: 0, stderr: '' }),
      (error) => ({ code: error.code, stderr: String(error.stderr) }),
    );
    const seconds = (Date.now() - started) / 1000;
    console.log(
      `swiftshader ${size}: failed in ${seconds.toFixed(1)} s (load ${os.loadavg()[0].toFixed(1)}, bound ${BOUND_S.toFixed(0)} s)`,
    );
    expect(out.code).toBe(1);
    expect(out.stderr.trim().split('\n')).toEqual([
      expect.stringMatching(
        /^shaderproof render: endless\.glsl: did not finish drawing a frame: one band of it used more than the watchdog's 5 s of the GPU process's CPU time \(30 s for a program's first draw, which compiles it\);/,
      ),
    ]);
    expect(seconds).toBeLessThan(BOUND_S);
    expect(fs.existsSync(path.join(folder, 'endless.png'))).toBe(false);
  });
});
