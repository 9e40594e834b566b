// index.html, the test run as a page people look at (issue 47): a summary (passed, failed,
// skipped, what went without an input, the renderer, the date the clocks ran at, when and how
// long), then every case, failures first, each with what it has: the reference, the actual and
// the diff and a comparison of the first two, zoomed and panned together and opened at the
// difference (viewer.js), the pixel count and where they differ against the tolerance, what it
// went without, the compile error at its line, the sound's figures; passed cases collapsed, with
// a thumbnail. The images are files beside it, linked and loaded lazily, never inlined: a report
// of a thousand cases opens at once; a case's pixel values (its -pixels.js) load when the pointer
// first comes over its images. Nothing is fetched from anywhere else (its Content-Security-Policy
// says so), so it works offline, from file://, as a CI artifact.

import { REPORT_STYLE, reportScript } from './report-page.js';
import { VIEWER_STYLE, viewerScript } from './viewer-page.js';
import { viewerHtml } from './viewer.js';
import { escape, href } from './html-text.js';
import { pixelCount, pixelText, verb, whereText } from '../../shared/differences.js';
import { THUMBNAIL } from '../scale.js';

/** Volatile text (times): the same run twice differs there only. @param {string} text */
const volatile = (text) => `<span data-volatile>${escape(text)}</span>`;

/**
 * @typedef {object} RunFacts
 * @property {string} dir the folder tested, as given
 * @property {string} renderer
 * @property {string} chromium
 * @property {string} date iDate at iTime 0
 * @property {Date} started
 * @property {number} seconds
 * @property {{index: number, count: number}} shard
 * @property {number} total the cases in the folder (every shard's)
 * @property {boolean} update
 */

/**
 * @param {import('../case.js').CaseResult[]} results in the cases' order
 * @param {RunFacts} run
 */
export function htmlReport(results, run) {
  const failed = results.filter((r) => !r.ok);
  const passed = results.filter((r) => r.ok && !r.skipped);
  const skipped = results.filter((r) => r.skipped);
  const without = results.filter((r) => r.ok && r.missing.length).length;
  const counts = [
    `${failed.length} failed`,
    `${passed.length} passed`,
    ...(skipped.length ? [`${skipped.length} skipped`] : []),
    ...(without ? [`${without} went without an input (allowed)`] : []),
  ].join(' · ');
  const shard = run.shard.count > 1 ? ` (shard ${run.shard.index + 1}/${run.shard.count})` : '';
  const section = (id, title, list) =>
    list.length ? `<section id="${id}">\n<h2>${title} (${list.length})</h2>\n${list.map(caseHtml).join('\n')}\n</section>` : '';
  const filters = ['all', 'failed', 'passed', ...(skipped.length ? ['skipped'] : [])]
    .map((f) => `<button type="button" data-filter="${f}" aria-pressed="${f === 'all'}">${f[0].toUpperCase() + f.slice(1)}</button>`)
    .join('');
  return `<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta http-equiv="Content-Security-Policy" content="default-src 'none'; img-src 'self' file: data:; media-src 'self' file:; style-src 'unsafe-inline'; script-src 'unsafe-inline' 'self' file:">
<title>shaderproof test: ${escape(counts)}</title>
<style>${REPORT_STYLE}${VIEWER_STYLE}</style>
</head>
<body data-filter="all">
<header>
<h1>shaderproof test <code>${escape(run.dir)}</code></h1>
<p class="verdict ${failed.length ? 'fail' : 'pass'}" id="verdict">${escape(counts)}</p>
<dl>
<dt>Cases</dt><dd>${results.length} of ${run.total}${escape(shard)}${run.update ? ', references written (--update)' : ''}</dd>
<dt>Renderer</dt><dd>${escape(run.renderer)}</dd>
<dt>Chromium</dt><dd>${escape(run.chromium)}</dd>
<dt>iDate at iTime 0</dt><dd>${escape(run.date)}</dd>
<dt>Ran</dt><dd>${volatile(
    `${run.started
      .toISOString()
      .replace('T', ' ')
      .replace(/\.\d+Z$/, ' UTC')}, ${run.seconds.toFixed(1)} s`,
  )}</dd>
</dl>
<nav aria-label="Cases">${filters}<button type="button" data-open="all">Expand all</button><button type="button" data-open="none">Collapse all</button></nav>
</header>
<main>
${section('failed', 'Failed', failed)}
${section('passed', 'Passed', passed)}
${section('skipped', 'Skipped', skipped)}
</main>
<script>(${reportScript.toString()})();(${viewerScript.toString()})();</script>
</body>
</html>
`;
}

