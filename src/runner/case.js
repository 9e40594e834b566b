// One case of `shaderproof test`: rendered, compared with its reference (or its reference
// written, with --update), its checks run (manifest.js), its Sound tab compared (sound-compare.js).
// Its outcome says what the reports show (junit.js, html-report.js): why it failed, what it went
// without, the compile error at its line, the pixel count against the tolerance, the sound's
// figures; and the files it left in the output folder (actual, reference and diff PNGs of a
// failure, a thumbnail of a pass for the HTML report).

import fs from 'node:fs';
import path from 'node:path';
import { compareImages, judgeImage } from '../headless/compare.js';
import { readPng, writePng, writeWhole } from '../headless/png.js';
import { allowedMissing } from '../api/io.js';
import { sayOnce } from '../shared/said-once.js';
import { renderShader } from '../api/render.js';
import { renderSound, writeWav } from '../api/sound.js';
import { ShaderproofError } from '../headless/session.js';
import { judgeLoops } from '../api/loop-limit.js';
import { UsageError } from '../api/view-options.js';
import { decodeWav } from '../shared/wav.js';
import { halve, thumbnail } from './scale.js';
import { compileDetail } from './compile-detail.js';
import { toleranceFor } from './manifest.js';
import { rmsDifference, spectrumDifference, spectrumOutline } from './sound-compare.js';
import { pixelCount, verb } from '../shared/differences.js';
import { pixelsScript } from './report/viewer.js';

/**
 * What a case's sound comparison found: the two figures and their tolerances, each spectrum's
 * outline for the report's chart (sound-compare.js spectrumOutline).
 * @typedef {{rms: number, spectrum: number, tolerance: {rms: number, spectrum: number},
 *   outline: {actual: number[], reference: number[]}}} SoundFigures
 */

/**
 * A case's outcome. `files` are names in the output folder.
 * @typedef {object} CaseResult
 * @property {string} name
 * @property {boolean} ok
 * @property {boolean} [skipped]
 * @property {string[]} failures
 * @property {string[]} notes
 * @property {number} ms
 * @property {number | null} diffPixels
 * @property {import('../headless/compare.js').Where | null} where where the pixels differ: their
 *   box and the first few with both images' values (null when none differs, or not compared)
 * @property {{width: number, height: number} | null} size the render's
 * @property {{threshold: number, maxDiffPixels: number} | null} tolerance
 * @property {Partial<Record<keyof typeof SUFFIXES, string>>} files
 * @property {{line: string, allowed: boolean}[]} missing what the case went without
 * @property {import('./compile-detail.js').CompileDetail | null} compile
 * @property {SoundFigures | null} sound
 * @property {boolean} [replace] its session should not draw the next case (it failed there)
 */

/** The engine's count of differing pixels (anti-aliased ones too), and the diff image. */
const compare = (actual, expected, threshold) => compareImages(actual, expected, { threshold, includeAA: true });

/** Every file a case may leave in the output folder, by its kind. */
const SUFFIXES = /** @type {const} */ ({
  actual: '-actual.png',
  reference: '-reference.png',
  diff: '-diff.png',
  half: '-half.png',
  thumb: '-thumb.png',
  actualWav: '-actual.wav',
  referenceWav: '-reference.wav',
  pixels: '-pixels.js',
});

/**
 * The outcome of a case that did not run: skipped by its manifest, or given up by the runner.
 * @param {import('./manifest.js').TestCase} testCase
 * @param {Partial<CaseResult>} outcome
 * @returns {CaseResult}
 */
export function caseResult(testCase, outcome) {
  return {
    name: testCase.name,
    ok: false,
    failures: [],
    notes: [],
    ms: 0,
    diffPixels: null,
    where: null,
    size: null,
    tolerance: testCase.tolerance,
    files: {},
    missing: [],
    compile: null,
    sound: null,
    ...outcome,
  };
}

/**
 * Runs one case: renders it, compares with its reference (or writes it, with --update), runs its
 * checks. Returns its outcome; throws only for what is not the shader's (a bug, a session that
 * cannot go on).
 * @param {import('../headless/session.js').Session} session
 * @param {import('./manifest.js').TestCase} testCase
 * @param {{update: boolean, out: string, thumbnails: boolean,
 *   renderer?: import('../headless/renderers.js').RendererName}} run thumbnails: the HTML
 *   report's; renderer: what draws (the case's tolerance is that renderer's own, where it has one)
 */
