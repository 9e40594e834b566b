// `shaderproof test DIR`: golden-image regression over a folder of any Shadertoy shaders. Each
// .glsl or .json file under DIR is a case (manifest.js reads DIR/shaderproof.json for a case's
// view, tolerance and checks); its reference is DIR/__references__/<case>.png, written by
// --update and by nothing else (case.js runs one). The arguments may choose some of the cases
// (files, sub-folders, view names, --grep, --last-failed: select.js), and --watch reruns them as
// they are saved (watch.js). The cases run on --jobs workers (runner.js),
// each case guarded (guard.js): a shader that does not compile, never finishes or takes its
// browser down fails its own case, and the run goes on. Whatever happens, the run ends with its
// reports (reporters.js: the case lines, junit.xml, index.html) and a summary line, and exits 1
// if any case failed.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { io, sessionOptions } from '../api/io.js';
import { MANIFEST, findCases, readManifest, REFERENCE_DIR } from './manifest.js';
import { lastFailedCases, pickCases, readGrep, readLastRun, readSelection, writeLastRun } from './select.js';
import { keptSessions, watchCases } from './watch.js';
import { junitXml } from './report/junit.js';
import { htmlReport } from './report/html-report.js';
import { dotLine, progressLine, readReporters } from './report/reporters.js';
import { runCases } from './runner.js';
import { silenceLimitMs } from './guard.js';
import { ShaderproofError, startSession } from '../headless/session.js';
import { drawnByDifference, drawnByNow, readDrawnBy, referenceRenderer, writeDrawnBy } from './drawn-by.js';
import { DEFAULT_DATE, UsageError, dateLabel, readDate, readMediaOptions, readNumber } from '../api/view-options.js';

/**
 * The workers without --jobs, measured on this project's 2-core machine (busy with other work),
 * runs of one, two and three workers interleaved, medians compared: two were as fast as one on
 * light cases and faster on heavier ones; three were slower than either (each worker is a
 * Chromium to start, and SwiftShader already draws on every core). Unmeasured on more cores.
 */
export const DEFAULT_JOBS = Math.max(1, Math.min(2, os.availableParallelism()));
/** The most workers --jobs takes: each is a Chromium of its own. */
const MAX_JOBS = 32;

/** "i/n" → {index (0-based), count}. @param {string | undefined} text */
function readShard(text) {
  if (text === undefined) return { index: 0, count: 1 };
  const match = /^(\d+)\/(\d+)$/.exec(text);
  const [i, n] = match ? [Number(match[1]), Number(match[2])] : [0, 0];
  if (!(n >= 1 && i >= 1 && i <= n)) throw new UsageError(`--shard ${text}: expected i/n with 1 <= i <= n, such as --shard 2/4`);
  return { index: i - 1, count: n };
}

/**
 * Says, in one line, when this run draws with another renderer than the references' (asked for:
 * each case is then compared at its manifest's tolerance), or when what draws differs in what can
 * change pixels (drawn-by.js).
 * @param {import('./drawn-by.js').DrawnBy | null} recorded
 * @param {boolean} hasReferences
 * @param {import('./drawn-by.js').DrawnBy} now
 * @param {{update: boolean, keepsRecord: boolean, referenceDir: string, say: (line: string) => void}} run keepsRecord: an
 *   --update of some cases, beside references of others that drawn-by.json speaks for
 */
function sayDrawnBy(recorded, hasReferences, now, { update, keepsRecord, referenceDir, say }) {
  const file = path.join(referenceDir, 'drawn-by.json');
  if (update) {
    if (keepsRecord && recorded && drawnByDifference(recorded, now))
      say(
        `note: ${file} is kept for the references of the cases not chosen, and what draws the chosen ones differs (${drawnByDifference(recorded, now)}); update the whole folder to draw them all alike`,
      );
    return;
  }
  const was = recorded?.renderer ?? (hasReferences ? 'swiftshader' : null);
  if (was && was !== now.renderer)
    say(
      `note: the references were drawn by ${was}, and this run draws with ${now.renderer} as asked: each case is compared at its manifest's tolerance (its "${now.renderer}" one where it gives one)`,
    );
  else if (recorded && drawnByDifference(recorded, now))
    say(`note: what draws differs from what drew the references (${file}): ${drawnByDifference(recorded, now)}`);
}

