// What the engine page (src/player/engine.html) is given from outside the player: the player
// imports this module as `#engine-plug-ins` (package.json "imports"), so that its own code names
// no shader family, and this is where the package says which ones it ships.
//
// Today one: the built-in raytracer's "Converge when still" (--converge), loaded only when a
// converge is asked for (import(): a chunk of its own, never part of the engine page's bundle).

/** @type {import('./player/app/converge.js').FormSource} */
export const progressiveForm = () => import('./raytracer/convergence.js').then((module) => module.raytracerConvergence);
