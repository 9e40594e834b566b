// Which cases a `shaderproof test` run takes, as Playwright's and vitest's users choose tests:
// folders, files and view names as arguments (each a case, or the cases under a sub-folder, of
// the test folder that governs it), --grep and --grep-invert on the cases' names, and
// --last-failed from the last run's OUT/.last-run.json (the file Playwright keeps in its output
// folder, of the same name). Node only: nothing here starts a browser.
//
// The test folder of an argument: the nearest folder, from the argument's own (a folder itself,
// a file's folder) upward, that holds a shaderproof.json or a __references__ folder; where none
// does, the folder argument itself, or the file's own folder.

import fs from 'node:fs';
import path from 'node:path';
import { ShaderproofError } from '../headless/session.js';
import { UsageError } from '../api/view-options.js';
import { MANIFEST, REFERENCE_DIR, SHADER_FILE } from './manifest.js';

/** The last run's record in the output folder: what ran, and which cases failed. */
export const LAST_RUN_FILE = '.last-run.json';

/**
 * What the arguments chose: the test folder, and within it the whole folder (`whole`) or the
 * cases each pick names.
 * @typedef {{arg: string, name: string, under: boolean, view: boolean}} Pick
 *   name: a case's name, or with `under` a sub-folder's ('' for the whole folder); view: the
 *   argument is no file, and names a view of the manifest (or a folder of views)
 * @typedef {{dir: string, picks: Pick[]}} Selection
 */

/** @param {string} file */
const isFolder = (file) => fs.existsSync(file) && fs.statSync(file).isDirectory();

/**
 * The test folder that governs `start` (a folder): the nearest, from it upward, with a manifest
 * or references; null where none has either.
 * @param {string} start
 */
export function testFolderOf(start) {
  for (let dir = path.resolve(start); ; dir = path.dirname(dir)) {
    if (fs.existsSync(path.join(dir, MANIFEST)) || isFolder(path.join(dir, REFERENCE_DIR))) return dir;
    if (path.dirname(dir) === dir) return null;
  }
}

/** `file`'s path under `dir`, with forward slashes ('' for dir itself). @param {string} dir @param {string} file */
const nameUnder = (dir, file) => path.relative(dir, file).split(path.sep).join('/');

/**
 * One argument: a folder, a shader file, or a name that is no file (a view of the manifest).
 * @param {string} arg
 * @returns {Pick & {dir: string}}
 */
function readPick(arg) {
  const full = path.resolve(arg);
  if (isFolder(full)) {
    const dir = testFolderOf(full) ?? full;
    return { arg, dir, name: nameUnder(dir, full), under: true, view: false };
  }
  if (fs.existsSync(full)) {
    if (path.basename(full) === MANIFEST) throw new ShaderproofError(`${arg}: a manifest, not a case; give its folder to run its cases`, 2);
    if (!SHADER_FILE.test(full))
      throw new ShaderproofError(`${arg}: not a shader (a case is a .glsl or .json file, or a folder of them)`, 2);
    const dir = testFolderOf(path.dirname(full)) ?? path.dirname(full);
    return { arg, dir, name: nameUnder(dir, full), under: false, view: false };
  }
  let existing = path.dirname(full);
  while (!fs.existsSync(existing)) existing = path.dirname(existing);
  // a view's name only where a manifest could name it: else no case is scanned for
  const dir = isFolder(existing) ? testFolderOf(existing) : null;
  if (!dir || !fs.existsSync(path.join(dir, MANIFEST))) throw new ShaderproofError(`${arg}: no such file or folder`, 2);
  return { arg, dir, name: nameUnder(dir, full), under: false, view: true };
}

/**
 * The test folder and the picks of `positionals`; with none, the last run's folder (lastDir:
 * --last-failed's), else a usage error. Arguments of two test folders are refused.
 * @param {string[]} positionals
 * @param {{lastDir?: string}} [last]
 * @returns {Selection}
 */
export function readSelection(positionals, { lastDir } = {}) {
  if (!positionals.length) {
    if (lastDir) return { dir: lastDir, picks: [{ arg: lastDir, name: '', under: true, view: false }] };
    throw new UsageError('expected a DIR, or cases of one (shader files, sub-folders, view names), got none');
  }
  const picks = positionals.map(readPick);
  const other = picks.find((pick) => pick.dir !== picks[0].dir);
  if (other) {
    const where = (/** @type {string} */ dir) => path.relative(process.cwd(), dir) || '.';
    throw new UsageError(
      `${picks[0].arg} and ${other.arg} are cases of two test folders (${where(picks[0].dir)} and ${where(other.dir)}): run shaderproof test once for each`,
    );
  }
  return { dir: picks[0].dir, picks: picks.map(({ dir, ...pick }) => pick) };
}

/**
 * A --grep or --grep-invert pattern: a regular expression, case-insensitive as Playwright's
 * -g is; written /PATTERN/ (flags i, m, s, u after it) it is taken as written, case-sensitive
 * unless it ends in /i.
 * @param {string | undefined} text
 * @param {string} flag
 */