/** Every reference PNG under `referenceDir`, by its path. @param {string} referenceDir */
function referencePngs(referenceDir) {
  if (!fs.existsSync(referenceDir)) return [];
  return fs
    .readdirSync(referenceDir, { recursive: true, encoding: 'utf8' })
    .filter((name) => name.endsWith('.png'))
    .map((name) => path.join(referenceDir, name));
}

/**
 * SIGINT or SIGTERM (Ctrl-C), for --watch: `off` stops listening. Puppeteer's own SIGINT handler
 * kills its browsers and exits 130 at once (@puppeteer/browsers, launch.js): the exit code is
 * then set to `code()`, that of the latest results, as the process exits.
 * @param {() => number} code
 */
function signalled(code) {
  /** @type {() => void} */
  let on = () => {};
  const exiting = () => (process.exitCode = code());
  const promise = new Promise((resolve) => {
    on = () => resolve(undefined);
    process.once('SIGINT', on);
    process.once('SIGTERM', on);
    process.once('exit', exiting);
  });
  return { promise, off: () => (process.off('SIGINT', on), process.off('SIGTERM', on), process.off('exit', exiting)) };
}

/**
 * `shaderproof test`: the run, its lines on stderr and stdout; the exit code.
 * @param {{values: Record<string, any>, positionals: string[]}} args
 * @param {{start?: typeof startSession, silenceMs?: number, stopped?: Promise<unknown>}} [seams] for the
 *   tests: how a session starts, guard.js's limit (else silenceLimitMs of the watchdog), and when
 *   --watch stops (else at SIGINT or SIGTERM)
 */
export async function runTest({ values, positionals }, seams = {}) {
  return (await testFolder({ values, positionals }, { ...seams, say: io.err, out: io.out })).exitCode;
}

/**
 * The run `shaderproof test` makes, for whoever wants its results (the Node API's test()):
 * every case's latest result, what drew them, the reports written, and the exit code. Its lines
 * go to `say` (progress, notes) and `out` (the summary).
 * @param {{values: Record<string, any>, positionals: string[]}} args
 * @param {{start?: typeof startSession, silenceMs?: number, stopped?: Promise<unknown>,
 *   say: (line: string) => void, out: (line: string) => void, bar?: boolean}} seams bar: false
 *   draws no progress line on a terminal (the case lines then go to `out` as they come)
 * @returns {Promise<{exitCode: number, results: import('./case.js').CaseResult[], environment:
 *   Awaited<ReturnType<typeof runCases>>['environment'] | null, out: string, reports: string[], referenceDir: string}>}
 */
