// The hook of a page that could not start (no WebGL2, a render worker that did not come up): the
// same methods as the page's hook would have had, taken from its class, so that none is missing
// (the command line and the tests call any of them): `ready` and every method reject with why the
// page could not start, and info() says it as its `error`.

import { markStartupFailure } from '../page-marks.js';
import { hookOnWindow } from './engine-hook.js';

/**
 * The names of the methods of `Hook`'s instances, its base classes' included.
 * @param {Function} Hook
 */
export function hookMethods(Hook) {
  /** @type {Set<string>} */
  const names = new Set();
  for (let proto = Hook.prototype; proto && proto !== Object.prototype; proto = Object.getPrototypeOf(proto))
    for (const name of Object.getOwnPropertyNames(proto)) if (name !== 'constructor') names.add(name);
  return [...names].sort();
}

/**
 * Installs, for a page that could not start with `error`, a hook with the methods of `Hook` (the
 * page's: engine-hook.js EngineHook on the engine page, page-hook.js PageHook on the interactive
 * one), each rejecting with `error`.
 * @template {new (...args: any[]) => import('./engine-hook.js').EngineHook} H
 * @param {Error} error
 * @param {H} Hook
 * @returns {InstanceType<H>}
 */
export function installFailedHook(error, Hook) {
  markStartupFailure(error);
  const failed = Promise.reject(error);
  failed.catch(() => {}); // said on the page
  const fail = () => failed;
  /** @type {Record<string, unknown>} */
  const hook = Object.fromEntries(hookMethods(Hook).map((name) => [name, fail]));
  Object.assign(hook, { ready: failed, info: () => ({ error: error.message }) });
  return hookOnWindow(/** @type {InstanceType<H>} */ (/** @type {unknown} */ (hook)));
}