function readPattern(text, flag) {
  if (text === undefined) return null;
  const slashed = /^\/(.+)\/([imsu]*)$/.exec(text);
  try {
    return slashed ? new RegExp(slashed[1], slashed[2]) : new RegExp(text, 'i');
  } catch (error) {
    throw new UsageError(
      `${flag} ${text}: not a regular expression (${String(error.message).replace(/^Invalid regular expression: /, '')})`,
    );
  }
}

/**
 * The test of a case's name that --grep and --grep-invert make (true without them).
 * @param {Record<string, any>} values
 * @returns {(name: string) => boolean}
 */
export function readGrep(values) {
  const match = readPattern(values.grep, '--grep');
  const invert = readPattern(values['grep-invert'], '--grep-invert');
  return (name) => (!match || match.test(name)) && (!invert || !invert.test(name));
}

/**
 * The cases of `all` that the selection picks and `grep` keeps, in their order. A pick that
 * names no case is refused in one line (exit 2); so is a choice that keeps none.
 * @template {{name: string}} T
 * @param {T[]} all
 * @param {Selection} selection
 * @param {(name: string) => boolean} grep
 * @param {string} label the folder as the person gave it
 */
export function pickCases(all, { picks }, grep, label) {
  const takes = (/** @type {Pick} */ pick, /** @type {string} */ name) =>
    pick.under
      ? pick.name === '' || name.startsWith(`${pick.name}/`)
      : name === pick.name || (pick.view && name.startsWith(`${pick.name}/`));
  for (const pick of picks) {
    if (all.some((c) => takes(pick, c.name))) continue;
    if (pick.under)
      throw new ShaderproofError(`${pick.arg}: no case under it (the cases of ${label} are its .glsl and .json files and views)`, 2);
    if (pick.view) throw new ShaderproofError(`${pick.arg}: no such file, nor a view named ${pick.name} in ${label}'s ${MANIFEST}`, 2);
    throw new ShaderproofError(
      `${pick.arg}: not a case of ${label} (a shader in a dot-folder, ${REFERENCE_DIR} or node_modules is none)`,
      2,
    );
  }
  const picked = all.filter((c) => picks.some((pick) => takes(pick, c.name)));
  const kept = picked.filter((c) => grep(c.name));
  if (!kept.length)
    throw new ShaderproofError(
      `no case of the ${picked.length} chosen in ${label} matches --grep/--grep-invert (regular expressions on the case's name, such as waves or ^views/)`,
      2,
    );
  return kept;
}

/**
 * @typedef {{dir: string, status: 'passed' | 'failed', failed: string[], ran: number}} LastRun
 *   dir: the test folder; failed: the names of the cases that failed; ran: how many ran
 */

/**
 * The last run's record in `out`, for --last-failed: a ShaderproofError (exit 2) where there is none.
 * @param {string} out
 * @returns {LastRun}
 */
export function readLastRun(out) {
  const file = path.join(out, LAST_RUN_FILE);
  const where = path.relative(process.cwd(), file) || file;
  if (!fs.existsSync(file))
    throw new ShaderproofError(`--last-failed: no last run in ${where}; run shaderproof test DIR first (with the same --out)`, 2);
  let record;
  try {
    record = JSON.parse(fs.readFileSync(file, 'utf8'));
  } catch (error) {
    throw new ShaderproofError(
      `--last-failed: ${where} is not valid JSON (${String(error.message).split('\n')[0]}); run the whole folder again`,
      2,
    );
  }
  if (typeof record?.dir !== 'string' || !Array.isArray(record.failed))
    throw new ShaderproofError(`--last-failed: ${where} is not a record of a run; run the whole folder again`, 2);
  return record;
}

/**
 * Records a run in `out` for --last-failed: its test folder and the cases that failed.
 * @param {string} out
 * @param {string} dir
 * @param {{name: string, ok: boolean}[]} results
 */
export function writeLastRun(out, dir, results) {
  const failed = results.filter((r) => !r.ok).map((r) => r.name);
  /** @type {LastRun} */
  const record = { dir, status: failed.length ? 'failed' : 'passed', failed, ran: results.length };
  fs.writeFileSync(path.join(out, LAST_RUN_FILE), JSON.stringify(record, null, 2) + '\n');
}

/**
 * The cases --last-failed runs: those of `cases` that failed in `last`. Null, with the line to
 * say, when there are none: the run then ends at once with exit 0.
 * @template {{name: string}} T
 * @param {T[]} cases
 * @param {LastRun} last
 * @returns {{cases: T[], none: string | null}}
 */
export function lastFailedCases(cases, last) {
  if (!last.failed.length) return { cases: [], none: `--last-failed: no case failed in the last run (of ${last.ran}); nothing to run` };
  const failed = new Set(last.failed);
  const chosen = cases.filter((c) => failed.has(c.name));
  if (!chosen.length)
    return {
      cases: [],
      none: `--last-failed: none of the ${last.failed.length} cases that failed last is among those chosen; nothing to run`,
    };
  return { cases: chosen, none: null };
}
