// `shaderproof test DIR`: golden-image regression over a folder of any Shadertoy shaders. Each
// .glsl or .json file under DIR is a case (manifest.js reads DIR/shaderproof.json for a case's
// view, tolerance and checks); its reference is DIR/__references__/<case>.png, written by
// --update and by nothing else (and a case with "sound", its Sound tab against <case>.wav there:
// sound-compare.js). A case that fails leaves its actual, reference and diff PNGs in
// the output folder; the run prints a table, writes junit.xml there, and exits 1 if any case
// failed. A shader that does not compile, or never finishes (the watchdog), fails its own case
// and the run goes on (session.js starts another browser after a hang).

import fs from 'node:fs';
import path from 'node:path';
import { compareImages } from '../../engine/compare.js';
import { readPng, writePng } from '../../engine/png.js';
import { allowedMissing, io, mergeMissingLines, watchdog } from '../io.js';
import { findCases, readManifest, REFERENCE_DIR } from './manifest.js';
import { junitXml } from './junit.js';
import { renderShader } from '../render.js';
import { renderSound, writeWav } from '../sound.js';
import { rmsDifference, spectrumDifference } from './sound-compare.js';
import { decodeWav } from '../../shared/wav.js';
import { CliError, startSession } from '../session.js';
import { DEFAULT_DATE, UsageError, dateLabel, readDate, readMediaOptions } from '../view-options.js';

/** "i/n" → {index (0-based), count}. @param {string | undefined} text */
function readShard(text) {
  if (text === undefined) return { index: 0, count: 1 };
  const match = /^(\d+)\/(\d+)$/.exec(text);
  const [i, n] = match ? [Number(match[1]), Number(match[2])] : [0, 0];
  if (!(n >= 1 && i >= 1 && i <= n)) throw new UsageError(`--shard ${text}: expected i/n with 1 <= i <= n, such as --shard 2/4`);
  return { index: i - 1, count: n };
}

/** The engine's count of differing pixels (anti-aliased ones too), and the diff image. */
const compare = (actual, expected, threshold) => compareImages(actual, expected, { threshold, includeAA: true });

/** The image at half the size, each pixel the mean of a 2×2 block (sizes rounded down). */
function halve({ width, height, data }) {
  const w = Math.floor(width / 2);
  const h = Math.floor(height / 2);
  const out = Buffer.alloc(w * h * 4);
  for (let y = 0; y < h; y++)
    for (let x = 0; x < w; x++)
      for (let c = 0; c < 4; c++) {
        const at = (dx, dy) => data[((2 * y + dy) * width + 2 * x + dx) * 4 + c];
        out[(y * w + x) * 4 + c] = Math.round((at(0, 0) + at(1, 0) + at(0, 1) + at(1, 1)) / 4);
      }
  return { width: w, height: h, data: out };
}

/**
 * A case's Sound tab against its reference WAV (written by --update): what failed, in words.
 * @param {import('../session.js').Session} session
 * @param {import('./manifest.js').TestCase} testCase
 * @param {NonNullable<import('./manifest.js').TestCase['sound']>} sound
 * @param {{update: boolean, out: string, notes: string[]}} run
 */
async function soundCase(session, testCase, { time, duration, tolerance, reference }, { update, out, notes }) {
  const actual = await renderSound(session, testCase.file, testCase.view, { time, duration });
  const actualFile = path.join(out, `${testCase.name}-actual.wav`);
  fs.rmSync(actualFile, { force: true });
  if (update) {
    writeWav(reference, actual);
    notes.push('sound reference written');
    return [];
  }
  if (!fs.existsSync(reference)) {
    writeWav(actualFile, actual);
    return [`no sound reference at ${reference}: run with --update to write it`];
  }
  const expected = decodeWav(new Uint8Array(fs.readFileSync(reference)));
  const failures = [];
  if (expected.sampleRate !== actual.sampleRate || expected.channels !== 2)
    failures.push(
      `the sound reference is ${expected.channels} channels at ${expected.sampleRate} Hz, not stereo at ${actual.sampleRate} Hz`,
    );
  const rms = rmsDifference(actual.pcm, expected.pcm);
  const spectrum = spectrumDifference(actual.pcm, expected.pcm);
  notes.push(`sound: RMS difference ${rms.toExponential(2)}, spectrum ${(spectrum * 100).toFixed(2)}%`);
  if (rms > tolerance.rms)
    failures.push(`sound: the RMS difference from the reference is ${rms.toExponential(2)} (at most ${tolerance.rms})`);
  if (spectrum > tolerance.spectrum)
    failures.push(
      `sound: the spectrum differs from the reference's by ${(spectrum * 100).toFixed(2)}% (at most ${tolerance.spectrum * 100}%)`,
    );
  if (failures.length) writeWav(actualFile, actual);
  return failures;
}

