// ESLint (flat config): the recommended rules, the globals each room runs with, and what each
// room may import (docs/architecture.md, "The rooms"). The rules are by folder: a new module in
// a room is under its room's rule without being listed (tests/unit/lint-rooms.test.js crosses each).
import js from '@eslint/js';
import globals from 'globals';

/** A room that a pattern keeps out: its import specifiers from anywhere below src/. */
const room = (/** @type {string} */ name) => [`**/${name}/**`, `../${name}`, `../../${name}`];

/** What a room may not import, and the line that says why and what to do. */
const KEEP_OUT = {
  studio: { group: room('studio'), message: 'The studio (src/studio/) is the page around the player: nothing below it imports it.' },
  raytracer: {
    group: [...room('raytracer'), '**/*.glsl', '**/*.glsl?raw'],
    message:
      'The built-in raytracer (src/raytracer/, shaders/) is one shader among others: only the studio plugs it in, and src/engine-plug-ins.js with import() (docs/architecture.md).',
  },
  reference: {
    group: room('reference'),
    message: 'The float64 reference is not loaded up front: import() it lazily where a feature needs it.',
  },
  player: {
    group: room('player'),
    message: "The player runs in the browser: Node's side talks to it through src/headless/client.js (types may be imported in JSDoc).",
  },
  headless: { group: room('headless'), message: 'src/headless/ drives Chromium from Node: the browser-side rooms never import it.' },
  node: {
    group: ['**/api/**', '../api', '**/runner/**', '../runner', '**/cli/**', '../cli'],
    message: 'The API, the runner and the command line sit above this room: it may not import them.',
  },
  cli: { group: ['**/cli/**', '../cli'], message: 'The command line is built on the API and the runner, never the other way.' },
  runner: { group: ['**/runner/**', '../runner'], message: 'The test runner is built on the API, never the other way.' },
};

/** The no-restricted-imports rule with `patterns` (a file gets the last config's that matches it, so each lists all of its own). */
const restricted = (/** @type {object[]} */ ...patterns) => ({ 'no-restricted-imports': /** @type {const} */ (['error', { patterns }]) });

