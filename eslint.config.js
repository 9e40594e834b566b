// ESLint (flat config): the recommended rules, with the globals each part of the tree runs with.
import js from '@eslint/js';
import globals from 'globals';

const REFERENCE_RULE = {
  group: ['**/reference/*'],
  message: 'The page does not load the float64 reference up front: import() it lazily where a feature needs it.',
};

/**
 * The engine page (engine-main.js) and the engine's modules load no widget of the interactive
 * page (src/page/ui/) and nothing of the built-in raytracer (src/raytracer/, shaders/*.glsl).
 */
const ENGINE_RULE = {
  group: ['**/ui/**', '**/raytracer/**', '**/*.glsl', '**/*.glsl?raw'],
  message:
    "The engine page loads no widget (ui/) and nothing of the built-in raytracer (src/raytracer/, shaders/): the interactive page plugs them in (main.js; docs/architecture.md, 'The engine page').",
};

/** The engine's modules on the page: the engine entry and what it runs. */
const ENGINE_FILES = [
  'src/page/engine-main.js',
  'src/page/engine-status.js',
  'src/page/open-view.js',
  'src/page/start-page.js',
  'src/page/page-marks.js',
  'src/page/words.js',
  'src/page/hook/engine-*.js',
  'src/page/hook/failed-hook.js',
  'src/page/hook/hook-window.js',
  'src/page/app/**/*.js',
  'src/page/gpu/**/*.js',
  'src/page/io/**/*.js',
  'src/page/inputs/**/*.js',
  'src/page/sound/**/*.js',
];
/** Widgets among them: the Sound tab's buttons (the interactive page's). */
const NOT_ENGINE = ['src/page/sound/sound-controls.js'];

/** The no-restricted-imports rule with `patterns` (a file gets the last config's that matches it, so each lists all of its own). */
const restricted = (/** @type {object[]} */ ...patterns) => ({ 'no-restricted-imports': /** @type {const} */ (['error', { patterns }]) });

export default [
  { ignores: ['dist/', 'node_modules/', 'tests/output/', 'public/'] },
  js.configs.recommended,
  {
    languageOptions: { ecmaVersion: 2023, sourceType: 'module' },
    rules: {
      // unused function arguments document a callback's shape; unused variables are mistakes
      'no-unused-vars': ['error', { args: 'none', caughtErrors: 'none' }],
      eqeqeq: ['error', 'always'],
      'no-var': 'error',
      'prefer-const': 'error',
    },
  },
  // The page runs in the browser.
  { files: ['src/page/**/*.js'], languageOptions: { globals: globals.browser } },
  // What may import what (docs/architecture.md, Layout). The page never loads the float64 reference up front:
  // a feature that needs it imports it with import(), when it is asked for.
  { files: ['src/page/**/*.js'], rules: restricted(REFERENCE_RULE) },
  // The engine page and what it runs load no widget and nothing of the built-in raytracer: the
  // engine entry and every module its imports reach (tests/engine-boundaries.test.js checks that
  // these lists cover them), and the command line.
  { files: ENGINE_FILES, ignores: NOT_ENGINE, rules: restricted(REFERENCE_RULE, ENGINE_RULE) },
  {
    files: ['src/engine/**/*.js', 'src/cli/**/*.js', 'bin/**/*.js', 'src/shared/**/*.js', 'src/shadertoy/**/*.js'],
    rules: restricted(ENGINE_RULE),
  },
  // The render worker (gpu/) runs on a thread of its own: it imports its own modules, the
  // Shadertoy contract and src/shared/, never the page's state (app/), widgets (ui/) or files (io/).
  {
    files: ['src/page/gpu/**/*.js'],
    rules: restricted(REFERENCE_RULE, ENGINE_RULE, {
      // from gpu/ and from its rooms (bands/, channels/)
      group: ['../app/*', '../ui/*', '../io/*', '../main.js', '../hook/*', '../../app/*', '../../ui/*', '../../io/*', '../../hook/*'],
      message: "gpu/ is the render worker's side: the page's state, widgets and files stay on the page (talk through gpu/protocol.js).",
    }),
  },
  // The page's state (app/) is below its widgets and its edge: ui/, io/ and inspect/ import app/,
  // never the other way (what app/ needs from io/, a loader, is given to it: main.js).
  {
    files: ['src/page/app/**/*.js'],
    rules: restricted(REFERENCE_RULE, ENGINE_RULE, {
      group: ['../ui/*', '../io/*', '../inspect/*', '../main.js', '../hook/*', '../open-view.js'],
      message: 'app/ is the state the rest of the page uses: it emits events and is given what it needs, never imports them.',
    }),
  },
  // The Shadertoy contract, the reference and the shared helpers run in both.
  {
    files: ['src/shadertoy/**/*.js', 'src/reference/**/*.js', 'src/shared/**/*.js'],
    languageOptions: { globals: { ...globals.browser, ...globals.node } },
  },
  // The engine (headless Chromium, the page's server) and the command line run in Node; the
  // functions they pass to page.evaluate() run in the page.
  {
    files: ['src/engine/**/*.js', 'src/cli/**/*.js', 'bin/**/*.js'],
    languageOptions: { globals: { ...globals.node, ...globals.browser } },
  },
  // Tests, scripts, the benchmark and configs run in Node; functions passed to page.evaluate()
  // run in the page, so the browser's globals are known there too.
  { files: ['tests/**/*.js', '*.js'], languageOptions: { globals: { ...globals.node, ...globals.browser } } },
];
