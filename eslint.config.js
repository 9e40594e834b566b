// ESLint (flat config): the recommended rules, with the globals each part of the tree runs with.
import js from '@eslint/js';
import globals from 'globals';

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
  // The Shadertoy contract and the reference run in both.
  { files: ['src/shadertoy/**/*.js', 'src/reference/**/*.js'], languageOptions: { globals: { ...globals.browser, ...globals.node } } },
  // Tests, scripts, the benchmark and configs run in Node; functions passed to page.evaluate()
  // run in the page, so the browser's globals are known there too.
  { files: ['tests/**/*.js', '*.js'], languageOptions: { globals: { ...globals.node, ...globals.browser } } },
];
