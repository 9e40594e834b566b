// Answers no real server gives on purpose, served by the harness's page server (setup.js) under
// HARNESS_ROUTES, so that the page's own loading code meets them on its own origin:
//
//   /__harness/hang               never answers (the connection stays open until the client
//                                 gives up or the server closes, which destroys open sockets)
//   /__harness/redirect?to=URL    302 to URL (another origin, or back to this one)
//   /__harness/repo/PATH          the repository's file PATH under src/ or tests/support/, as it
//                                 is on disk: the raw WebGL2 page (raw-webgl.html) and the plain
//                                 ES modules it imports, on the build's server as on the dev one
//
// Only the test harness adds them (on the built page's server, and as a Vite plugin on the dev
// server: page-server.js); vite.config.js and `npm run dev` have none.
//
// The same plugin serves files the tests write into public/ while the server runs (withServedDir
// in tests/support/page-helpers.js) as soon as they are on disk. Vite serves public/ from a list of its
// files made at start and kept up to date by its file watcher; a file written just before the
// page asks for it can miss that list (the watcher's event comes later, the more so under load),
// and the page then got the index page instead (measured: two failures in three full runs).

import fs from 'node:fs';
import path from 'node:path';
import { REPO_ROOT } from './config.js';

export const HARNESS_ROUTES = '/__harness/';

/** Content types of the files tests write into public/. */
const TYPES = {
  '.glsl': 'text/plain',
  '.json': 'application/json',
  '.png': 'image/png',
  '.txt': 'text/plain',
  '.html': 'text/html',
  '.js': 'text/javascript',
};
/** What /__harness/repo/ serves. */
const REPO_DIRS = ['src', path.join('tests', 'support')].map((dir) => path.join(REPO_ROOT, dir));

/**
 * Serves `pathname` from `dir` when it is a file there (or in one of `within`, folders of `dir`),
 * with no cache (the tests rewrite files). Returns false when it is not.
 * @param {string} dir
 * @param {string} pathname
 * @param {import('node:http').ServerResponse} res
 * @param {string[]} [within]
 */
function serveFile(dir, pathname, res, within = [dir]) {
  let file;
  try {
    file = path.join(dir, decodeURIComponent(pathname));
  } catch {
    return false;
  }
  if (!within.some((d) => file.startsWith(d + path.sep)) || !fs.existsSync(file) || !fs.statSync(file).isFile()) return false;
  const type = TYPES[path.extname(file).toLowerCase()] ?? 'application/octet-stream';
  res.writeHead(200, { 'content-type': type, 'cache-control': 'no-store' });
  res.end(fs.readFileSync(file));
  return true;
}

/**
 * HARNESS_ROUTES and the files tests write into `publicDir`, as a connect-style handler: the
 * built page's server (src/headless/page-server.js) runs it first, and so does the dev server
 * (harnessRoutes).
 * @param {string} publicDir
 * @returns {import('../../src/headless/page-server.js').Routes}
 */
export function harnessMiddleware(publicDir) {
  return (req, res, next) => {
    const url = new URL(req.url ?? '/', 'http://harness');
    if (!url.pathname.startsWith(HARNESS_ROUTES)) {
      const plain = req.method === 'GET' && url.search === '';
      if (plain && serveFile(path.resolve(publicDir), url.pathname, res)) return undefined;
      return next();
    }
    const route = url.pathname.slice(HARNESS_ROUTES.length);
    // never a status, never a byte; the server's close() destroys the open socket
    if (route === 'hang') return undefined;
    if (route.startsWith('repo/') && serveFile(REPO_ROOT, route.slice('repo'.length), res, REPO_DIRS)) return undefined;
    const to = url.searchParams.get('to');
    if (route === 'redirect' && to) {
      res.writeHead(302, { location: to, 'cache-control': 'no-store' });
      return res.end();
    }
    res.writeHead(404, { 'content-type': 'text/plain' });
    return res.end(`no harness route ${url.pathname}`);
  };
}

/**
 * The Vite plugin that serves HARNESS_ROUTES on the dev server (page-server.js).
 * @returns {import('vite').Plugin}
 */
export function harnessRoutes() {
  return {
    name: 'raytracer-harness-routes',
    configureServer(server) {
      server.middlewares.use(harnessMiddleware(server.config.publicDir));
    },
  };
}

/** The URL of a harness route on the page server at `baseUrl`. */
export const hangUrl = (baseUrl) => `${baseUrl}${HARNESS_ROUTES}hang`;
/** A URL on the page server at `baseUrl` that redirects to `to`. */
export const redirectUrl = (baseUrl, to) => `${baseUrl}${HARNESS_ROUTES}redirect?to=${encodeURIComponent(to)}`;
