// The raytracer's "Converge when still", plugged into the engine's convergence (src/player/app/
// converge.js use()): which shaders have a progressive form (the raytracer, or an edit that keeps
// its camera and radiance functions), the form itself (progressive.js), and the sample count it
// draws over the picture while it converges (an overlay: a render turns it off). The interactive
// page plugs it in at its start (main.js); the engine page loads it when a converge is asked for
// (src/engine-plug-ins.js: import()).

import { MAX_SAMPLES, missingRaytracerFunctions, progressiveTabs } from './progressive.js';

/** @type {import('../player/app/converge.js').ProgressiveForm} */
export const raytracerConvergence = {
  name: 'the raytracer',
  file: 'shaders/raytrace.glsl',
  maxSamples: MAX_SAMPLES,
  missing: missingRaytracerFunctions,
  form: progressiveTabs,
  controls: { SHOW_SAMPLE_COUNT: 1 },
  overlays: ['SHOW_SAMPLE_COUNT'],
};