/** @param {import('../case.js').CaseResult} r */
function caseHtml(r) {
  const state = r.skipped ? 'skip' : r.ok ? 'pass' : 'fail';
  const thumb = r.files.thumb
    ? `<img class="thumb" src="${href(r.files.thumb)}" alt="" loading="lazy" width="${thumbSize(r).width}" height="${thumbSize(r).height}">`
    : '';
  const said =
    state === 'fail' ? (r.failures[0]?.split('\n')[0] ?? 'failed') : state === 'skip' ? r.notes.join('; ').replace(/^skipped: /, '') : '';
  const reason = said ? `<span class="reason">${escape(said)}</span>` : '';
  const summary = `<summary>${thumb}<span class="badge">${state === 'fail' ? 'FAIL' : state}</span><code>${escape(r.name)}</code>${reason}<span class="ms">${r.skipped ? '' : volatile(`${r.ms} ms`)}</span></summary>`;
  const body = [
    failuresHtml(r),
    facts(r),
    r.missing.length
      ? `<p>Went without:</p><ul class="missing">${r.missing.map((m) => `<li class="${m.allowed ? 'allowed' : 'unallowed'}">${escape(m.line)}${m.allowed ? ' (allowed)' : ' (allow it with "allowMissing" in shaderproof.json, or give the input)'}</li>`).join('')}</ul>`
      : '',
    viewerHtml(r, thumbSize(r)),
    r.compile ? compileHtml(r.compile, r.name) : '',
    r.sound || r.files.actualWav ? soundHtml(r) : '',
    notesHtml(r),
  ].join('');
  return `<details class="case ${state}" data-case="${escape(r.name)}"${state === 'fail' ? ' open' : ''}>\n${summary}\n<div class="body">${body}</div>\n</details>`;
}

/**
 * Why the case failed. What the page shows better below is said there only: a compile error's
 * source lines (its first line stays here), each input it went without.
 * @param {import('../case.js').CaseResult} r
 */
function failuresHtml(r) {
  const listed = r.failures
    .filter((f) => !(r.missing.length && f.startsWith('went without: ')))
    .map((f) => (r.compile?.excerpt.length ? f.split('\n')[0] : f));
  return listed.length ? `<ul class="failures">${listed.map((f) => `<li>${escape(f)}</li>`).join('')}</ul>` : '';
}

/** The thumbnail's size in the page (its file is THUMBNAIL-sized: scale.js). @param {import('../case.js').CaseResult} r */
function thumbSize(r) {
  const { width, height } = r.size ?? THUMBNAIL;
  const scale = Math.min(1, THUMBNAIL.width / width, THUMBNAIL.height / height);
  return { width: Math.max(1, Math.round(width * scale)), height: Math.max(1, Math.round(height * scale)) };
}

/** The size, the pixel count and where they differ against the tolerance. @param {import('../case.js').CaseResult} r */
function facts(r) {
  if (r.skipped || !r.size || !r.tolerance) return '';
  const { width, height } = r.size;
  const { threshold, maxDiffPixels } = r.tolerance;
  const count = r.diffPixels;
  const share = count ? (100 * count) / (width * height) : 0;
  // where they are, unless the failure's line just said it
  const where = count && r.where ? whereText(count, r.where) : '';
  const said = where && r.failures.some((f) => f.endsWith(where));
  const differ =
    count === null
      ? 'not compared'
      : `${count.toLocaleString('en-US')} of ${pixelCount(width * height)} ${verb(count, 'differs', 'differ')} (${share && share < 0.01 ? 'under 0.01' : share.toFixed(2)}%)${where && !said ? ` ${where}` : ''}`;
  const first =
    count && count > 1 && r.where ? `<li>The first, row by row: ${r.where.first.map((p) => escape(pixelText(p))).join('; ')}</li>` : '';
  return `<ul class="facts"><li>${width}×${height}: ${escape(differ)}; the tolerance: at most ${pixelCount(maxDiffPixels)} may, at threshold ${threshold}</li>${first}</ul>`;
}