/**
 * Runs one case: renders it, compares with its reference (or writes it, with --update), runs its
 * checks. Returns its outcome; throws only for a session that cannot go on.
 * @param {import('../session.js').Session} session
 * @param {import('./manifest.js').TestCase} testCase
 * @param {{update: boolean, out: string}} run
 */
async function runCase(session, testCase, { update, out }) {
  const started = Date.now();
  const failures = [];
  const notes = [];
  const outFile = (suffix) => path.join(out, `${testCase.name}-${suffix}.png`);
  for (const suffix of ['actual', 'reference', 'diff', 'half']) fs.rmSync(outFile(suffix), { force: true });
  let image;
  try {
    image = await renderShader(session, testCase.file, testCase.view);
  } catch (error) {
    if (!(error instanceof CliError || error instanceof UsageError)) throw error;
    return { name: testCase.name, ok: false, failures: [error.message], notes, ms: Date.now() - started, diffPixels: null };
  }
  // a render that went without an input or a pass is no reference, nor a pass, unless allowed
  const missing = image.notes.filter((n) => n.kind === 'missing').flatMap((n) => n.lines);
  const unallowed = missing.filter((line) => !allowedMissing(line, testCase.allowMissing));
  // each line checked on its own, said once however many passes share it (io.js mergeMissingLines)
  for (const line of mergeMissingLines(missing)) notes.push(`went without (allowed): ${line}`);
  if (unallowed.length) {
    notes.splice(0);
    failures.push(
      ...mergeMissingLines(unallowed).map(
        (line) => `went without: ${line} (allow it with "allowMissing" in shaderproof.json, or give the input)`,
      ),
    );
    if (update) failures.push('no reference written from a render that went without what the shader asks for');
    writePng(outFile('actual'), image);
    return { name: testCase.name, ok: false, failures, notes, ms: Date.now() - started, diffPixels: null };
  }
  for (const { lines } of image.notes.filter((n) => n.kind === 'values')) notes.push(...lines);
  let diffPixels = null;
  if (update) {
    writePng(testCase.reference, image);
    notes.push('reference written');
  } else if (!fs.existsSync(testCase.reference)) {
    failures.push(`no reference at ${testCase.reference}: run with --update to write it`);
    writePng(outFile('actual'), image);
  } else {
    const reference = readPng(testCase.reference);
    if (reference.width !== image.width || reference.height !== image.height) {
      failures.push(`the render is ${image.width}x${image.height}, the reference ${reference.width}x${reference.height}`);
      writePng(outFile('actual'), image);
    } else {
      const result = compare(image, reference, testCase.tolerance.threshold);
      diffPixels = result.diffPixels;
      if (diffPixels > testCase.tolerance.maxDiffPixels) {
        failures.push(`${diffPixels} pixels differ from the reference (at most ${testCase.tolerance.maxDiffPixels} may)`);
        writePng(outFile('actual'), image);
        writePng(outFile('reference'), reference);
        writePng(outFile('diff'), result.diff);
      }
    }
  }
  const { checks } = testCase;
  try {
    if (checks.deterministic) {
      const again = await renderShader(session, testCase.file, testCase.view);
      if (Buffer.compare(Buffer.from(again.data), Buffer.from(image.data)) !== 0)
        failures.push('deterministic: a second render differs from the first');
    }
    if (checks.halfSize) {
      const { width, height } = testCase.view.size;
      const half = await renderShader(session, testCase.file, {
        ...testCase.view,
        size: { width: Math.floor(width / 2), height: Math.floor(height / 2) },
      });
      const { diffPixels: off } = compare(half, halve(image), checks.halfSize.threshold);
      const allowed = Math.floor(half.width * half.height * checks.halfSize.maxDiffFraction);
      if (off > allowed) {
        failures.push(`halfSize: ${off} pixels of the half-size render differ from the full render halved (at most ${allowed} may)`);
        writePng(outFile('half'), half);
      }
    }
    if (checks.noNaN) {
      await renderShader(session, testCase.file, testCase.view);
      const { data } = await session.drawFloat();
      let bad = 0;
      for (let i = 0; i < data.length; i += 4)
        if (!(Number.isFinite(data[i]) && Number.isFinite(data[i + 1]) && Number.isFinite(data[i + 2]))) bad++;
      if (bad) failures.push(`noNaN: ${bad} pixels have a NaN or infinite colour`);
    }
    if (testCase.sound) failures.push(...(await soundCase(session, testCase, testCase.sound, { update, out, notes })));
    if (checks.maxFrameMs !== undefined) {
      const page = /** @type {import('puppeteer-core').Page} */ (session.page());
      await renderShader(session, testCase.file, testCase.view);
      const { median } = await page.evaluate(() => window.raytracer.renderFrames(5));
      notes.push(`frame ${median.toFixed(1)} ms`);
      if (median > checks.maxFrameMs)
        failures.push(`maxFrameMs: a frame takes ${median.toFixed(1)} ms (median of 5), more than ${checks.maxFrameMs}`);
    }
  } catch (error) {
    if (!(error instanceof CliError || error instanceof UsageError)) throw error;
    failures.push(error.message);
  }
  return { name: testCase.name, ok: failures.length === 0, failures, notes, ms: Date.now() - started, diffPixels };
}

