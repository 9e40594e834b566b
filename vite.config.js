// Vite serves two pages from src/: the studio (src/studio/index.html, at /) and the player that
// the command line drives (src/player/engine.html, at /engine.html). They import the Shadertoy
// contract from src/shadertoy/ and never the float64 reference (src/reference/); the shader
// comes from shaders/ with `?raw`, static files from public/ (examples/*.glsl among them), and
// the build goes to dist/.
//
// The glsl-files plugin makes every shader a URL the page can load with ?shader=: public/**.glsl
// are static files anyway, and shaders/*.glsl are served (and copied into the build) as
// /shaders/NAME.glsl. Under `npm run dev` it tells the page when any of them changes (the
// `glsl-file-changed` event, with the file's URL path), so the page reloads that shader in place
// instead of reloading itself.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';

const repo = fileURLToPath(new URL('.', import.meta.url));
const shadersDir = path.join(repo, 'shaders');
const publicDir = path.join(repo, 'public');

/** The URL path a .glsl file is served at, or null if the page does not serve it. */
function glslUrl(file) {
  if (!file.endsWith('.glsl')) return null;
  for (const [dir, prefix] of [
    [shadersDir, '/shaders/'],
    [publicDir, '/'],
  ]) {
    const relative = path.relative(dir, file);
    if (!relative.startsWith('..') && !path.isAbsolute(relative)) return prefix + relative.split(path.sep).join('/');
  }
  return null;
}

function glslFiles() {
  return {
    name: 'glsl-files',
    configureServer(server) {
      server.watcher.add(shadersDir);
      server.middlewares.use((req, res, next) => {
        const pathname = decodeURIComponent((req.url ?? '').split('?')[0]);
        const match = /^\/shaders\/([\w.-]+\.glsl)$/.exec(pathname);
        if (!match || (req.method !== 'GET' && req.method !== 'HEAD')) return next();
        const file = path.join(shadersDir, match[1]);
        fs.readFile(file, (error, data) => {
          if (error) return next();
          res.setHeader('Content-Type', 'text/plain; charset=utf-8');
          res.setHeader('Cache-Control', 'no-cache');
          res.end(req.method === 'HEAD' ? undefined : data);
        });
      });
    },
    hotUpdate({ file }) {
      if (this.environment.name !== 'client') return;
      const url = glslUrl(file);
      if (url) this.environment.hot.send({ type: 'custom', event: 'glsl-file-changed', data: { url } });
    },
    generateBundle() {
      for (const name of fs.readdirSync(shadersDir).filter((n) => n.endsWith('.glsl'))) {
        this.emitFile({ type: 'asset', fileName: `shaders/${name}`, source: fs.readFileSync(path.join(shadersDir, name), 'utf8') });
      }
    },
  };
}

/**
 * ogv.js in the build (the Theora decoder, src/player/inputs/theora-video.js). Its Emscripten modules
 * require Node's `fs` and `path` in a branch that runs only under Node: for the page they are an
 * empty module, so that the build neither warns about them nor ships Vite's stand-in. Its
 * WebAssembly is a binary form of libogg and libtheora, whose BSD licences (and ogv.js's MIT one)
 * ask that it travel with their notices: they go into the build as licenses/ogv/*.txt.
 */
function ogvInBuild() {
  const STUB = '\0ogv-node-builtin';
  const ogvDist = path.join(repo, 'node_modules', 'ogv', 'dist');
  return {
    name: 'ogv-in-build',
    enforce: /** @type {const} */ ('pre'),
    resolveId(source, importer) {
      if ((source === 'fs' || source === 'path') && importer?.includes(`${path.sep}node_modules${path.sep}ogv${path.sep}`)) return STUB;
      return null;
    },
    load(id) {
      return id === STUB ? 'export default {};' : null;
    },
    generateBundle() {
      for (const [from, to] of [
        ['COPYING', 'ogv.js.txt'],
        ['COPYING-ogg.txt', 'libogg.txt'],
        ['COPYING-theora.txt', 'libtheora.txt'],
      ])
        this.emitFile({ type: 'asset', fileName: `licenses/ogv/${to}`, source: fs.readFileSync(path.join(ogvDist, from), 'utf8') });
    },
  };
}

/** What the built page lists of its sources (src/headless/page-server.js reads it to tell a stale build). */
const SOURCES_FILE = 'page-sources.json';

/**
 * Lists every file the build was made from, from the module graphs themselves (the page's and
 * each worker's: the render worker, the float64 reference's threads), plus the static files and
 * this config, into dist/page-sources.json. A hand-written list of folders missed src/raytracer
 * and src/reference, which the page bundles: a clone could render with a stale page.
 * @param {Set<string>} seen shared by the page's build and its workers' builds
 * @param {{emit: boolean}} options emit: this is the page's build (its workers' are done by then)
 */
function pageSources(seen, { emit }) {
  return {
    name: 'page-sources',
    generateBundle() {
      for (const id of this.getModuleIds()) {
        const file = id.split('?')[0];
        if (file.startsWith(repo) && !file.includes(`${path.sep}node_modules${path.sep}`) && fs.existsSync(file)) seen.add(file);
      }
      if (!emit) return;
      const listed = [...seen, publicDir, shadersDir, fileURLToPath(import.meta.url)].map((f) =>
        path.relative(repo, f).split(path.sep).join('/'),
      );
      this.emitFile({ type: 'asset', fileName: SOURCES_FILE, source: JSON.stringify([...new Set(listed)].sort(), null, 1) });
    },
  };
}

/** Each page's file in its room, and the URL it is served at, in development and in the build. */
const PAGES = {
  '/index.html': 'studio/index.html',
  '/engine.html': 'player/engine.html',
};

/**
 * The pages at the site's root, as their URLs have always been (a shared link, the command
 * line's engine page), while their files live in their rooms: the development server reads a
 * page's URL as its file, and the build writes each page at its URL (base is '/', so the
 * assets' URLs do not depend on where a page's file lies). A page names its script and style
 * from the root (/studio/main.js), since the browser resolves a relative one against the URL.
 */
function pagesAtSiteRoot() {
  return {
    name: 'pages-at-site-root',
    enforce: /** @type {const} */ ('post'),
    configureServer(server) {
      server.middlewares.use((req, res, next) => {
        const [pathname, query = ''] = (req.url ?? '').split(/(?=\?)/);
        const file = PAGES[pathname === '/' ? '/index.html' : pathname];
        if (file) req.url = `/${file}${query}`;
        next();
      });
    },
    generateBundle(_options, bundle) {
      for (const [url, file] of Object.entries(PAGES)) {
        if (bundle[file]) bundle[file].fileName = url.slice(1);
      }
    },
  };
}

const sourcesSeen = new Set();

export default defineConfig({
  root: `${repo}src`,
  publicDir,
  plugins: [ogvInBuild(), glslFiles(), pagesAtSiteRoot(), pageSources(sourcesSeen, { emit: true })],
  worker: { plugins: () => [pageSources(sourcesSeen, { emit: false })] },
  server: {
    host: '127.0.0.1',
    // the studio imports ../shaders/*.glsl, outside the root: allow the whole repository
    fs: { allow: [repo] },
  },
  build: {
    // two pages: the studio, and the player's engine page the command line drives (only what draws)
    rollupOptions: { input: { main: `${repo}src/studio/index.html`, engine: `${repo}src/player/engine.html` } },
    outDir: `${repo}dist`,
    emptyOutDir: true,
    chunkSizeWarningLimit: 800, // three.js's WebGLRenderer is most of the bundle (~600 kB)
  },
});
