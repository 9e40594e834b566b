// The watchdog's clock: the work a browser's GPU process has done, not the time on the wall.
//
// On a CPU renderer (SwiftShader, llvmpipe) the GPU process is where a shader runs: its CPU time
// (utime + stime in /proc/PID/stat, the whole thread group, rasterizer threads included) grows
// only while it works. A busy machine slows it down, a stopped process (SIGSTOP) or a suspended
// laptop halts it, and neither adds to its CPU time; an endless shader adds a second of it every
// second it is given, and more on more cores (llvmpipe and SwiftShader draw on every core). So a
// band that has cost the GPU process the watchdog's limit in CPU time without ending is taken
// never to end, however long the wall clock says it took.
//
// Where that cannot be read (no /proc, as on macOS and Windows; no GPU process found under the
// browser) the clock is the wall clock, as the watchdog was before. A hardware GPU draws on the
// GPU, not on the CPU: its GPU process waits, and its CPU time says nothing; it gets the wall
// clock too.

import fs from 'node:fs';
import path from 'node:path';

/**
 * Clock ticks per second of /proc/PID/stat's times: USER_HZ, which Linux fixes at 100 for
 * user space on every architecture Node runs on (`getconf CLK_TCK`).
 */
const TICKS_PER_SECOND = 100;

/** How often a clock without a GPU process looks for one again. */
const SEARCH_EVERY_MS = 1_000;

/**
 * What a clock measures: 'cpu' (the GPU process's CPU time) or 'wall' (the wall clock).
 * @typedef {'cpu' | 'wall'} ClockMeasure
 */

/**
 * Milliseconds of work, only ever growing: differences between two readings are what counts.
 * `measure` says what the last reading measured.
 * @typedef {{now: () => number, readonly measure: ClockMeasure}} WorkClock
 */

/** The wall clock, as a WorkClock. @type {WorkClock} */
export const WALL_CLOCK = Object.freeze({ now: () => performance.now(), measure: /** @type {const} */ ('wall') });

/**
 * The fields of /proc/PID/stat after the process's name (which may hold spaces and parentheses:
 * it ends at the last ')'), from field 3 (state) on; null if it cannot be read.
 * @param {string} proc
 * @param {number} pid
 */
function statFields(proc, pid) {
  let text;
  try {
    text = fs.readFileSync(path.join(proc, String(pid), 'stat'), 'utf8');
  } catch {
    return null;
  }
  const end = text.lastIndexOf(')');
  return end < 0 ? null : text.slice(end + 2).split(' ');
}

/**
 * The CPU time a process has spent, in ms (its threads', living and ended), or null when it is
 * gone or cannot be read. Fields 14 and 15, utime and stime, in clock ticks.
 * @param {number} pid
 * @param {string} [proc]
 */
export function cpuMs(pid, proc = '/proc') {
  const fields = statFields(proc, pid);
  if (!fields) return null;
  const ticks = Number(fields[14 - 3]) + Number(fields[15 - 3]);
  return Number.isFinite(ticks) ? (ticks * 1000) / TICKS_PER_SECOND : null;
}

/**
 * The process under `root` (itself or a descendant: Chromium starts it through a zygote, and
 * /usr/bin/chromium may be a script that starts Chromium as its child) whose command line has
 * `--type=gpu-process`, or null.
 * @param {number} root
 * @param {string} [proc]
 */
export function findGpuProcess(root, proc = '/proc') {
  let names;
  try {
    names = fs.readdirSync(proc);
  } catch {
    return null;
  }
  /** @type {Map<number, number[]>} */
  const children = new Map();
  for (const name of names) {
    if (!/^\d+$/.test(name)) continue;
    const parent = Number(statFields(proc, Number(name))?.[4 - 3]);
    if (!Number.isInteger(parent)) continue;
    children.set(parent, [...(children.get(parent) ?? []), Number(name)]);
  }
  const queue = [root];
  for (let pid = queue.shift(); pid !== undefined; pid = queue.shift()) {
    let command;
    try {
      command = fs.readFileSync(path.join(proc, String(pid), 'cmdline'), 'utf8');
    } catch {
      continue;
    }
    // Chromium rewrites its processes' titles: their arguments joined by spaces, not NULs
    if (/(?:^|[\0 ])--type=gpu-process(?:[\0 ]|$)/.test(command)) return pid;
    queue.push(...(children.get(pid) ?? []));
  }
  return null;
}

/**
 * The watchdog's clock for a browser launched as process `root`: the CPU time of its GPU process
 * while one is found, the wall clock while none is (a reading adds what passed since the last
 * one, by the measure at hand, so that the clock only grows). A new GPU process (Chromium starts
 * another after a crash) is counted from its first reading.
 * @param {number | undefined} root the browser's process id (none: the wall clock)
 * @param {{proc?: string, wall?: () => number}} [options] a /proc and a wall clock (for tests)
 * @returns {WorkClock}
 */
export function gpuClock(root, { proc = '/proc', wall = () => performance.now() } = {}) {
  if (root === undefined || !fs.existsSync(path.join(proc, 'self', 'stat'))) return { ...WALL_CLOCK, now: wall };
  /** @type {number | null} */
  let gpu = null;
  let searched = -Infinity;
  let total = 0;
  /** @type {{measure: ClockMeasure, pid: number | null, at: number} | null} */
  let last = null;
  /** @type {ClockMeasure} */
  let measure = 'wall';

  /** @returns {{measure: ClockMeasure, pid: number | null, at: number}} */
  const read = () => {
    if (gpu !== null) {
      const spent = cpuMs(gpu, proc);
      if (spent !== null) return { measure: 'cpu', pid: gpu, at: spent };
      gpu = null; // gone: look for another
    }
    const now = wall();
    if (now - searched >= SEARCH_EVERY_MS) {
      searched = now;
      gpu = findGpuProcess(root, proc);
      const spent = gpu === null ? null : cpuMs(gpu, proc);
      if (gpu !== null && spent !== null) return { measure: 'cpu', pid: gpu, at: spent };
    }
    return { measure: 'wall', pid: null, at: now };
  };

  return {
    now() {
      const reading = read();
      if (last && last.measure === reading.measure && last.pid === reading.pid) total += Math.max(0, reading.at - last.at);
      last = reading;
      measure = reading.measure;
      return total;
    },
    get measure() {
      return measure;
    },
  };
}
