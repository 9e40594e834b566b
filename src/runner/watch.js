// `shaderproof test --watch`: after the first run, the files the chosen cases depend on are
// watched (each case's shader, the manifest, its references, its channels' images; the test
// folder's sub-folders for new shaders), and a save reruns the cases it touches: a case whose
// file changed, whose manifest entry (or the defaults) changed, or that is new. Saves within
// DEBOUNCE_MS of each other are one change; a change during a run waits for its end. The
// browsers are kept between runs (keptSessions), so that a rerun starts no Chromium.
//
// Folders are watched, not files: editors save by writing in place or by renaming a new file
// over the old one (page-server.js watch() does the same for `shaderproof open`).

import fs from 'node:fs';
import path from 'node:path';
import { ShaderproofError } from '../headless/session.js';
import { SKIPPED_DIRS } from './manifest.js';

/** Quiet this long after a file event before the rerun: an editor's save is several events. */
const DEBOUNCE_MS = 150;

/**
 * Sessions kept between runs: runner.js closes a session at a run's end, and here that puts it
 * aside for the next run instead; a session it kills (its browser stopped answering) is gone
 * for good. close() closes them all, and no session starts after it.
 * @param {() => Promise<import('../headless/session.js').Session>} startOne
 */
export function keptSessions(startOne) {
  /** @type {import('../headless/session.js').Session[]} */
  const idle = [];
  /** @type {Set<import('../headless/session.js').Session>} */
  const open = new Set();
  let closed = false;
  return {
    /** A kept session, or a new one. @returns {Promise<import('../headless/session.js').Session>} */
    async start() {
      if (closed) throw new ShaderproofError('the watch was stopped');
      const session = idle.pop() ?? (await startOne());
      open.add(session);
      let gone = false;
      // a copy of its own properties (guard.js spreads a session), its end kept here
      return {
        ...session,
        async kill() {
          gone = true;
          open.delete(session);
          await session.kill();
        },
        async close() {
          if (gone || closed) return session.close();
          idle.push(session);
        },
      };
    },
    async close() {
      closed = true;
      idle.splice(0);
      await Promise.all([...open].map((session) => session.close().catch(() => {})));
      open.clear();
    },
  };
}

/**
 * The files a case depends on: its shader, its references, its channels' images.
 * @param {import('./manifest.js').TestCase} testCase
 */
function caseFiles(testCase) {
  const files = [testCase.file, testCase.reference, ...testCase.view.channels];
  if (testCase.sound) files.push(testCase.sound.reference);
  return files.filter((file) => typeof file === 'string').map((file) => path.resolve(file));
}

/** `dir` and its sub-folders that may hold cases (not `skip`). @param {string} dir @param {string} skip */
function foldersUnder(dir, skip) {
  const found = [dir];
  for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
    const sub = path.join(dir, entry.name);
    if (entry.isDirectory() && !SKIPPED_DIRS.test(entry.name) && sub !== skip) found.push(...foldersUnder(sub, skip));
  }
  return found;
}

/**
 * File events of a set of folders, gathered into batches: next() resolves with the paths that
 * changed once DEBOUNCE_MS have gone by with none.
 * @param {number} debounceMs
 */
function fileEvents(debounceMs) {
  /** @type {Map<string, fs.FSWatcher>} */
  const watchers = new Map();
  let changed = new Set();
  let ready = false;
  /** @type {((paths: Set<string>) => void) | null} */
  let waiting = null;
  /** @type {NodeJS.Timeout | undefined} */
  let timer;
  const take = () => {
    const paths = changed;
    changed = new Set();
    ready = false;
    return paths;
  };
  const fire = () => {
    ready = true;
    if (waiting) {
      const resolve = waiting;
      waiting = null;
      resolve(take());
    }
  };
  return {
    /** Watches exactly `dirs` (those that exist). @param {Iterable<string>} dirs */
    sync(dirs) {
      const wanted = new Set([...dirs].filter((dir) => fs.existsSync(dir)));
      for (const [dir, watcher] of watchers)
        if (!wanted.has(dir)) {
          watcher.close();
          watchers.delete(dir);
        }
      for (const dir of wanted) {
        if (watchers.has(dir)) continue;
        try {
          const watcher = fs.watch(dir, (_, name) => {
            changed.add(name ? path.join(dir, String(name)) : dir);
            clearTimeout(timer);
            timer = setTimeout(fire, debounceMs);
          });
          watcher.on('error', () => {}); // a folder removed: the next sync drops it
          watchers.set(dir, watcher);
        } catch {
          // gone between the check and the watch: the next sync tries again
        }
      }
    },
    /** @returns {Promise<Set<string>>} */
    next: () => (ready ? Promise.resolve(take()) : new Promise((resolve) => (waiting = resolve))),
    close() {
      clearTimeout(timer);
      for (const watcher of watchers.values()) watcher.close();
      watchers.clear();
    },
  };
}

