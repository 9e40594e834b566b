// knip (npm run knip): unused files, exports and dependencies.
//
// Most entry points knip finds by itself, from what actually starts them, so that a file stays
// "used" only while something still runs it:
//   - package.json: bin (bin/shaderproof.js) and the scripts (`node tests/scripts/*.js`,
//     `node tests/bench/*.js`, `vitest run --config tests/vitest.config.js`);
//   - its Vite plugin: vite.config.js, whose root src/player/ holds index.html, whose script is
//     src/studio/main.js;
//   - its Vitest plugin: tests/vitest.config.js, its projects' include (tests/unit/, tests/browser/) and the
//     globalSetup (tests/support/setup.js);
//   - its ESLint plugin: eslint.config.js;
//   - imports, including new Worker(new URL('./x.js', import.meta.url)) and
//     fs.readFileSync(new URL('./x.js', import.meta.url)).
// Listed here are only the entry points none of those can see.

/** @type {import('knip').KnipConfig} */
export default {
  entry: [
    // The raw WebGL2 test page's module: tests/support/raw-webgl/raw-webgl.html loads it with a <script>,
    // and the page is opened by URL through the harness's routes (raw-webgl.js), not by Vite.
    'tests/support/raw-webgl/raw-webgl-page.js',
    // The floor bench:cli times beside each render: run as a process of its own (cli-start.js).
    'tests/bench/baseline-launch.js',
  ],
  // System programs, not npm packages: ffmpeg makes the Theora fixture again by hand (node
  // tests/support/fixtures/theora-fixture.js; CI never runs it, the fixture is committed); dpkg-query is asked,
  // best effort, for Mesa's version (src/runner/drawn-by.js).
  ignoreBinaries: ['ffmpeg', 'dpkg-query'],
  // The files that must all be reached. `!` marks what ships (the page, the command line), for
  // `knip --production`: it checks that package.json's dependencies are what they use.
  project: ['src/**/*.js!', 'bin/**/*.js!', 'tests/**/*.{js,ts}', '*.js'],
};
