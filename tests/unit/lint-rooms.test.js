// The engine page has one client (src/headless/client.js): no other module under src/ runs code on a
// page, and the command line and the engine modules read no DOM of the page (its ids, selectors,
// data- attributes are the page's own; what they say comes back as data through the hook). These
// read the source, so that a second way in fails here rather than drifting unseen.

import fs from 'node:fs';
import path from 'node:path';
import { ESLint } from 'eslint';
import { describe, expect, it, vi } from 'vitest';
import { EngineHook } from '../../src/player/hook/engine-hook.js';
import { PageHook } from '../../src/studio/page-hook.js';
import { hookMethods, installFailedHook } from '../../src/player/hook/failed-hook.js';

const ROOT = path.resolve(import.meta.dirname, '..', '..');
/** package.json's "imports": what a `#name` specifier is (the engine page's plug-ins). */
const PACKAGE_IMPORTS = JSON.parse(fs.readFileSync(path.join(ROOT, 'package.json'), 'utf8')).imports ?? {};

/** The .js files under `folder` (relative to the repository). @param {string} folder */
function sources(folder) {
  return fs
    .readdirSync(path.join(ROOT, folder), { recursive: true, encoding: 'utf8' })
    .filter((file) => file.endsWith('.js'))
    .map((file) => path.join(folder, file).split(path.sep).join('/'))
    .sort();
}

