// Answers no real server gives on purpose, served by the harness's page server (setup.js) under
// HARNESS_ROUTES, so that the page's own loading code meets them on its own origin:
//
//   /__harness/hang               never answers (the connection stays open until the client
//                                 gives up or the server closes, which destroys open sockets)
//   /__harness/redirect?to=URL    302 to URL (another origin, or back to this one)
//
// Only the test harness adds them (a Vite plugin); vite.config.js and `npm run dev` have none.

export const HARNESS_ROUTES = '/__harness/';

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
        if (!url.pathname.startsWith(HARNESS_ROUTES)) return next();
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