/** @param {{values: Record<string, any>, positionals: string[]}} args */
export async function runTest({ values, positionals }) {
  if (positionals.length !== 1) throw new UsageError(`expected one DIR, got ${positionals.length ? positionals.join(' ') : 'none'}`);
  const dir = path.resolve(positionals[0]);
  if (!fs.existsSync(dir) || !fs.statSync(dir).isDirectory()) throw new CliError(`${positionals[0]}: not a folder`);
  const shard = readShard(values.shard);
  const out = path.resolve(values.out ?? 'shaderproof-output');
  const update = Boolean(values.update);
  const manifest = readManifest(dir);
  const runDate = dateLabel(readDate(values.date ?? DEFAULT_DATE)); // checked before any browser starts
  const media = readMediaOptions(values); // --media and --fetch-media hold for every case
  const all = findCases(dir, manifest, { date: values.date }).map((c) => (c.view ? { ...c, view: { ...c.view, media } } : c));
  if (!all.length) throw new CliError(`${positionals[0]}: no .glsl or .json shaders in it`);
  const cases = all.filter((_, i) => i % shard.count === shard.index);
  fs.mkdirSync(out, { recursive: true });
  const started = Date.now();
  const session = await startSession({ gpu: values.gpu, ...watchdog(values.watchdog), say: io.err });
  const results = [];
  let environment;
  try {
    environment = await session.environment();
    io.err(
      `${cases.length} of ${all.length} cases${shard.count > 1 ? ` (shard ${shard.index + 1}/${shard.count})` : ''}, drawn by ${environment.label}; iDate at iTime 0: ${runDate}`,
    );
    for (const testCase of cases) {
      if (testCase.skip !== null) {
        results.push({
          name: testCase.name,
          ok: true,
          skipped: true,
          failures: [],
          notes: [`skipped: ${testCase.skip}`],
          ms: 0,
          diffPixels: null,
        });
        io.out(`skip  ${testCase.name.padEnd(28)} ${'-'.padStart(6)}     ${testCase.skip}`);
        continue;
      }
      const result = await runCase(session, testCase, { update, out });
      results.push(result);
      const said = [...result.failures, ...result.notes].join('; ');
      io.out(`${result.ok ? 'pass' : 'FAIL'}  ${testCase.name.padEnd(28)} ${String(result.ms).padStart(6)} ms  ${said}`);
    }
  } finally {
    await session.close();
  }
  const failed = results.filter((r) => !r.ok);
  const seconds = (Date.now() - started) / 1000;
  fs.writeFileSync(
    path.join(out, 'junit.xml'),
    junitXml(results, { seconds, renderer: environment?.renderer ?? 'unknown', date: runDate }),
  );
  io.out(
    `${results.length - failed.length} passed, ${failed.length} failed, in ${seconds.toFixed(1)} s` +
      (failed.length ? `; images and junit.xml in ${path.relative(process.cwd(), out) || '.'}` : ''),
  );
  if (update) io.out(`references in ${path.relative(process.cwd(), path.join(dir, REFERENCE_DIR)) || '.'}`);
  return failed.length ? 1 : 0;
}