/** A module's code without its comments (a comment may name what the code must not). @param {string} text */
const code = (text) => text.replace(/\/\*[\s\S]*?\*\//g, '').replace(/(^|[^:\\'"`])\/\/.*$/gm, '$1');

/** The modules of `files` whose code matches `pattern`. @param {string[]} files @param {RegExp} pattern */
const matching = (files, pattern) => files.filter((file) => pattern.test(code(fs.readFileSync(path.join(ROOT, file), 'utf8'))));

describe('the engine client is the one way into the page', () => {
  it.each([
    // a call of page.evaluate, evaluateOnNewDocument or evaluateHandle, on any object
    ['runs code on a page', /\.evaluate(OnNewDocument|Handle)?\s*\(/, sources('src'), ['src/headless/client.js']],
    // a DOM lookup, an id or selector of the page, or a data- attribute: what the page says comes
    // back as data (window.shaderEngine notes(), hang(), info(); a page that does not answer, which
    // may have no hook yet, its window.pageMarks). The test report's HTML (html-report.js,
    // report-page.js) is the command line's own page, not the engine's.
    [
      'reads the DOM of the page',
      /getElementById|querySelector|\.dataset\b|data-[a-z]|role=|#(load|value)-notes/,
      [...sources('src/headless'), ...sources('src/cli')].filter((file) => !/\/(html-report|report-page)\.js$/.test(file)),
      [],
    ],
  ])('%s: only the modules listed', (_, pattern, files, allowed) => {
    expect(matching(files, pattern)).toEqual(allowed);
  });

  it('the check finds a call when there is one', () => {
    expect(code('await page\n  .evaluate(() => 0); // page.evaluate')).toMatch(/\.evaluate(OnNewDocument|Handle)?\s*\(/);
    expect(code('// a trivial page.evaluate(() => 0)')).not.toMatch(/\.evaluate\s*\(/);
  });
});

it('both pages start their app in one place (start-page.js)', () => {
  expect(matching(sources('src/player'), /ShaderApp\.start\s*\(/)).toEqual(['src/player/start-page.js']);
});

// ---- the engine page loads no widget and no raytracer (issue 46) ---------------------------

/** A static import or re-export, a side-effect import, a dynamic import(), a worker's module. */
const STATIC_IMPORT = /(?:^|[\s;])(?:import|export)\s[^'"`;]*?from\s*['"]([^'"]+)['"]|^\s*import\s*['"]([^'"]+)['"]/gm;
const DYNAMIC_IMPORT = /\bimport\(\s*['"]([^'"]+)['"]\s*\)/g;
const WORKER_MODULE = /new\s+URL\(\s*['"]([^'"]+)['"]\s*,\s*import\.meta\.url\s*\)/g;

/**
 * The modules `entry` loads (repository paths): its static imports, and the render worker's
 * modules it starts (new Worker(new URL(…))), followed through; a query (`?raw`) kept off the
 * path, a `#name` as package.json's "imports" has it, a package left out. `lazy`: the import()s among them, "from -> to", which load a chunk
 * of their own when asked for.
 * @param {string} entry
 */
function importClosure(entry) {
  const modules = new Set();
  /** @type {string[]} */
  const lazy = [];
  const visit = (/** @type {string} */ file) => {
    if (modules.has(file)) return;
    modules.add(file);
    if (!file.endsWith('.js')) return; // a shader's text, a stylesheet
    const text = code(fs.readFileSync(path.join(ROOT, file), 'utf8'));
    const target = (/** @type {string} */ spec) => {
      if (spec.startsWith('#')) return spec in PACKAGE_IMPORTS ? path.posix.normalize(PACKAGE_IMPORTS[spec]) : null;
      return spec.startsWith('.') ? path.posix.normalize(path.posix.join(path.posix.dirname(file), spec.replace(/\?.*$/, ''))) : null;
    };
    for (const [, from, bare] of text.matchAll(STATIC_IMPORT)) {
      const next = target(from ?? bare);
      if (next) visit(next);
    }
    for (const [, spec] of text.matchAll(WORKER_MODULE)) {
      const next = target(spec);
      if (next) visit(next);
    }
    for (const [, spec] of text.matchAll(DYNAMIC_IMPORT)) {
      const next = target(spec);
      if (next) lazy.push(`${file} -> ${next}`);
    }
  };
  visit(entry);
  return { modules: [...modules].sort(), lazy: lazy.sort() };
}

/** What the engine page must not load: the interactive page's widgets, the raytracer, shaders' text. */
const NOT_ENGINE = /^src\/studio\/|^src\/raytracer\/|^shaders\/.*\.glsl$/;

describe('the engine page loads no widget and no raytracer', () => {
  const engine = importClosure('src/player/engine-main.js');

  it('its imports reach nothing of src/studio/, src/raytracer/ or shaders/*.glsl', () => {
    expect(engine.modules).toContain('src/player/gpu/render-worker.js'); // the worker is followed
    expect(engine.modules).toContain('src/engine-plug-ins.js'); // and #engine-plug-ins
    expect(engine.modules.filter((file) => NOT_ENGINE.test(file))).toEqual([]);
  });

  it('the raytracer comes in only as the converge a command asks for, a chunk of its own', () => {
    // --converge drives the raytracer's "Converge when still" on the engine page: its form is
    // plugged in lazily from outside the player (src/engine-plug-ins.js), and nothing else of it
    // is loaded, even lazily
    expect(engine.lazy.filter((edge) => NOT_ENGINE.test(edge.split(' -> ')[1]))).toEqual([
      'src/engine-plug-ins.js -> src/raytracer/convergence.js',
    ]);
    expect(importClosure('src/raytracer/convergence.js').modules.filter((file) => /^src\/(player|studio)\//.test(file))).toEqual([]);
  });

  it('the walk finds them where they are: the interactive page loads all three', () => {
    const page = importClosure('src/studio/main.js').modules;
    for (const where of ['src/studio/ui/', 'src/raytracer/', 'shaders/'])
      expect(
        page.some((file) => file.startsWith(where)),
        where,
      ).toBe(true);
  });
});

// ---- the raytracer is one shader among others (the player and Node's side name none) -------

/** The rooms that draw, drive or test any shader: none names the built-in one. */
const SHADER_NEUTRAL = ['src/player', 'src/headless', 'src/api', 'src/runner', 'src/cli', 'bin'];
/** The raytracer by name: src/raytracer/, shaders/raytrace.glsl, "the raytracer". */
const RAYTRACER = /raytrac/i;

describe('the player, headless, api, runner, cli and bin name no raytracer', () => {
  // comments included: what those rooms say of a shader holds for every shader
  it('not in any module, code or comment', () => {
    const files = SHADER_NEUTRAL.flatMap(sources);
    expect(files).toContain('bin/shaderproof.js');
    expect(files.filter((file) => RAYTRACER.test(fs.readFileSync(path.join(ROOT, file), 'utf8')))).toEqual([]);
  });

  it('nor in the pages they serve (the engine page, its status line)', () => {
    const pages = fs.readdirSync(path.join(ROOT, 'src/player')).filter((file) => /\.(html|css)$/.test(file));
    expect(pages).toContain('engine.html');
    expect(pages.filter((file) => RAYTRACER.test(fs.readFileSync(path.join(ROOT, 'src/player', file), 'utf8')))).toEqual([]);
  });

  it('the check finds the name where it is', () => {
    expect(
      ['src/raytracer', 'src/studio'].flatMap(sources).some((file) => RAYTRACER.test(fs.readFileSync(path.join(ROOT, file), 'utf8'))),
    ).toBe(true);
  });
});

describe('the lint rules by room keep each room to its own', () => {
  const eslint = new ESLint({ cwd: ROOT });
  /** The lint's messages for `text` as the module `file`. @param {string} file @param {string} text */
  const lint = async (file, text) => (await eslint.lintText(text, { filePath: path.join(ROOT, file) }))[0].messages;
  /** A snippet that imports `module`. @param {string} module */
  const importing = (module) => `import { x } from '${module}';\nexport const y = x;\n`;

  it.each([
    // the player: no studio, no raytracer, no reference up front, nothing of Node's side
    ['src/player/engine-main.js', '../studio/ui/notices.js', /studio/],
    ['src/player/engine-main.js', '../../shaders/raytrace.glsl?raw', /raytracer/],
    ['src/player/open-view.js', '../studio/wiring.js', /studio/],
    ['src/player/hook/engine-hook.js', '../../studio/page-hook.js', /studio/],
    ['src/player/app/converge.js', '../../raytracer/progressive.js', /raytracer/],
    ['src/player/gpu/probe.js', '../../raytracer/path-probe.js', /raytracer/],
    // the engine page's plug-ins: a shader family's code only lazily (import())
    ['src/engine-plug-ins.js', './raytracer/convergence.js', /raytracer/],
    ['src/player/io/recorder.js', '../../reference/render.js', /float64 reference/],
    ['src/player/app/app.js', '../../headless/client.js', /Chromium/],
    // a room of the player's worker (gpu/bands/) reaching the page's state
    ['src/player/gpu/bands/band-scheduler.js', '../../app/app.js', /render worker/],
    ['src/player/app/frame-loop.js', '../io/recorder.js', /app\/ is the state/],
    // Node's side: the player's code never (its types in JSDoc only), and bottom up
    ['src/headless/client.js', '../player/hook/engine-hook.js', /player runs in the browser/],
    ['src/headless/session.js', '../api/render.js', /sit above/],
    ['src/api/render.js', '../raytracer/progressive.js', /raytracer/],
    ['src/api/render.js', '../cli/main.js', /built on the API/],
    ['src/runner/case.js', '../cli/arguments.js', /built on the API/],
    ['src/api/sound.js', '../runner/case.js', /runner is built on the API/],
    ['src/api/index.js', '../cli/main.js', /built on the API/],
    ['src/cli/main.js', '../studio/wiring.js', /studio/],
    // what every room shares imports no room
    ['src/shared/pixels.js', '../player/app/app.js', /player runs in the browser/],
    ['src/shadertoy/header.js', '../headless/view.js', /Chromium/],
    // the raytracer's plug-ins are the studio's
    ['src/raytracer/progressive.js', '../player/app/converge.js', /player runs in the browser/],
  ])('%s may not import %s', async (file, module, why) => {
    const messages = await lint(file, importing(module));
    expect(new Set(messages.map((m) => m.ruleId))).toEqual(new Set(['no-restricted-imports']));
    expect(messages.map((m) => m.message)).toContainEqual(expect.stringMatching(why));
  });

  it.each([
    ['src/studio/main.js', './ui/notices.js'],
    ['src/studio/main.js', '../raytracer/convergence.js'],
    ['src/studio/wiring.js', '../player/app/app.js'],
    ['src/runner/case.js', '../api/render.js'],
    ['src/cli/main.js', '../runner/corpus.js'],
    ['src/api/index.js', '../runner/corpus.js'],
    ['src/api/render.js', '../headless/session.js'],
    ['src/player/gpu/renderer.js', '../../shadertoy/header.js'],
  ])('%s may import %s', async (file, module) => {
    expect(await lint(file, importing(module))).toEqual([]);
  });

  it('a new module in a room is under its rule without being listed', async () => {
    const messages = await lint('src/player/new-room/new-module.js', importing('../../studio/ui/dom.js'));
    expect(messages.map((m) => m.ruleId)).toEqual(['no-restricted-imports']);
  });

  it('covers every module the engine page loads', async () => {
    const covered = async (/** @type {string} */ file) => {
      const config = await eslint.calculateConfigForFile(path.join(ROOT, file));
      const [, options] = config.rules?.['no-restricted-imports'] ?? [];
      return Boolean(options?.patterns?.some((/** @type {{group: string[]}} */ p) => p.group.includes('**/raytracer/**')));
    };
    const uncovered = [];
    for (const file of importClosure('src/player/engine-main.js').modules)
      if (file.endsWith('.js') && !(await covered(file))) uncovered.push(file);
    expect(uncovered).toEqual([]);
  });
});

describe("a page that could not start has the hook's every method", () => {
  it.each([
    ['the engine page', EngineHook],
    ['the interactive page', PageHook],
  ])('%s: each rejects with why, derived from its class', async (_, Hook) => {
    const error = new Error('WebGL2 is not available');
    vi.stubGlobal('window', {});
    vi.stubGlobal('document', { documentElement: { dataset: {} } });
    try {
      const hook = /** @type {Record<string, any>} */ (installFailedHook(error, Hook));
      expect(/** @type {any} */ (window).shaderEngine).toBe(hook);
      expect(Object.keys(hook).sort()).toEqual([...hookMethods(Hook), 'ready'].sort());
      await expect(hook.ready).rejects.toBe(error);
      await expect(hook.renderSound()).rejects.toBe(error); // a method the hand-kept list once lacked
      expect(hook.info()).toEqual({ error: 'WebGL2 is not available' });
      expect(document.documentElement.dataset.error).toBe('startup');
    } finally {
      vi.unstubAllGlobals();
    }
  });

  it("the interactive page's hook is the engine's and its widgets' methods", () => {
    const engine = hookMethods(EngineHook);
    expect(engine).toEqual(expect.arrayContaining(['open', 'readFrame', 'capture', 'record', 'renderSound', 'notes', 'hang', 'info']));
    expect(hookMethods(PageHook).filter((name) => !engine.includes(name))).toEqual([
      'compareWithFloat64',
      'comparison',
      'editorSource',
      'inspect',
      'inspection',
      'setMuted',
      'shareUrl',
      'soundState',
      'unpin',
    ]);
  });
});
