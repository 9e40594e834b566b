// The page as the command line serves it: the built page (dist/, made by `vite build`; in a
// packed tarball it is made by `prepack`) from a plain Node HTTP server on a loopback port, with
// a user's files from anywhere on disk mounted beside it, so that the page's own loading code
// (?shader=, ?iChannel0=) reads them from its own origin as it reads examples/*.glsl.
//
//   /__files/<id>/<name>   a mounted file (mount(): its own id, its own name, so that the page
//                          names the shader as the file is named), read from disk at each
//                          request: a saved file is served as it is now; or a text the command
//                          made (mountText())
//   /__media/<id>/<path>   a file of the folders mountFolders() was given, from the first that
//                          has it (the site's media: --media DIR, then the download cache, then
//                          each --channelN volume's or cubemap's own files under channel<N>/)
//   /__events              Server-Sent Events: `{"url": "/__files/…"}` when a watched file
//                          changes (watch()); the page reloads that shader in place (main.js)
//   anything else          the built page's files; an unknown path answers 404
//
// It answers only a request for its own host (Host: 127.0.0.1:PORT, localhost:PORT or
// [::1]:PORT), and refuses any other with 403: a page on another site whose name was made to
// point at 127.0.0.1 (DNS rebinding) reads nothing of it, as Vite's dev server refuses one
// (server.allowedHosts).
//
// With fileEvents (`open`), index.html gets one <meta name="shaderproof-file-events"> so the page
// knows to listen. A test run serves the same page through it, with the harness's routes first
// (tests/support/page-server.js). Nothing here writes to disk.

import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { buildPage } from './page-build.js';

const PACKAGE_ROOT = fileURLToPath(new URL('../..', import.meta.url));
const BUILT_PAGE_DIR = path.join(PACKAGE_ROOT, 'dist');
const FILES_ROUTE = '/__files/';
const EVENTS_ROUTE = '/__events';
const FOLDERS_ROUTE = '/__media/';

const TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.glsl': 'text/plain; charset=utf-8',
  '.frag': 'text/plain; charset=utf-8',
  '.txt': 'text/plain; charset=utf-8',
  '.png': 'image/png',
  '.jpg': 'image/jpeg',
  '.jpeg': 'image/jpeg',
  '.webp': 'image/webp',
  '.gif': 'image/gif',
  '.svg': 'image/svg+xml',
  '.ico': 'image/x-icon',
  '.wasm': 'application/wasm',
};

const typeOf = (file) => TYPES[path.extname(file).toLowerCase()] ?? 'application/octet-stream';

/**
 * The build's own list of the files it was made from (vite.config.js pageSources: the page's and
 * its workers' module graphs, the static files, the config), paths relative to the package.
 */
const SOURCES_FILE = 'page-sources.json';

/**
 * What the bundles hold of node_modules, which the build's list leaves out (its module graphs
 * stop at the package's own files): an npm install or upgrade rewrites package-lock.json (a
 * changed dependency in a pull) and node_modules/.package-lock.json (any install), so a newer
 * one of either makes the build stale. Each counts only where it is there (a package installed
 * from npm has neither, and must not rebuild on every run).
 */
const DEPENDENCY_FILES = ['package-lock.json', 'node_modules/.package-lock.json'];

/**
 * What the tests write into public/ while they run (git ignores them): never a source of the
 * page, so never a reason to build it again under a running suite.
 */
const TEST_FILES = /^(test-|hmr-test-)/;

/**
 * The newest modification time of the files under `file` (a file or a folder), in ms; a file
 * gone since the build counts as changed now.
 */
function newestMtime(file) {
  let stat;
  try {
    stat = fs.statSync(file);
  } catch {
    return Date.now();
  }
  if (!stat.isDirectory()) return stat.mtimeMs;
  let newest = 0;
  for (const entry of fs.readdirSync(file)) if (!TEST_FILES.test(entry)) newest = Math.max(newest, newestMtime(path.join(file, entry)));
  return newest;
}

/**
 * The sources of the build in `dir` changed since it was made (newer than its index.html), by the
 * build's own list of them and the dependencies' lock files (DEPENDENCY_FILES); every source when
 * the list is missing (a build from before it).
 * @param {string} dir a built page
 * @returns {string[]} paths relative to the package
 */
export function staleSources(dir) {
  const built = fs.statSync(path.join(dir, 'index.html')).mtimeMs;
  let listed;
  try {
    listed = JSON.parse(fs.readFileSync(path.join(dir, SOURCES_FILE), 'utf8'));
  } catch {
    return [`(${SOURCES_FILE} is missing: the build is from before the list)`];
  }
  const dependencies = DEPENDENCY_FILES.filter((file) => fs.existsSync(path.join(PACKAGE_ROOT, file)));
  return [...listed, ...dependencies].filter((/** @type {string} */ file) => newestMtime(path.join(PACKAGE_ROOT, file)) > built);
}