/** @param {import('../compile-detail.js').CompileDetail} detail @param {string} name the case's */
function compileHtml({ where, errors, excerpt }, name) {
  const shown = excerpt.map(({ number, text, error }) => {
    const messages = error
      ? errors
          .filter((e) => e.line === number)
          .map((e) => `<div class="message">${escape(e.text)}</div>`)
          .join('')
      : '';
    return `<div class="${error ? 'error' : ''}"><span class="n">${number}</span>${escape(text ?? '')}</div>${messages}`;
  });
  const lines = [...new Set(errors.map((e) => e.line))];
  const title = `Compile error in ${/\.(glsl|json)$/i.test(where) ? name : `the ${where} tab`}, line ${lines.join(', ')}`;
  return `<div class="compile"><p>${escape(title)}</p>${shown.length ? `<div class="source">${shown.join('')}</div>` : ''}</div>`;
}

/** @param {import('../case.js').CaseResult} r */
function soundHtml(r) {
  const parts = [];
  if (r.sound) {
    const { rms, spectrum, tolerance } = r.sound;
    const row = (what, value, limit, text) =>
      `<tr><td>${what}</td><td class="${value > limit ? 'over' : ''}">${text(value)}</td><td>${text(limit)}</td></tr>`;
    parts.push(
      `<table><tr><th>Sound</th><th>difference</th><th>at most</th></tr>${row('RMS', rms, tolerance.rms, (v) => v.toExponential(2))}${row('Spectrum', spectrum, tolerance.spectrum, (v) => `${(v * 100).toFixed(2)}%`)}</table>`,
      spectrumSvg(r.sound.outline),
    );
  }
  if (r.files.referenceWav) parts.push(`<p>Reference <audio controls preload="none" src="${href(r.files.referenceWav)}"></audio></p>`);
  if (r.files.actualWav) parts.push(`<p>Actual <audio controls preload="none" src="${href(r.files.actualWav)}"></audio></p>`);
  return `<div class="sound">${parts.join('')}</div>`;
}

/** The two spectra's outlines (sound-compare.js spectrumOutline: dB in log-spaced bands). @param {{actual: number[], reference: number[]}} outline */
function spectrumSvg({ actual, reference }) {
  const [w, h, floor] = [480, 120, -100];
  const points = (bands) =>
    bands
      .map((db, i) => `${((i + 0.5) / bands.length) * w},${(Math.min(0, Math.max(floor, db)) / floor) * h}`)
      .map((p) => p.replace(/(\.\d)\d+/g, '$1'))
      .join(' ');
  return `<svg viewBox="0 0 ${w} ${h + 14}" width="${w}" height="${h + 14}" role="img" aria-label="The spectra, 20 Hz to 22 kHz, 0 to ${floor} dB: reference grey, actual red">
<polyline points="${points(reference)}" fill="none" stroke="#888" stroke-width="3"/><polyline points="${points(actual)}" fill="none" stroke="#c62828" stroke-width="1.5"/>
<text x="0" y="${h + 12}">20 Hz</text><text x="${w / 2}" y="${h + 12}" text-anchor="middle">660 Hz</text><text x="${w}" y="${h + 12}" text-anchor="end">22 kHz</text></svg>`;
}

/** @param {import('../case.js').CaseResult} r */
function notesHtml(r) {
  const notes = r.notes.filter(
    (n) => !/^went without \(allowed\)|^skipped: /.test(n) && !(r.sound && n.startsWith('sound: RMS difference')),
  );
  return notes.length ? `<ul class="notes">${notes.map((n) => `<li>${escape(n)}</li>`).join('')}</ul>` : '';
}
