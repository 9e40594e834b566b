// The engine page's entry (engine.html): only what draws, for the command line. The app (its
// Shadertoy inputs, passes and render worker), the recorder, the watchdog and the engine's hook
// (hook/engine-hook.js: window.shaderEngine), and none of the interactive page's widgets (ui/, the
// inspector, kept work) nor any shader family's own code (tests/unit/lint-rooms.test.js walks its
// imports; the lint rule in eslint.config.js keeps them out). A view is opened as on the interactive page
// (open-view.js), strictly: a shader that cannot be had rejects the view, never another drawn in
// its place. What it says comes back to the command line as data through the hook (notes(),
// hang(), info()), and as one line of text on the page (engine-status.js).
//
// With no ?shader= (and no #source=) it runs a black start shader. "Converge when still"
// (--converge) runs a shader's progressive form, which the page is given from outside the player
// (`#engine-plug-ins`: src/engine-plug-ins.js) and loads only when a converge is asked for.

import { installEngine, EngineHook } from './hook/engine-hook.js';
import { installFailedHook } from './hook/failed-hook.js';
import { parseUrlParams } from '../shared/url-params.js';
import { progressiveForm } from '#engine-plug-ins';
import { Recorder } from './io/recorder.js';
import { openView, useBuiltinShader } from './open-view.js';
import { startPage } from './start-page.js';
import { followStatus, showStatus } from './engine-status.js';

/** The engine page's built-in shader: black, and cheap to compile. */
useBuiltinShader({
  name: 'start.glsl',
  text: 'void mainImage(out vec4 c, in vec2 f) { c = vec4(0.0, 0.0, 0.0, 1.0); }\n',
  what: "the engine page's start shader",
});

async function start() {
  const started = await startPage((error) => {
    showStatus(`The engine could not start: ${error.message}`);
    installFailedHook(error, EngineHook);
  });
  if (!started) return;
  const { app, params } = started;
  app.converge.use(progressiveForm);
  const open = (/** @type {string} */ query) => {
    const url = new URL(query, location.href);
    return openView(app, parseUrlParams(url.search, url.href), { hash: url.hash, again: true });
  };
  // the first view starts compiling only after this task: the hook's marks follow it from its start
  const ready = openView(app, params, { hash: location.hash, strict: true });
  ready.catch((error) => showStatus(String(error.report ?? error.message).split('\n')[0]));
  followStatus(app, installEngine(app, { ready, open, recorder: new Recorder(app) }));
}

start();