/**
 * Watches the cases and reruns what a change touches, until `stopped`. Returns the exit code
 * of the cases' latest results: 1 while any chosen case fails.
 * @param {object} options
 * @param {string} options.dir the test folder
 * @param {string} options.out the output folder (not watched)
 * @param {string} options.manifestFile
 * @param {import('./manifest.js').TestCase[]} options.cases the chosen cases, as the first run ran them
 * @param {import('./case.js').CaseResult[]} options.results their results
 * @param {() => import('./manifest.js').TestCase[]} options.rescan the chosen cases now (throws ShaderproofError for a bad manifest)
 * @param {(cases: import('./manifest.js').TestCase[]) => Promise<import('./case.js').CaseResult[] | null>} options.rerun
 *   runs `cases`: their results, or null when the run was stopped
 * @param {(results: import('./case.js').CaseResult[]) => void} options.report the latest result of every case, in order
 * @param {Promise<unknown>} options.stopped
 * @param {(line: string) => void} options.say
 * @param {number} [options.debounceMs]
 */
export async function watchCases({
  dir,
  out,
  manifestFile,
  cases,
  results,
  rescan,
  rerun,
  report,
  stopped,
  say,
  debounceMs = DEBOUNCE_MS,
}) {
  const signature = (/** @type {import('./manifest.js').TestCase} */ c) => JSON.stringify(c);
  let current = new Map(cases.map((c) => [c.name, { testCase: c, signature: signature(c) }]));
  const latest = new Map(results.map((r) => [r.name, r]));
  const events = fileEvents(debounceMs);
  const watched = () => [
    ...foldersUnder(dir, out),
    path.dirname(manifestFile),
    ...[...current.values()].flatMap(({ testCase }) => caseFiles(testCase).map((file) => path.dirname(file))),
  ];
  const ordered = () => [...current.keys()].sort().flatMap((name) => latest.get(name) ?? []);
  const code = () => (ordered().some((r) => !r.ok) ? 1 : 0);
  const waiting = () => {
    const now = ordered();
    const failed = now.filter((r) => !r.ok).length;
    say(`watching ${now.length} case${now.length === 1 ? '' : 's'} (${failed} failing): a save reruns what it touches; Ctrl-C ends`);
  };
  const STOP = null;
  events.sync(watched());
  waiting();
  try {
    for (;;) {
      const changed = await Promise.race([events.next(), stopped.then(() => STOP)]);
      if (changed === STOP) break; // Ctrl-C
      let now;
      try {
        now = rescan();
      } catch (error) {
        if (!(error instanceof ShaderproofError)) throw error;
        say(`${error.message}; waiting for the next save`);
        continue;
      }
      const touched = (/** @type {string} */ file) => changed.has(file) || changed.has(path.dirname(file));
      const again = now.filter((c) => {
        const was = current.get(c.name);
        return !was || was.signature !== signature(c) || caseFiles(c).some(touched);
      });
      const gone = [...current.keys()].filter((name) => !now.some((c) => c.name === name));
      current = new Map(now.map((c) => [c.name, { testCase: c, signature: signature(c) }]));
      for (const name of gone) latest.delete(name);
      events.sync(watched());
      if (!again.length) {
        if (gone.length) report(ordered());
        continue;
      }
      const names = again.map((c) => c.name);
      say(
        `rerunning ${again.length} case${again.length === 1 ? '' : 's'}: ${names.slice(0, 5).join(', ')}${names.length > 5 ? ', …' : ''}`,
      );
      const fresh = await rerun(again);
      if (!fresh) break;
      for (const result of fresh) latest.set(result.name, result);
      report(ordered());
      waiting();
    }
  } finally {
    events.close();
  }
  return code();
}
