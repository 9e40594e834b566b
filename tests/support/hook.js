// The studio's hook (window.shaderEngine, src/studio/page-hook.js) from a test: each of its
// methods called on the page, its result back as data. A test asks the page through this, not
// through a page.evaluate() of its own; the engine page's own client is src/headless/client.js.
// What is left to page.evaluate() in the tests is the DOM the studio's widgets show.

/**
 * The hook's methods as Node sees them: the same arguments, the result as a promise of its data.
 * @typedef {{[K in Exclude<keyof import('../../src/studio/page-hook.js').PageHook, 'ready'>]:
 *   import('../../src/studio/page-hook.js').PageHook[K] extends (...args: infer A) => infer R
 *     ? (...args: A) => Promise<Awaited<R>> : never}} HookFromNode
 */

/**
 * The hook of `page`. `ready()` waits for the page's first frame (the hook's `ready` promise).
 * @param {import('puppeteer-core').Page} page
 * @returns {HookFromNode & {ready: () => Promise<void>}}
 */
export function hook(page) {
  return /** @type {any} */ (
    new Proxy(
      {},
      {
        get: (_, name) =>
          name === 'ready'
            ? () => page.evaluate(() => window.shaderEngine.ready.then(() => undefined))
            : (/** @type {unknown[]} */ ...args) =>
                page.evaluate((method, given) => /** @type {any} */ (window.shaderEngine)[method](...given), String(name), args),
      },
    )
  );
}
