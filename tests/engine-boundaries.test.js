// The engine page has one client (src/engine/client.js): no other module under src/ runs code on a
// page, and the command line and the engine modules read no DOM of the page (its ids, selectors,
// data- attributes are the page's own; what they say comes back as data through the hook). These
// read the source, so that a second way in fails here rather than drifting unseen.

import fs from 'node:fs';
import path from 'node:path';
import { ESLint } from 'eslint';
import { describe, expect, it, vi } from 'vitest';
import { EngineHook } from '../src/page/hook/engine-hook.js';
import { PageHook } from '../src/page/hook/page-hook.js';
import { hookMethods, installFailedHook } from '../src/page/hook/failed-hook.js';

const ROOT = path.resolve(import.meta.dirname, '..');

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
    ['runs code on a page', /\.evaluate(OnNewDocument|Handle)?\s*\(/, sources('src'), ['src/engine/client.js']],
    // a DOM lookup, an id or selector of the page, or a data- attribute: what the page says comes
    // back as data (window.shaderEngine notes(), hang(), info(); a page that does not answer, which
    // may have no hook yet, its window.pageMarks). The test report's HTML (html-report.js,
    // report-page.js) is the command line's own page, not the engine's.
    [
      'reads the DOM of the page',
      /getElementById|querySelector|\.dataset\b|data-[a-z]|role=|#(load|value)-notes/,
      [...sources('src/engine'), ...sources('src/cli')].filter((file) => !/\/(html-report|report-page)\.js$/.test(file)),
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
  expect(matching(sources('src/page'), /ShaderApp\.start\s*\(/)).toEqual(['src/page/start-page.js']);
});

// ---- the engine page loads no widget and no raytracer (issue 46) ---------------------------

/** A static import or re-export, a side-effect import, a dynamic import(), a worker's module. */
const STATIC_IMPORT = /(?:^|[\s;])(?:import|export)\s[^'"`;]*?from\s*['"]([^'"]+)['"]|^\s*import\s*['"]([^'"]+)['"]/gm;
const DYNAMIC_IMPORT = /\bimport\(\s*['"]([^'"]+)['"]\s*\)/g;
const WORKER_MODULE = /new\s+URL\(\s*['"]([^'"]+)['"]\s*,\s*import\.meta\.url\s*\)/g;

/**
 * The modules `entry` loads (repository paths): its static imports, and the render worker's
 * modules it starts (new Worker(new URL(…))), followed through; a query (`?raw`) kept off the
 * path, a package left out. `lazy`: the import()s among them, "from -> to", which load a chunk
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
    const target = (/** @type {string} */ spec) =>
      spec.startsWith('.') ? path.posix.normalize(path.posix.join(path.posix.dirname(file), spec.replace(/\?.*$/, ''))) : null;
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
const NOT_ENGINE = /^src\/page\/ui\/|^src\/raytracer\/|^shaders\/.*\.glsl$/;

describe('the engine page loads no widget and no raytracer', () => {
  const engine = importClosure('src/page/engine-main.js');

  it('its imports reach nothing of src/page/ui/, src/raytracer/ or shaders/*.glsl', () => {
    expect(engine.modules).toContain('src/page/gpu/render-worker.js'); // the worker is followed
    expect(engine.modules.filter((file) => NOT_ENGINE.test(file))).toEqual([]);
  });

  it('the raytracer comes in only as the converge a command asks for, a chunk of its own', () => {
    // --converge drives the raytracer's "Converge when still" on the engine page: its form is
    // plugged in lazily (engine-main.js), and nothing else of it is loaded, even lazily
    expect(engine.lazy.filter((edge) => NOT_ENGINE.test(edge.split(' -> ')[1]))).toEqual([
      'src/page/engine-main.js -> src/raytracer/convergence.js',
    ]);
    expect(importClosure('src/raytracer/convergence.js').modules.filter((file) => /^src\/page\//.test(file))).toEqual([]);
  });

  it('the walk finds them where they are: the interactive page loads all three', () => {
    const page = importClosure('src/page/main.js').modules;
    for (const where of ['src/page/ui/', 'src/raytracer/', 'shaders/'])
      expect(
        page.some((file) => file.startsWith(where)),
        where,
      ).toBe(true);
  });
});

describe('the lint rule keeps them out', () => {
  const eslint = new ESLint({ cwd: ROOT });
  /** The lint's messages for `text` as the module `file`. @param {string} file @param {string} text */
  const lint = async (file, text) => (await eslint.lintText(text, { filePath: path.join(ROOT, file) }))[0].messages;

  it.each([
    ['src/page/engine-main.js', './ui/notices.js'],
    ['src/page/engine-main.js', '../../shaders/raytrace.glsl?raw'],
    ['src/page/open-view.js', './ui/notices.js'],
    ['src/page/hook/engine-hook.js', '../ui/notices.js'],
    ['src/page/app/converge.js', '../../raytracer/progressive.js'],
    ['src/page/gpu/probe.js', '../../raytracer/path-probe.js'],
    ['src/page/io/recorder.js', '../ui/dom.js'],
    ['src/engine/client.js', '../page/ui/dom.js'],
    ['src/cli/render.js', '../raytracer/progressive.js'],
    // a module of a room of ui/ (ui/toolbar/), from a room of gpu/
    ['src/page/gpu/bands/band-scheduler.js', '../../ui/toolbar/toolbar.js'],
  ])('%s may not import %s', async (file, module) => {
    const messages = await lint(file, `import { x } from '${module}';\nexport const y = x;\n`);
    // the engine's rule says so (a room's own rule, gpu/'s, may say it too)
    expect(new Set(messages.map((m) => m.ruleId))).toEqual(new Set(['no-restricted-imports']));
    expect(messages.map((m) => m.message)).toContainEqual(expect.stringMatching(/engine page loads no widget/));
  });

  it('the interactive page may (it plugs them in)', async () => {
    expect(await lint('src/page/main.js', "import { x } from './ui/notices.js';\nexport const y = x;\n")).toEqual([]);
  });

  it('covers every module the engine page loads', async () => {
    const covered = async (/** @type {string} */ file) => {
      const config = await eslint.calculateConfigForFile(path.join(ROOT, file));
      const [, options] = config.rules?.['no-restricted-imports'] ?? [];
      return Boolean(options?.patterns?.some((/** @type {{group: string[]}} */ p) => p.group.includes('**/raytracer/**')));
    };
    const uncovered = [];
    for (const file of importClosure('src/page/engine-main.js').modules)
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