/**
 * The folder of the built page, built now when this is a clone whose dist/ is missing or older
 * than the page's sources (with Vite, a dev dependency a clone has). `say` tells the person why
 * the first run takes longer, in one line; the build's own log only with `verbose`, or when it
 * fails (page-build.js).
 * @param {{say?: (line: string) => void, verbose?: boolean}} [options]
 * @returns {Promise<string>}
 */
export async function builtPage({ say = () => {}, verbose = false } = {}) {
  const index = path.join(BUILT_PAGE_DIR, 'index.html');
  const inClone = fs.existsSync(path.join(PACKAGE_ROOT, 'vite.config.js'));
  const built = fs.existsSync(index) ? fs.statSync(index).mtimeMs : 0;
  if (built && !(inClone && staleSources(BUILT_PAGE_DIR).length)) return BUILT_PAGE_DIR;
  try {
    await import('vite');
  } catch {
    throw new Error(
      built
        ? `The built page in ${BUILT_PAGE_DIR} is older than the page's sources, and Vite is not installed to build it again: run npm install, then npm run build.`
        : `This package has no built page (${index} is missing): in a clone, run npm install, then npm run build.`,
    );
  }
  say(built ? 'the page changed since it was built: building it again (vite build)…' : 'building the page (vite build), once…');
  await buildPage({ configFile: path.join(PACKAGE_ROOT, 'vite.config.js'), verbose, say });
  return BUILT_PAGE_DIR;
}

/**
 * What mountFolders() serves: a folder (everything under it), or some named files of a folder
 * under a prefix of their own.
 * @typedef {string | {prefix: string, dir: string, files: string[]}} FolderMount
 */

/**
 * A handler that runs before the server's own, connect-style: it answers, or calls `next`.
 * @typedef {(req: import('node:http').IncomingMessage, res: import('node:http').ServerResponse, next: () => void) => void} Routes
 */

/**
 * Starts the server on a free loopback port (or `port`): the one server of the built page, for
 * the command line and the test run alike (tests/support/page-server.js adds its routes).
 * @param {{root: string, port?: number, fileEvents?: boolean, routes?: Routes}} options root: the
 *   built page's folder; fileEvents: index.html says where to hear of saved files (`open`);
 *   routes: answered first
 */