export async function runCase(session, testCase, { update, out, thumbnails, renderer }) {
  const started = Date.now();
  const tolerance = toleranceFor(testCase, renderer);
  const result = caseResult(testCase, { tolerance });
  const { failures, notes, files } = result;
  const file = (/** @type {keyof typeof SUFFIXES} */ kind) => path.join(out, testCase.name + SUFFIXES[kind]);
  const keep = (/** @type {keyof typeof SUFFIXES} */ kind, image) => {
    writePng(file(kind), image);
    files[kind] = testCase.name + SUFFIXES[kind];
  };
  for (const kind of /** @type {(keyof typeof SUFFIXES)[]} */ (Object.keys(SUFFIXES))) fs.rmSync(file(kind), { force: true });
  const finish = () => {
    // the kept images again, for the HTML report's pixel readout (a page from file:// cannot read its PNGs)
    if (thumbnails && files.actual) {
      const kept = /** @type {const} */ (['reference', 'actual', 'diff']).filter((kind) => files[kind]);
      const pngs = Object.fromEntries(kept.map((kind) => [kind, fs.readFileSync(file(kind))]));
      writeWhole(file('pixels'), Buffer.from(pixelsScript(pngs)));
      files.pixels = testCase.name + SUFFIXES.pixels;
    }
    return Object.assign(result, { ok: failures.length === 0, ms: Date.now() - started });
  };
  let image;
  try {
    image = await renderShader(session, testCase.file, testCase.view);
  } catch (error) {
    if (!(error instanceof ShaderproofError || error instanceof UsageError)) throw error;
    failures.push(error.message);
    if (error instanceof ShaderproofError && error.compile) result.compile = compileDetail(error.message, testCase);
    else result.replace = error instanceof ShaderproofError;
    return finish();
  }
  result.size = { width: image.width, height: image.height };
  // a frame llvmpipe's loop limit cut short is not the shader's: no reference, nor a pass
  const cut = await judgeLoops(session, testCase.file, 'fail');
  if (cut.length) {
    failures.push(...cut);
    if (update) failures.push("no reference written from a render llvmpipe's loop limit cut short");
    keep('actual', image);
    return finish();
  }
  // a render that went without an input or a pass is no reference, nor a pass, unless allowed
  const missing = image.notes.filter((n) => n.kind === 'missing').flatMap((n) => n.lines);
  result.missing = missing.map((line) => ({ line, allowed: allowedMissing(line, testCase.allowMissing) }));
  const unallowed = result.missing.filter((m) => !m.allowed).map((m) => m.line);
  // each line checked on its own, said once however many passes share it (src/shared/said-once.js)
  for (const line of sayOnce(missing)) notes.push(`went without (allowed): ${line}`);
  if (unallowed.length) {
    notes.splice(0);
    failures.push(
      ...sayOnce(unallowed).map((line) => `went without: ${line} (allow it with "allowMissing" in shaderproof.json, or give the input)`),
    );
    if (update) failures.push('no reference written from a render that went without what the shader asks for');
    keep('actual', image);
    return finish();
  }
  for (const { lines } of image.notes.filter((n) => n.kind === 'values')) notes.push(...lines);
  if (update) {
    writePng(testCase.reference, image);
    notes.push('reference written');
  } else if (!fs.existsSync(testCase.reference)) {
    failures.push(`no reference at ${testCase.reference}: run with --update to write it`);
    keep('actual', image);
  } else {
    const reference = readPng(testCase.reference);
    const judged = judgeImage(image, reference, tolerance);
    if (judged.diffPixels !== null) Object.assign(result, { diffPixels: judged.diffPixels, where: judged.where });
    if (!judged.ok) {
      failures.push(/** @type {string} */ (judged.failure));
      keep('actual', image);
      keep('reference', reference);
      if (judged.diff) keep('diff', judged.diff);
    }
  }
  try {
    await runChecks(session, testCase, image, { update, result, keep, file });
    failures.push(...(await judgeLoops(session, testCase.file, 'fail')));
  } catch (error) {
    if (!(error instanceof ShaderproofError || error instanceof UsageError)) throw error;
    failures.push(error.message);
    result.replace = error instanceof ShaderproofError && !error.compile;
  }
  if (thumbnails && !files.actual) keep('thumb', thumbnail(image));
  return finish();
}