const BROWSER_ROOMS = ['src/player/**/*.js', 'src/studio/**/*.js', 'src/raytracer/**/*.js'];
const NODE_ROOMS = ['src/headless/**/*.js', 'src/api/**/*.js', 'src/runner/**/*.js', 'src/cli/**/*.js', 'bin/**/*.js'];
const BOTH = ['src/shadertoy/**/*.js', 'src/shared/**/*.js', 'src/reference/**/*.js'];

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
  { files: BROWSER_ROOMS, languageOptions: { globals: globals.browser } },
  // Node's rooms: the functions they pass to page.evaluate() run in the page.
  { files: NODE_ROOMS, languageOptions: { globals: { ...globals.node, ...globals.browser } } },
  { files: BOTH, languageOptions: { globals: { ...globals.browser, ...globals.node } } },

  // ---- what each room may import --------------------------------------------------------
  // The player: the engine that draws any shader (engine.html). No studio, no raytracer, no
  // reference up front, nothing of Node's side.
  {
    files: ['src/player/**/*.js'],
    rules: restricted(KEEP_OUT.studio, KEEP_OUT.raytracer, KEEP_OUT.reference, KEEP_OUT.headless, KEEP_OUT.node),
  },
  // Its render worker runs on a thread of its own: never the page's state (app/), files (io/) or hook.
  {
    files: ['src/player/gpu/**/*.js'],
    rules: restricted(KEEP_OUT.studio, KEEP_OUT.raytracer, KEEP_OUT.reference, KEEP_OUT.headless, KEEP_OUT.node, {
      group: [
        '**/player/app/**',
        '**/player/io/**',
        '**/player/hook/**',
        '../app/*',
        '../io/*',
        '../hook/*',
        '../../app/*',
        '../../io/*',
        '../../hook/*',
      ],
      message: "gpu/ is the render worker's side: the page's state and files stay on the page (talk through gpu/protocol.js).",
    }),
  },
  // The app is the state the rest uses: it is given what it needs, never imports its users.
  {
    files: ['src/player/app/**/*.js'],
    rules: restricted(KEEP_OUT.studio, KEEP_OUT.raytracer, KEEP_OUT.reference, KEEP_OUT.headless, KEEP_OUT.node, {
      group: ['../io/*', '../hook/*', '../open-view.js'],
      message: 'app/ is the state the rest of the player uses: it emits events and is given what it needs, never imports them.',
    }),
  },
  // The engine page's plug-ins (the player imports it as #engine-plug-ins: package.json "imports"):
  // what it names of a shader family, it loads lazily (import()), never up front.
  {
    files: ['src/engine-plug-ins.js'],
    languageOptions: { globals: globals.browser },
    rules: restricted(KEEP_OUT.studio, KEEP_OUT.raytracer, KEEP_OUT.reference, KEEP_OUT.headless, KEEP_OUT.node),
  },
  // The studio: the page around the player. It plugs the raytracer in; the reference only lazily.
  { files: ['src/studio/**/*.js'], rules: restricted(KEEP_OUT.reference, KEEP_OUT.headless, KEEP_OUT.node) },
  // The raytracer's plug-ins: the studio's, never the player's modules at run time.
  { files: ['src/raytracer/**/*.js'], rules: restricted(KEEP_OUT.studio, KEEP_OUT.player, KEEP_OUT.headless, KEEP_OUT.node) },
  // What every room shares: the Shadertoy contract, the shared helpers, the float64 reference.
  {
    files: ['src/shadertoy/**/*.js', 'src/shared/**/*.js'],
    rules: restricted(KEEP_OUT.player, KEEP_OUT.studio, KEEP_OUT.raytracer, KEEP_OUT.reference, KEEP_OUT.headless, KEEP_OUT.node),
  },
  {
    files: ['src/reference/**/*.js'],
    rules: restricted(KEEP_OUT.player, KEEP_OUT.studio, KEEP_OUT.headless, KEEP_OUT.node),
  },
  // Node's side, bottom up: headless (Chromium driven) → api (render, record, test's case) →
  // runner (the test verb) → cli. Each imports the player's types only (JSDoc), never its code.
  {
    files: ['src/headless/**/*.js'],
    rules: restricted(KEEP_OUT.player, KEEP_OUT.studio, KEEP_OUT.raytracer, KEEP_OUT.reference, KEEP_OUT.node),
  },
  {
    files: ['src/api/**/*.js'],
    rules: restricted(KEEP_OUT.player, KEEP_OUT.studio, KEEP_OUT.raytracer, KEEP_OUT.reference, KEEP_OUT.runner, KEEP_OUT.cli),
  },
  {
    files: ['src/runner/**/*.js'],
    rules: restricted(KEEP_OUT.player, KEEP_OUT.studio, KEEP_OUT.raytracer, KEEP_OUT.reference, KEEP_OUT.cli),
  },
  {
    files: ['src/cli/**/*.js', 'bin/**/*.js'],
    rules: restricted(KEEP_OUT.player, KEEP_OUT.studio, KEEP_OUT.raytracer, KEEP_OUT.reference),
  },
  // the package's entry (the Node API: test() runs the runner) sits on top, beside the command line
  {
    files: ['src/api/index.js'],
    rules: restricted(KEEP_OUT.player, KEEP_OUT.studio, KEEP_OUT.raytracer, KEEP_OUT.reference, KEEP_OUT.cli),
  },

  // Tests, scripts, the benchmark and configs run in Node; functions passed to page.evaluate()
  // run in the page, so the browser's globals are known there too.
  { files: ['tests/**/*.js', '*.js'], languageOptions: { globals: { ...globals.node, ...globals.browser } } },
  // the docs' examples are a user's Node scripts (docs/api.md)
  { files: ['docs/**/*.mjs'], languageOptions: { globals: globals.node } },
];