export async function startPageServer({ root, port = 0, fileEvents = false, routes = (_req, _res, next) => next() }) {
  /** @type {Map<string, string>} url path → file */
  const mounts = new Map();
  /** @type {FolderMount[][]} mountFolders()'s entries, by id */
  const folderMounts = [];
  /** @type {Map<string, string>} url path → text */
  const texts = new Map();
  /** @type {Set<import('node:http').ServerResponse>} */
  const listeners = new Set();
  /** @type {fs.FSWatcher[]} */
  const watchers = [];
  let nextId = 0;

  const page = fs.readFileSync(path.join(root, 'index.html'), 'utf8');
  const index = fileEvents
    ? page.replace(/<meta charset[^>]*>|<head>/i, (tag) => `${tag}\n    <meta name="shaderproof-file-events" content="${EVENTS_ROUTE}" />`)
    : page;

  /** The Host headers it answers (lower case), once it listens. @type {Set<string>} */
  const ownHosts = new Set();
  let baseUrl = '';
  const server = http.createServer((req, res) => {
    const host = req.headers.host?.toLowerCase();
    if (!host || !ownHosts.has(host)) {
      res.writeHead(403, { 'content-type': 'text/plain; charset=utf-8' });
      res.end(`This server answers only for its own host (127.0.0.1, localhost or [::1] on its port): open ${baseUrl}/\n`);
      return;
    }
    routes(req, res, () => answer(req, res));
  });
  /** @param {import('node:http').IncomingMessage} req @param {import('node:http').ServerResponse} res */
  function answer(req, res) {
    const url = new URL(req.url ?? '/', 'http://page');
    if (req.method !== 'GET' && req.method !== 'HEAD') {
      res.writeHead(405).end();
      return;
    }
    if (url.pathname === EVENTS_ROUTE) {
      res.writeHead(200, { 'content-type': 'text/event-stream', 'cache-control': 'no-store', connection: 'keep-alive' });
      res.write(': listening\n\n');
      listeners.add(res);
      req.on('close', () => listeners.delete(res));
      return;
    }
    let pathname;
    try {
      pathname = decodeURIComponent(url.pathname);
    } catch {
      res.writeHead(400).end();
      return;
    }
    const text = texts.get(pathname);
    if (text !== undefined) {
      res.writeHead(200, { 'content-type': typeOf(pathname), 'cache-control': 'no-store' });
      res.end(req.method === 'HEAD' ? undefined : text);
      return;
    }
    const mounted = mounts.get(pathname) ?? folderFile(pathname);
    if (mounted) {
      fs.readFile(mounted, (error, data) => {
        if (error) {
          res.writeHead(404, { 'content-type': 'text/plain' }).end(`${mounted}: ${error.message}`);
          return;
        }
        res.writeHead(200, { 'content-type': typeOf(mounted), 'cache-control': 'no-store' });
        res.end(req.method === 'HEAD' ? undefined : data);
      });
      return;
    }
    if (pathname === '/' || pathname === '/index.html') {
      res.writeHead(200, { 'content-type': TYPES['.html'], 'cache-control': 'no-cache' });
      res.end(req.method === 'HEAD' ? undefined : index);
      return;
    }
    const file = path.join(root, pathname);
    if (!file.startsWith(root + path.sep) || !fs.existsSync(file) || !fs.statSync(file).isFile()) {
      res.writeHead(404, { 'content-type': 'text/plain' }).end(`${pathname}: not found`);
      return;
    }
    // the build's assets have content hashes in their names; the rest is small
    const immutable = pathname.startsWith('/assets/');
    res.writeHead(200, { 'content-type': typeOf(file), 'cache-control': immutable ? 'max-age=31536000, immutable' : 'no-cache' });
    if (req.method === 'HEAD') res.end();
    else fs.createReadStream(file).pipe(res);
  }
  /**
   * A file of mounted folders at `pathname`, from the first entry that has it: a folder serves
   * what is under it, never outside; a `{prefix, dir, files}` entry serves `prefix/NAME` for
   * its named files only.
   * @param {string} pathname
   */
  function folderFile(pathname) {
    const match = new RegExp(`^${FOLDERS_ROUTE}(\\d+)/(.+)$`).exec(pathname);
    const entries = match ? folderMounts[Number(match[1])] : undefined;
    if (!match || !entries) return undefined;
    const wanted = match[2];
    for (const entry of entries) {
      let file;
      if (typeof entry === 'string') file = path.resolve(entry, wanted);
      else if (wanted.startsWith(`${entry.prefix}/`) && entry.files.includes(wanted.slice(entry.prefix.length + 1)))
        file = path.join(entry.dir, wanted.slice(entry.prefix.length + 1));
      else continue;
      const inside = typeof entry !== 'string' || file.startsWith(entry + path.sep);
      if (inside && fs.existsSync(file) && fs.statSync(file).isFile()) return file;
    }
    return undefined;
  }
  await new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, '127.0.0.1', () => resolve(undefined));
  });
  const { port: chosen } = /** @type {import('node:net').AddressInfo} */ (server.address());
  baseUrl = `http://127.0.0.1:${chosen}`;
  for (const name of ['127.0.0.1', 'localhost', '[::1]']) ownHosts.add(`${name}:${chosen}`);

  return {
    baseUrl,
    /**
     * Serves `file` (any path on disk) at a URL path of its own, named as the file is.
     * @param {string} file
     * @returns {string} the URL path
     */
    mount(file) {
      const urlPath = `${FILES_ROUTE}${nextId++}/${path.basename(file)}`;
      mounts.set(urlPath, path.resolve(file));
      return urlPath;
    },
    /**
     * Serves the files of `entries` at a URL of their own (ending in /), each path from the
     * first entry that has it.
     * @param {FolderMount[]} entries
     * @returns {string} the URL path
     */
    mountFolders(entries) {
      folderMounts.push(
        entries.map((entry) => (typeof entry === 'string' ? path.resolve(entry) : { ...entry, dir: path.resolve(entry.dir) })),
      );
      return `${FOLDERS_ROUTE}${folderMounts.length - 1}/`;
    },
    /**
     * Serves `text` at a URL path of its own, ending in `name`.
     * @param {string} text
     * @param {string} name
     * @returns {string} the URL path
     */
    mountText(text, name) {
      const urlPath = `${FILES_ROUTE}${nextId++}/${name}`;
      texts.set(urlPath, text);
      return urlPath;
    },
    /**
     * Tells every page listening that `urlPath`'s file changed whenever it is saved. Editors
     * save by writing in place or by renaming a new file over the old one: the folder is
     * watched, and events for the file's name within 50 ms are one change.
     * @param {string} urlPath a path mount() returned
     */
    watch(urlPath) {
      const file = mounts.get(urlPath);
      if (!file) throw new Error(`watch: ${urlPath} is not mounted`);
      let pending = null;
      const watcher = fs.watch(path.dirname(file), (_, name) => {
        if (name !== null && name !== path.basename(file)) return;
        clearTimeout(pending);
        pending = setTimeout(() => {
          for (const res of listeners) res.write(`data: ${JSON.stringify({ url: urlPath })}\n\n`);
        }, 50);
      });
      watchers.push(watcher);
    },
    /** How many pages listen for changes now. */
    listening: () => listeners.size,
    async close() {
      for (const watcher of watchers) watcher.close();
      for (const res of listeners) res.end();
      server.closeAllConnections();
      await new Promise((resolve) => server.close(() => resolve(undefined)));
    },
  };
}