/**
 * The case's checks (manifest.js CHECK_KEYS) and its sound, each adding to `result`.
 * @param {import('../headless/session.js').Session} session
 * @param {import('./manifest.js').TestCase} testCase
 * @param {{width: number, height: number, data: Uint8Array}} image the case's render
 * @param {{update: boolean, result: CaseResult, keep: (kind: any, image: any) => void,
 *   file: (kind: any) => string}} context
 */
async function runChecks(session, testCase, image, { update, result, keep, file }) {
  const { checks } = testCase;
  const { failures, notes } = result;
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
      failures.push(
        `halfSize: ${pixelCount(off)} of the half-size render ${verb(off, 'differs', 'differ')} from the full render halved (at most ${allowed} may)`,
      );
      keep('half', half);
    }
  }
  if (checks.noNaN) {
    await renderShader(session, testCase.file, testCase.view);
    const { data } = await session.drawFloat();
    let bad = 0;
    for (let i = 0; i < data.length; i += 4)
      if (!(Number.isFinite(data[i]) && Number.isFinite(data[i + 1]) && Number.isFinite(data[i + 2]))) bad++;
    if (bad) failures.push(`noNaN: ${pixelCount(bad)} ${verb(bad, 'has', 'have')} a NaN or infinite colour`);
  }
  if (testCase.sound) await soundCase(session, testCase, testCase.sound, { update, result, file });
  if (checks.maxFrameMs !== undefined) {
    await renderShader(session, testCase.file, testCase.view);
    const client = /** @type {import('../headless/client.js').EngineClient} */ (session.client());
    const { median } = await client.renderFrames(5);
    notes.push(`frame ${median.toFixed(1)} ms`);
    if (median > checks.maxFrameMs)
      failures.push(`maxFrameMs: a frame takes ${median.toFixed(1)} ms (median of 5), more than ${checks.maxFrameMs}`);
  }
}

/**
 * A case's Sound tab against its reference WAV (written by --update): its figures and what
 * failed go into `result`; a failure leaves the actual WAV and a copy of the reference.
 * @param {import('../headless/session.js').Session} session
 * @param {import('./manifest.js').TestCase} testCase
 * @param {NonNullable<import('./manifest.js').TestCase['sound']>} sound
 * @param {{update: boolean, result: CaseResult, file: (kind: 'actualWav' | 'referenceWav') => string}} context
 */
async function soundCase(session, testCase, { time, duration, tolerance, reference }, { update, result, file }) {
  const { failures, notes, files } = result;
  const actual = await renderSound(session, testCase.file, testCase.view, { time, duration });
  const keepWav = () => {
    writeWav(file('actualWav'), actual);
    files.actualWav = `${testCase.name}-actual.wav`;
  };
  if (update) {
    writeWav(reference, actual);
    notes.push('sound reference written');
    return;
  }
  if (!fs.existsSync(reference)) {
    keepWav();
    failures.push(`no sound reference at ${reference}: run with --update to write it`);
    return;
  }
  const expected = decodeWav(new Uint8Array(fs.readFileSync(reference)));
  const before = failures.length;
  if (expected.sampleRate !== actual.sampleRate || expected.channels !== 2)
    failures.push(
      `the sound reference is ${expected.channels} channels at ${expected.sampleRate} Hz, not stereo at ${actual.sampleRate} Hz`,
    );
  const rms = rmsDifference(actual.pcm, expected.pcm);
  const spectrum = spectrumDifference(actual.pcm, expected.pcm);
  result.sound = {
    rms,
    spectrum,
    tolerance,
    outline: { actual: spectrumOutline(actual.pcm), reference: spectrumOutline(expected.pcm) },
  };
  notes.push(`sound: RMS difference ${rms.toExponential(2)}, spectrum ${(spectrum * 100).toFixed(2)}%`);
  if (rms > tolerance.rms)
    failures.push(`sound: the RMS difference from the reference is ${rms.toExponential(2)} (at most ${tolerance.rms})`);
  if (spectrum > tolerance.spectrum)
    failures.push(
      `sound: the spectrum differs from the reference's by ${(spectrum * 100).toFixed(2)}% (at most ${tolerance.spectrum * 100}%)`,
    );
  if (failures.length > before) {
    keepWav();
    fs.copyFileSync(reference, file('referenceWav'));
    files.referenceWav = `${testCase.name}-reference.wav`;
  }
}
