// Answers no real server gives on purpose, served by the harness's page server (setup.js) under
// HARNESS_ROUTES, so that the page's own loading code meets them on its own origin:
//
//   /__harness/hang               never answers (the connection stays open until the client
//                                 gives up or the server closes, which destroys open sockets)
//   /__harness/redirect?to=URL    302 to URL (another origin, or back to this one)
//
// Only the test harness adds them (a Vite plugin); vite.config.js and `npm run dev` have none.
//
// The same plugin serves files the tests write into public/ while the server runs (withServedDir
// in tests/page-helpers.js) as soon as they are on disk. Vite serves public/ from a list of its
// files made at start and kept up to date by its file watcher; a file written just before the
// page asks for it can miss that list (the watcher's event comes later, the more so under load),
// and the page then got the index page instead (measured: two failures in three full runs).

import fs from 'node:fs';
import path from 'node:path';

export const HARNESS_ROUTES = '/__harness/';

/** Content types of the files tests write into public/. */
const TYPES = { '.glsl': 'text/plain', '.json': 'application/json', '.png': 'image/png', '.txt': 'text/plain' };

/**
 * Serves `pathname` from `publicDir` when it is a file there, with no cache (the tests rewrite
 * files). Returns false when it is not.
 */
function servePublicFile(publicDir, pathname, res) {
  let file;
  try {
    file = path.join(publicDir, decodeURIComponent(pathname));
  } catch {
    return false;
  }
  if (!file.startsWith(publicDir + path.sep) || !fs.existsSync(file) || !fs.statSync(file).isFile()) return false;
  const type = TYPES[path.extname(file).toLowerCase()] ?? 'application/octet-stream';
  res.writeHead(200, { 'content-type': type, 'cache-control': 'no-store' });
  res.end(fs.readFileSync(file));
  return true;
}

/**
 * The Vite plugin that serves HARNESS_ROUTES.
 * @returns {import('vite').Plugin}
 */
export function harnessRoutes() {
  return {
    name: 'raytracer-harness-routes',
    configureServer(server) {
      server.middlewares.use((req, res, next) => {
        const url = new URL(req.url ?? '/', 'http://harness');
        if (!url.pathname.startsWith(HARNESS_ROUTES)) {
          const publicDir = server.config.publicDir;
          const plain = req.method === 'GET' && url.search === '' && publicDir;
          if (plain && servePublicFile(path.resolve(publicDir), url.pathname, res)) return undefined;
          return next();
        }
        const route = url.pathname.slice(HARNESS_ROUTES.length);
        // never a status, never a byte; Vite's close() destroys the open socket
        if (route === 'hang') return undefined;
        const to = url.searchParams.get('to');
        if (route === 'redirect' && to) {
          res.writeHead(302, { location: to, 'cache-control': 'no-store' });
          return res.end();
        }
        res.writeHead(404, { 'content-type': 'text/plain' });
        return res.end(`no harness route ${url.pathname}`);
      });
    },
  };
}

/** The URL of a harness route on the page server at `baseUrl`. */
export const hangUrl = (baseUrl) => `${baseUrl}${HARNESS_ROUTES}hang`;
/** A URL on the page server at `baseUrl` that redirects to `to`. */
export const redirectUrl = (baseUrl, to) => `${baseUrl}${HARNESS_ROUTES}redirect?to=${encodeURIComponent(to)}`;
