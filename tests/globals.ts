// Types for `npm run typecheck` only (nothing imports this file at run time): the globals that
// the pages under test define on `window`, which the tests reach through page.evaluate(), and
// what vitest's globalSetup (tests/support/setup.js) provides to the test files. It is a .ts
// file, not a .d.ts, so that skipLibCheck (jsconfig.json) does not skip it: a broken import()
// here is an error. JSDoc reaches its types as import('./globals.js').

/** window.shaderEngine.info(): see src/player/hook/engine-state.js. */
export type HookInfo = ReturnType<WindowHook['info']>;

/**
 * window.shaderEngine: the page's hook, its type the hook's class, in src/ (the engine's,
 * src/player/hook/engine-hook.js, with the interactive page's methods: page-hook.js). The tests
 * drive both pages; the command line reads the engine's alone (src/headless/client.js, HookedWindow).
 */
type WindowHook = import('../src/studio/page-hook.js').PageHook;

/** Whether T is `any` (what an untyped parameter of a JavaScript function is). */
type IsAny<T> = 0 extends 1 & T ? true : false;
/** The names of H's methods with a parameter of type `any`. */
type UntypedMethods<H> = {
  [K in keyof H]: H[K] extends (...args: infer P) => unknown ? (true extends { [I in keyof P]: IsAny<P[I]> }[number] ? K : never) : never;
}[keyof H];
/** Compiles only when `Untyped` is never: no method named. */
type Typed<Untyped extends never> = Untyped;
/**
 * Every parameter of the hook's methods is typed (issue 46): a method with an `any` parameter
 * names itself in the error here (npm run typecheck). The hook is the command line's contract
 * with the page.
 */
type HookParametersTyped = Typed<UntypedMethods<WindowHook>>;

/** What the pixel inspector read at a pixel. */
export type Readout = import('../src/studio/inspect/inspector.js').Readout;

/** window.__benchmark: the benchmark's programs, set up in its raw WebGL2 page (tests/bench/timer.js). */
interface BenchmarkPage {
  /** Draws shader `i` once, with a 1-pixel readPixels: the time it took, in ms. */
  frame(i: number): number;
  /** Draws shader `i` once: its pixels as base64 RGBA8, rows top to bottom. */
  pixels(i: number): string;
}

/** What tests/support/setup.js starts and hands to the test files (inject('harness')) and to scripts. */
export interface HarnessContext {
  /** the browser's DevTools WebSocket endpoint */
  wsEndpoint: string;
  /** the page server's URL, without a trailing slash */
  baseUrl: string;
  environment: { chromium: string; renderer: string; webglVersion: string };
}

declare global {
  // Each of these exists only on its own page (or after the test sets it): read them there.
  interface Window {
    /** The page's hook (src/player/hook/: engine-hook.js, and page-hook.js on the interactive page). */
    shaderEngine: WindowHook;
    /** The longest gap between 10 ms timer ticks (tests/browser/page-heavy.test.js). */
    __longestGap: number;
    /** The time the page's script was held up past 100 ms, in all (tests/browser/page-heavy.test.js). */
    __heldUp: number;
    /** The raw WebGL2 page's functions (tests/support/raw-webgl/raw-webgl-page.js). */
    __rawWebGL: import('./support/raw-webgl/raw-webgl-page.js').RawWebGL;
    /** Set by the deterministic injection (tests/support/deterministic-injection.js). */
    __deterministic: Readonly<{ fixedTime: number; frameMs: number }>;
    /** Set by the benchmark's timer (tests/bench/timer.js). */
    __benchmark: BenchmarkPage;
    /** Set by page-helpers.js's nextFrame(): the frame it waits for. */
    __nextFrame: ReturnType<WindowHook['nextFrame']>;
    /** Set by page-heavy.test.js's compile test: hold back the next compiling band's messages this long. */
    __holdCompileMs: number;
    /** Set by the first-pin test (tests/browser/page-inspector.test.js): the complete readout to come. */
    __complete: ReturnType<WindowHook['inspect']>;
    /** Set by the lost-context test (tests/browser/page-lifecycle.test.js). */
    /** Set by the file-watching tests (tests/browser/page-lifecycle.test.js): still true if the page did not reload. */
    __sameDocument: boolean;
    /** Set by the pointer test (tests/browser/page-shaders.test.js): the last pointer event's position. */
    __pointer: { clientX: number; clientY: number };
    /** Set by tests/browser/page-whole-frames.test.js: each picture the canvas was shown, as its distinct colours (at most 4). */
    __shown: number[][];
  }
}

declare module 'vitest' {
  interface ProvidedContext {
    harness: HarnessContext;
  }
}
