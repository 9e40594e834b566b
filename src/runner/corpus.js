// `shaderproof test DIR`: golden-image regression over a folder of any Shadertoy shaders. Each
// .glsl or .json file under DIR is a case (manifest.js reads DIR/shaderproof.json for a case's
// view, tolerance and checks); its reference is DIR/__references__/<case>.png, written by
// --update and by nothing else (case.js runs one). The cases run on --jobs workers (runner.js),
// each case guarded (guard.js): a shader that does not compile, never finishes or takes its
// browser down fails its own case, and the run goes on. Whatever happens, the run ends with its
// reports (reporters.js: the case lines, junit.xml, index.html) and a summary line, and exits 1
// if any case failed.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { io, sessionOptions } from '../api/io.js';
import { findCases, readManifest, REFERENCE_DIR } from './manifest.js';
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
 * @param {{update: boolean, referenceDir: string, say: (line: string) => void}} run
 */
function sayDrawnBy(recorded, hasReferences, now, { update, referenceDir, say }) {
  if (update) return;
  const was = recorded?.renderer ?? (hasReferences ? 'swiftshader' : null);
  if (was && was !== now.renderer)
    say(
      `note: the references were drawn by ${was}, and this run draws with ${now.renderer} as asked: each case is compared at its manifest's tolerance (its "${now.renderer}" one where it gives one)`,
    );
  else if (recorded && drawnByDifference(recorded, now))
    say(
      `note: what draws differs from what drew the references (${path.join(referenceDir, 'drawn-by.json')}): ${drawnByDifference(recorded, now)}`,
    );
}

/**
 * @param {{values: Record<string, any>, positionals: string[]}} args
 * @param {{start?: typeof startSession, silenceMs?: number}} [seams] for the tests: how a
 *   session starts, and guard.js's limit (else silenceLimitMs of the watchdog)
 */
export async function runTest({ values, positionals }, seams = {}) {
  return (await testFolder({ values, positionals }, { ...seams, say: io.err, out: io.out })).exitCode;
}

/**
 * The run `shaderproof test` makes, for whoever wants its results (the Node API's test()):
 * every case's result, what drew them, the reports written, and the exit code. Its lines go to
 * `say` (progress, notes) and `out` (the summary).
 * @param {{values: Record<string, any>, positionals: string[]}} args
 * @param {{start?: typeof startSession, silenceMs?: number, say: (line: string) => void,
 *   out: (line: string) => void, bar?: boolean}} seams bar: false draws no progress line on a
 *   terminal (the case lines then go to `out` as they come)
 */
export async function testFolder({ values, positionals }, seams) {
  const { say, out: sayOut } = seams;
  if (positionals.length !== 1) throw new UsageError(`expected one DIR, got ${positionals.length ? positionals.join(' ') : 'none'}`);
  const dir = path.resolve(positionals[0]);
  if (!fs.existsSync(dir) || !fs.statSync(dir).isDirectory()) throw new ShaderproofError(`${positionals[0]}: not a folder`);
  const shard = readShard(values.shard);
  const jobs = values.jobs === undefined ? DEFAULT_JOBS : readNumber(values.jobs, '--jobs', { min: 1, max: MAX_JOBS, whole: true });
  const reporters = readReporters(values.reporter);
  const out = path.resolve(values.out ?? 'shaderproof-output');
  const update = Boolean(values.update);
  const manifest = readManifest(dir);
  const runDate = dateLabel(readDate(values.date ?? DEFAULT_DATE)); // checked before any browser starts
  const media = readMediaOptions(values); // --media and --fetch-media hold for every case
  const all = findCases(dir, manifest, { date: values.date }).map((c) => (c.view ? { ...c, view: { ...c.view, media } } : c));
  if (!all.length) throw new ShaderproofError(`${positionals[0]}: no .glsl or .json shaders in it`);
  const cases = all.filter((_, i) => i % shard.count === shard.index);
  fs.mkdirSync(out, { recursive: true });
  // a report of an earlier run would speak for this one
  for (const report of ['junit.xml', 'index.html']) fs.rmSync(path.join(out, report), { force: true });
  const referenceDir = path.join(dir, REFERENCE_DIR);
  let recorded;
  try {
    recorded = readDrawnBy(referenceDir);
  } catch (error) {
    throw new ShaderproofError(error.message);
  }
  const hasReferences = fs.existsSync(referenceDir) && fs.readdirSync(referenceDir).some((name) => name.endsWith('.png'));
  // the references' renderer unless one is asked for (a flag, or $SHADERPROOF_RENDERER)
  const limits = sessionOptions(values, update ? 'auto' : referenceRenderer(recorded, hasReferences));
  const started = new Date();
  /** The progress line, drawn once the run's first line is out. */
  const shown = { progress: /** @type {ReturnType<typeof progressLine> | null} */ (null) };
  let ran;
  /** What draws in this run, as the references record it. @type {import('./drawn-by.js').DrawnBy | undefined} */
  let now;
  try {
    ran = await runCases(cases, {
      jobs,
      // a case whose loops llvmpipe's limit cuts fails (case.js): its frame stops at the cut
      start: () => (seams.start ?? startSession)({ ...limits, loopLimit: 'fail', say }),
      silenceMs: seams.silenceMs ?? silenceLimitMs(limits),
      run: { update, out, thumbnails: reporters.has('html') },
      verbose: Boolean(values.verbose),
      say,
      onEnvironment: (environment) => {
        const share = shard.count > 1 ? ` (shard ${shard.index + 1}/${shard.count})` : '';
        const workers = `${jobs} worker${jobs === 1 ? '' : 's'}`;
        say(`${cases.length} of ${all.length} cases${share}, drawn by ${environment.label}, ${workers}; iDate at iTime 0: ${runDate}`);
        sayDrawnBy(recorded, hasReferences, (now = drawnByNow(environment)), { update, referenceDir, say });
        if (seams.bar !== false) shown.progress = progressLine(cases.length);
      },
      onSettled: (result) => shown.progress?.settled(result),
      onResult: (result) => {
        if (!reporters.has('dot')) return;
        if (shown.progress) shown.progress.line(dotLine(result));
        else if (seams.bar === false) sayOut(dotLine(result));
      },
    });
  } finally {
    shown.progress?.end();
  }
  const { results, environment } = ran;
  const failed = results.filter((r) => !r.ok);
  const seconds = (Date.now() - started.getTime()) / 1000;
  const written = [];
  if (reporters.has('junit')) {
    fs.writeFileSync(path.join(out, 'junit.xml'), junitXml(results, { seconds, renderer: environment.renderer, date: runDate }));
    written.push('junit.xml');
  }
  if (reporters.has('html')) {
    const facts = { dir: positionals[0], renderer: environment.label, chromium: environment.chromium, date: runDate, started, seconds };
    fs.writeFileSync(path.join(out, 'index.html'), htmlReport(results, { ...facts, shard, total: all.length, update }));
    written.push('index.html');
  }
  const where = path.relative(process.cwd(), out) || '.';
  sayOut(
    `${results.length - failed.length} passed, ${failed.length} failed, in ${seconds.toFixed(1)} s` +
      (written.length ? `; ${written.join(' and ')} in ${where}` : ''),
  );
  if (update && now && results.some((r) => r.ok && !r.skipped)) writeDrawnBy(referenceDir, now);
  if (update) sayOut(`references in ${path.relative(process.cwd(), referenceDir) || '.'}`);
  return {
    exitCode: failed.length ? 1 : 0,
    results,
    environment,
    out,
    reports: written.map((name) => path.join(out, name)),
    referenceDir,
  };
}
