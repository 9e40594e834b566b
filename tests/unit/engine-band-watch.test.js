// The command line's watchdog, in milliseconds and without a browser: its clock (the GPU
// process's CPU time read from a /proc the test writes: src/headless/watchdog/gpu-time.js) and its
// judgement of a band (src/headless/watchdog/band-watch.js) on a clock the test moves. Chromium's own,
// stopped for seconds in a frame, is tests/browser/cli-watchdog.test.js.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { afterEach, beforeEach, describe, expect, test } from 'vitest';
import { BandWatch, answerUnlessOverdue } from '../../src/headless/watchdog/band-watch.js';
import { cpuMs, findGpuProcess, gpuClock } from '../../src/headless/watchdog/gpu-time.js';

let proc = '';
beforeEach(() => {
  proc = fs.mkdtempSync(path.join(os.tmpdir(), 'fake-proc-'));
  fs.mkdirSync(path.join(proc, 'self'));
  fs.writeFileSync(path.join(proc, 'self', 'stat'), '1 (node) R 0');
});
afterEach(() => fs.rmSync(proc, { recursive: true, force: true }));

/**
 * A process in the fake /proc: its parent, command line and CPU time (utime, stime in ticks of
 * 10 ms), its name with a space and parentheses, as a thread's may have.
 * @param {number} pid
 * @param {{parent: number, command: string, utime?: number, stime?: number}} process
 */
function fakeProcess(pid, { parent, command, utime = 0, stime = 0 }) {
  fs.mkdirSync(path.join(proc, String(pid)), { recursive: true });
  // fields 3 (state) to 13, then utime (14) and stime (15), then the rest
  const fields = ['S', parent, 1, 1, 0, -1, 0, 0, 0, 0, 0, utime, stime, 0, 0, 20, 0, 7];
  fs.writeFileSync(path.join(proc, String(pid), 'stat'), `${pid} (Chrome (GPU) x) ${fields.join(' ')}\n`);
  fs.writeFileSync(path.join(proc, String(pid), 'cmdline'), command);
}

describe("the GPU process's CPU time", () => {
  test('utime + stime in ms, read past a name with spaces and parentheses; null when gone', () => {
    fakeProcess(40, { parent: 1, command: 'chromium', utime: 150, stime: 25 });
    expect(cpuMs(40, proc)).toBe(1750);
    expect(cpuMs(41, proc)).toBeNull();
  });

  test('the process with --type=gpu-process under the browser, through its zygote, and not another browser’s', () => {
    fakeProcess(10, { parent: 1, command: '/bin/sh\0/usr/bin/chromium\0' });
    fakeProcess(11, { parent: 10, command: '/usr/lib/chromium/chromium --headless' });
    fakeProcess(12, { parent: 11, command: '/usr/lib/chromium/chromium --type=zygote' });
    fakeProcess(13, { parent: 12, command: '/usr/lib/chromium/chromium --type=gpu-process --no-sandbox' });
    fakeProcess(20, { parent: 1, command: '/usr/lib/chromium/chromium\0--type=gpu-process\0' }); // another browser's
    expect(findGpuProcess(10, proc)).toBe(13);
    expect(findGpuProcess(20, proc)).toBe(20);
    expect(findGpuProcess(11, proc)).toBe(13);
    expect(findGpuProcess(99, proc)).toBeNull();
  });

  test("the clock counts the GPU process's CPU time, and the wall clock while there is none", () => {
    let wall = 0;
    fakeProcess(10, { parent: 1, command: 'chromium' });
    const clock = gpuClock(10, { proc, wall: () => wall });
    expect(clock.now()).toBe(0);
    expect(clock.measure).toBe('wall');
    wall = 500;
    expect(clock.now(), 'no GPU process yet: the wall clock').toBe(500);
    fakeProcess(13, { parent: 10, command: 'chromium --type=gpu-process', utime: 100 });
    wall = 1500; // searched again after a second
    expect(clock.now()).toBe(500);
    expect(clock.measure).toBe('cpu');
    wall = 60_000; // a minute on the wall, 0.3 s of CPU time
    fakeProcess(13, { parent: 10, command: 'chromium --type=gpu-process', utime: 120, stime: 10 });
    expect(clock.now()).toBe(800);
    // the GPU process is gone (a crash), and Chromium starts another
    fs.rmSync(path.join(proc, '13'), { recursive: true });
    fakeProcess(14, { parent: 10, command: 'chromium --type=gpu-process', utime: 5 });
    wall = 61_000;
    expect(clock.now(), 'the new one counted from its first reading').toBe(800);
    fakeProcess(14, { parent: 10, command: 'chromium --type=gpu-process', utime: 25 });
    expect(clock.now()).toBe(1000);
  });

  test('no /proc (macOS, Windows), or no browser process: the wall clock', () => {
    let wall = 100;
    fs.rmSync(path.join(proc, 'self'), { recursive: true });
    const clock = gpuClock(10, { proc, wall: () => wall });
    expect(clock.measure).toBe('wall');
    expect(clock.now()).toBe(100);
    wall = 350;
    expect(clock.now()).toBe(350);
    expect(gpuClock(undefined).measure).toBe('wall');
  });
});

describe('the band watch', () => {
  const LIMITS = { hangMs: 5_000, compileHangMs: 30_000 };
  /** A clock the test moves. */
  const moved = () => {
    const clock = { at: 0, now: () => clock.at, measure: /** @type {const} */ ('cpu') };
    return clock;
  };

  test('a band is overdue after its limit of work; a new band counts again', () => {
    const clock = moved();
    const watch = new BandWatch(LIMITS, clock);
    watch.heard({ band: { compiling: false, serial: 3 }, bands: 1 });
    clock.at = 4_000;
    watch.heard({ band: { compiling: false, serial: 3 }, bands: 1 });
    expect(watch.overdue()).toBe(false);
    clock.at = 5_001;
    expect(watch.overdue()).toBe(true);
    watch.heard({ band: { compiling: false, serial: 4 }, bands: 2 });
    expect(watch.overdue(), 'the next band').toBe(false);
    clock.at = 10_001;
    expect(watch.overdue()).toBe(false);
    clock.at = 10_002;
    expect(watch.overdue()).toBe(true);
  });

  test("a program's first draw gets the compile's limit; before any band is heard of, so does the page", () => {
    const clock = moved();
    const watch = new BandWatch(LIMITS, clock);
    clock.at = 20_000;
    expect(watch.overdue(), 'nothing heard yet: a first draw may be under way').toBe(false);
    watch.heard({ band: { compiling: true, serial: 1 }, bands: 0 });
    clock.at = 49_000;
    expect(watch.overdue()).toBe(false);
    clock.at = 50_001;
    expect(watch.overdue()).toBe(true);
    watch.heard({ band: null, bands: 0 });
    expect(watch.limit, 'between bands of a frame with none drawn: the next may compile').toBe(30_000);
    watch.heard({ band: null, bands: 1 });
    expect(watch.limit).toBe(5_000);
  });

  test('a page that does not answer is a hang once its band is overdue; one that answers is heard', async () => {
    const clock = moved();
    const watch = new BandWatch(LIMITS, clock);
    watch.heard({ band: { compiling: false, serial: 1 }, bands: 1 });
    const silent = answerUnlessOverdue(new Promise(() => {}), watch, 5);
    clock.at = 6_000;
    expect(await silent).toBeNull();
    expect(await answerUnlessOverdue(Promise.resolve('drawn'), watch, 5)).toBe('drawn');
  });
});
