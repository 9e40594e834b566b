// The window with the engine's hook on it: the type the command line's client
// (src/headless/client.js) reads window.shaderEngine through, and tests/globals.ts declares the
// window's field with (the interactive page's hook, page-hook.js, for its tests). Types only.

/**
 * The window of a page with the hook: the engine page's (EngineHook); on the interactive page it
 * is a PageHook, the engine's methods and its widgets'.
 * @typedef {Window & {shaderEngine: import('./engine-hook.js').EngineHook}} HookedWindow
 */

export {};