export async function testFolder({ values, positionals }, seams) {
  const { say, out: sayOut } = seams;
  const out = path.resolve(values.out ?? 'shaderproof-output');
  const update = Boolean(values.update);
  const watch = Boolean(values.watch);
  if (watch && update) throw new UsageError('--watch and --update: give one (write the references once, then watch)');
  const last = values['last-failed'] ? readLastRun(out) : null;
  const selection = readSelection(positionals, { lastDir: last?.dir });
  const { dir } = selection;
  const label = path.relative(process.cwd(), dir) || '.';
  if (last && last.dir !== dir)
    throw new ShaderproofError(
      `--last-failed: the last run in ${path.relative(process.cwd(), out) || '.'} was of ${path.relative(process.cwd(), last.dir) || '.'}, not ${label}: give that folder, or the --out of a run of this one`,
      2,
    );
  const grep = readGrep(values);
  const shard = readShard(values.shard);
  const jobs = values.jobs === undefined ? DEFAULT_JOBS : readNumber(values.jobs, '--jobs', { min: 1, max: MAX_JOBS, whole: true });
  const reporters = readReporters(values.reporter);
  const runDate = dateLabel(readDate(values.date ?? DEFAULT_DATE)); // checked before any browser starts
  const media = readMediaOptions(values); // --media and --fetch-media hold for every case
  /** The folder's cases as they are now, and those chosen (read again for each rerun of --watch). */
  const choose = () => {
    const all = findCases(dir, readManifest(dir), { date: values.date }).map((c) => (c.view ? { ...c, view: { ...c.view, media } } : c));
    if (!all.length) throw new ShaderproofError(`${label}: no .glsl or .json shaders in it`);
    const picked = pickCases(all, selection, grep, label);
    return { all, picked, cases: picked.filter((_, i) => i % shard.count === shard.index) };
  };
  const { all, picked, cases: shared } = choose();
  let cases = shared;
  if (last) {
    const failedLast = lastFailedCases(shared, last);
    if (failedLast.none) {
      sayOut(failedLast.none);
      return { exitCode: 0, results: [], environment: null, out, reports: [], referenceDir: path.join(dir, REFERENCE_DIR) };
    }
    cases = failedLast.cases;
  }
  const referenceDir = path.join(dir, REFERENCE_DIR);
  let recorded;
  try {
    recorded = readDrawnBy(referenceDir);
  } catch (error) {
    throw new ShaderproofError(error.message);
  }
  const hasReferences = fs.existsSync(referenceDir) && fs.readdirSync(referenceDir).some((name) => name.endsWith('.png'));
  // --update of some cases where others have references: drawn as those were, and drawn-by.json kept
  const chosenReferences = new Set(cases.map((c) => c.reference));
  const keepsRecord =
    update && (picked.length < all.length || Boolean(last)) && referencePngs(referenceDir).some((file) => !chosenReferences.has(file));
  const theirs = referenceRenderer(recorded, true);
  // the references' renderer unless one is asked for (a flag, or $SHADERPROOF_RENDERER)
  const limits = sessionOptions(values, update && !keepsRecord ? 'auto' : referenceRenderer(recorded, hasReferences || keepsRecord));
  if (keepsRecord && theirs && limits.renderer !== theirs)
    throw new ShaderproofError(
      `--update of ${cases.length} of ${all.length} cases with ${limits.renderer}: the folder's other references are ${theirs}'s; update the whole folder to change what draws them (shaderproof test ${label} --update)`,
      2,
    );
  fs.mkdirSync(out, { recursive: true });
  // a report of an earlier run would speak for this one
  for (const report of ['junit.xml', 'index.html']) fs.rmSync(path.join(out, report), { force: true });

  const startOne = () => (seams.start ?? startSession)({ ...limits, loopLimit: 'fail', say });
  // --watch keeps its browsers from run to run; Ctrl-C ends it with the latest results' exit code
  const kept = watch ? keptSessions(startOne) : null;
  /** The exit code of the chosen cases' latest results (each report's). */
  let latestCode = 0;
  const signal = watch && !seams.stopped ? signalled(() => latestCode) : null;
  let stopping = false;
  const stopped = (seams.stopped ?? signal?.promise ?? new Promise(() => {})).then(() => {
    stopping = true;
    return kept?.close();
  });
  /** What draws in this run, as the references record it. @type {import('./drawn-by.js').DrawnBy | undefined} */
  let now;

  /** Runs `chosen`: their results, what drew them, and when. @param {import('./manifest.js').TestCase[]} chosen */
  const runSome = async (chosen) => {
    const started = new Date();
    /** The progress line, drawn once the run's first line is out. */
    const shown = { progress: /** @type {ReturnType<typeof progressLine> | null} */ (null) };
    try {
      const ran = await runCases(chosen, {
        jobs,
        // a case whose loops llvmpipe's limit cuts fails (case.js): its frame stops at the cut
        start: kept ? kept.start : startOne,
        silenceMs: seams.silenceMs ?? silenceLimitMs(limits),
        run: { update, out, thumbnails: reporters.has('html') },
        verbose: Boolean(values.verbose),
        say,
        onEnvironment: (environment) => {
          const share = shard.count > 1 ? ` (shard ${shard.index + 1}/${shard.count})` : '';
          const workers = `${jobs} worker${jobs === 1 ? '' : 's'}`;
          say(`${chosen.length} of ${all.length} cases${share}, drawn by ${environment.label}, ${workers}; iDate at iTime 0: ${runDate}`);
          if (!now) sayDrawnBy(recorded, hasReferences, (now = drawnByNow(environment)), { update, keepsRecord, referenceDir, say });
          if (seams.bar !== false) shown.progress = progressLine(chosen.length);
        },
        onSettled: (result) => shown.progress?.settled(result),
        onResult: (result) => {
          if (!reporters.has('dot')) return;
          if (shown.progress) shown.progress.line(dotLine(result));
          else if (seams.bar === false) sayOut(dotLine(result));
        },
      });
      return { ...ran, started, seconds: (Date.now() - started.getTime()) / 1000 };
    } finally {
      shown.progress?.end();
    }
  };

  /**
   * The reports of `results` (every chosen case's latest), the record for --last-failed and the
   * summary line; the exit code.
   * @param {import('./case.js').CaseResult[]} results
   * @param {Awaited<ReturnType<typeof runSome>>} ran
   */
  const report = (results, { environment, started, seconds }) => {
    const failed = results.filter((r) => !r.ok);
    const written = [];
    if (reporters.has('junit')) {
      fs.writeFileSync(path.join(out, 'junit.xml'), junitXml(results, { seconds, renderer: environment.renderer, date: runDate }));
      written.push('junit.xml');
    }
    if (reporters.has('html')) {
      const facts = { dir: label, renderer: environment.label, chromium: environment.chromium, date: runDate, started, seconds };
      fs.writeFileSync(path.join(out, 'index.html'), htmlReport(results, { ...facts, shard, total: all.length, update }));
      written.push('index.html');
    }
    writeLastRun(out, dir, results);
    const where = path.relative(process.cwd(), out) || '.';
    sayOut(
      `${results.length - failed.length} passed, ${failed.length} failed, in ${seconds.toFixed(1)} s` +
        (written.length ? `; ${written.join(' and ')} in ${where}` : ''),
    );
    latestCode = failed.length ? 1 : 0;
    reports = written.map((name) => path.join(out, name));
    reported = results;
    return latestCode;
  };
  /** The reports the latest report wrote, and the results it reported (every chosen case's latest). */
  let reports = /** @type {string[]} */ ([]);
  let reported = /** @type {import('./case.js').CaseResult[]} */ ([]);
  /** What a run gives back. @param {number} exitCode @param {Awaited<ReturnType<typeof runSome>>} ran the latest run */
  const done = (exitCode, ran) => ({ exitCode, results: reported, environment: ran.environment, out, reports, referenceDir });

  try {
    const first = await runSome(cases);
    const code = report(first.results, first);
    if (update && now && first.results.some((r) => r.ok && !r.skipped) && !keepsRecord) writeDrawnBy(referenceDir, now);
    if (update) sayOut(`references in ${path.relative(process.cwd(), referenceDir) || '.'}`);
    if (!kept || stopping) return done(code, first);
    const names = new Set(cases.map((c) => c.name));
    let latest = first;
    const watched = await watchCases({
      dir,
      out,
      manifestFile: path.join(dir, MANIFEST),
      cases,
      results: first.results,
      // --last-failed watches the cases it ran; else the choice is made again, new cases in it
      rescan: () => choose().cases.filter((c) => !last || names.has(c.name)),
      rerun: async (chosen) => {
        latest = await runSome(chosen);
        return stopping ? null : latest.results;
      },
      report: (results) => report(results, latest),
      stopped,
      say,
    });
    return done(watched, latest);
  } finally {
    signal?.off();
    await kept?.close();
  }
}
