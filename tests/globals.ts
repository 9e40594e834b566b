// Types for `npm run typecheck` only (nothing imports this file at run time): the globals that
// the pages under test define on `window`, which the tests reach through page.evaluate(), and
// what vitest's globalSetup (tests/harness/setup.js) provides to the test files. It is a .ts
// file, not a .d.ts, so that skipLibCheck (jsconfig.json) does not skip it: a broken import()
// here is an error. JSDoc reaches its types as import('./globals.js').

/** Base64 RGBA8 pixels, rows top to bottom, as the page hands them over page.evaluate(). */
interface Base64Frame {
  width: number;
  height: number;
  data: string;
}

/** window.raytracer.info(): see src/page/automation.js. */
export interface RaytracerInfo {
  /** UNMASKED_RENDERER_WEBGL (or RENDERER) */
  renderer: string;
  vendor: string;
  version: string;
  shadingLanguage: string;
  /** the drawing buffer's size, device pixels */
  width: number;
  height: number;
  /** frames drawn so far */
  frame: number;
  /** the next frame's iFrame (0 after a restart or a newly loaded shader) */
  iFrame: number;
  time: number;
  playing: boolean;
  speed: number;
  /** iMouse: [x, y, z, w] */
  mouse: number[];
  /** the controls' current values, by name: a number, a boolean or an array of numbers */
  controls: Record<string, any>;
  fileName: string;
  shaderUrl: string | null;
  origin: import('../src/page/app/app.js').RaytracerApp['origin'];
  contextLost: boolean;
  /** successful compiles so far */
  compiled: number;
  liveControls: 'constants' | 'uniforms';
  /** the watchdog's verdict: a frame has gone HANG_AFTER_MS without finishing a band */
  hung: boolean;
  /** how far the frame being drawn has got (rows done, bands drawn); null when none is */
  progress: { y: number; height: number; bands: number } | null;
  /** "Converge when still" is on */
  converging: boolean;
  /** frames drawn since the last change */
  stillFrames: number;
  /** Only on a page that could not start (installFailedAutomation), which reports nothing else. */
  error?: string;
}

/** What setSource() and loadShader() resolve with. */
interface CompileOutcome {
  ok: boolean;
  /** the compile error's report (or message) when !ok */
  error?: string;
}

/** What record() resolves with: the recording's settings and the file as base64. */
type RecordingResult = Omit<import('../src/page/io/recorder.js').Recording, 'bytes'> & { data: string };

/** window.raytracer: the page's automation hook, installed by src/page/automation.js (see its header). */
export interface RaytracerHook {
  /** Resolves after the first frame has been drawn; rejects when WebGL2 is missing or the first compile fails. */
  ready: Promise<void>;
  /** The page as a fresh load of `query` ("?…" and "#…") gives it, without a reload (src/page/open-view.js). */
  open(query: string): Promise<void>;
  /** Draws one frame and reads it back. */
  readPixels(): Promise<Base64Frame>;
  /** Draws n frames back to back: per-frame times in ms and their median. */
  renderFrames(n?: number): Promise<{ median: number; times: number[] }>;
  /** Sets shader controls as the URL does; resolves once compiled. */
  setControls(changes: Record<string, unknown>): Promise<void>;
  setSource(source: string): Promise<CompileOutcome>;
  /** Runs a multipass shader given as Shadertoy's JSON export. */
  setProject(json: object | string): Promise<CompileOutcome & { notes: string[] }>;
  /** "Converge when still" on or off; `frames`: still frames to draw. */
  setConverging(on: boolean, options?: { frames?: number }): Promise<void>;
  play(): void;
  pause(): void;
  togglePlay(): void;
  restart(): void;
  setTime(seconds: number): void;
  setSpeed(speed: number): void;
  /** iMouse [x, y, z, w] in device pixels, until the next click */
  setMouse(mouse: number[]): void;
  resetView(): void;
  /** The next frame the page draws by itself, and its iFrame. Asks for no frame. */
  nextFrame(): Promise<Base64Frame & { iFrame: number }>;
  /** The render worker's WebGL context lost / restored through WEBGL_lose_context. */
  loseContext(): void;
  restoreContext(): void;
  /** The last frame drawn again off screen at that size (default: the canvas's). */
  capture(size?: { width: number; height: number } | null): Promise<Base64Frame>;
  /** An image into iChannel `index` (null: black again). */
  setChannel(index: number, url: string | null): Promise<void>;
  /** Fetches and runs a shader as ?shader= does. */
  loadShader(url: string): Promise<CompileOutcome>;
  /** The link "Copy link" copies. */
  shareUrl(): string;
  /** The editor's text (what it holds, compiled or not). */
  editorSource(): string;
  /** Records the shader frame by frame (src/page/io/recorder.js); `data` is the file as base64. */
  /** The last frame's Image pass in RGBA32F: `data` is base64 of the floats' bytes, rows top to bottom. */
  captureFloat(): Promise<Base64Frame>;
  /** A tile, from the bottom left, of the last frame drawn at fullWidth × fullHeight. */
  captureTile(tile: { x: number; y: number; width: number; height: number; fullWidth: number; fullHeight: number }): Promise<Base64Frame>;
  record(request?: import('../src/page/io/recorder.js').RecordRequest): Promise<RecordingResult>;
  /** Frame `frame` as record() would draw it, and no file (recorder.js frameAt); `data` is base64 RGBA8. */
  frameAt(request: {
    frame: number;
    fps?: number;
    width?: number;
    height?: number;
  }): Promise<{ width: number; height: number; data: string }>;
  /** The Sound tab's samples from `time` for `duration` s (src/page/sound/samples.js): `data` is base64 of interleaved Int16 LE. */
  renderSound(request?: {
    time?: number;
    duration?: number;
  }): Promise<{ sampleRate: number; channels: number; samples: number; data: string }>;
  /** The Sound tab's player (src/page/sound/player.js) as it is now. */
  soundState(): {
    available: boolean;
    context: AudioContextState | null;
    muted: boolean;
    plan: { sample: number; when: number; rate: number; time: number } | null;
    now: number | null;
    sources: number;
    level: number;
  };
  /** The Sound tab's mute button. */
  setMuted(muted: boolean): void;
  /** Stops the recording under way: its record() rejects, nothing is made. */
  cancelRecording(): void;
  recording(): { busy: boolean; done: number; total: number };
  /** Inspect on, pixel (x, y) pinned (y from the bottom) and read, path and reference included (src/page/inspect/inspector.js). */
  inspect(x: number, y: number): Promise<Readout>;
  /** The inspector as it is now. */
  inspection(): { active: boolean; pinned: { x: number; y: number } | null; problem: string | null; readout: Readout | null };
  unpin(): void;
  /** "Compare with float64" on the frame on the canvas (src/page/inspect/compare.js). */
  compareWithFloat64(): Promise<ComparisonSummary>;
  /** The comparison's state on the page. */
  comparison(): {
    running: { phase: string; rows: number; of: number } | null;
    error: string | null;
    stale: boolean;
    shown: { width: number; height: number } | null;
  };
  info(): RaytracerInfo;
}

/** What the pixel inspector read at a pixel. */
export type Readout = import('../src/page/inspect/inspector.js').Readout;

/** What compareWithFloat64() resolves with: a ComparisonResult without its images. */
type ComparisonSummary = Pick<
  import('../src/page/inspect/compare.js').ComparisonResult,
  'figures' | 'width' | 'height' | 'extraSampleShare' | 'frame' | 'ms' | 'caveat'
>;

/** window.__benchmark: the benchmark's programs, set up in its raw WebGL2 page (tests/bench/timer.js). */
interface BenchmarkPage {
  /** Draws shader `i` once, with a 1-pixel readPixels: the time it took, in ms. */
  frame(i: number): number;
  /** Draws shader `i` once: its pixels as base64 RGBA8, rows top to bottom. */
  pixels(i: number): string;
}

/** What tests/harness/setup.js starts and hands to the test files (inject('harness')) and to scripts. */
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
    /** The page's automation hook (src/page/automation.js). */
    raytracer: RaytracerHook;
    /** The longest gap between 10 ms timer ticks (tests/page-heavy.test.js). */
    __longestGap: number;
    /** The raw WebGL2 page's functions (tests/harness/raw-webgl-page.js). */
    __rawWebGL: import('./harness/raw-webgl-page.js').RawWebGL;
    /** Set by the deterministic injection (tests/harness/deterministic-injection.js). */
    __deterministic: Readonly<{ fixedTime: number; frameMs: number }>;
    /** Set by the benchmark's timer (tests/bench/timer.js). */
    __benchmark: BenchmarkPage;
    /** Set by page-helpers.js's nextFrame(): the frame it waits for. */
    __nextFrame: ReturnType<RaytracerHook['nextFrame']>;
    /** Set by page-heavy.test.js's compile test: hold back the next compiling band's messages this long. */
    __holdCompileMs: number;
    /** Set by the first-pin test (tests/page-inspector.test.js): the complete readout to come. */
    __complete: ReturnType<RaytracerHook['inspect']>;
    /** Set by the lost-context test (tests/page-lifecycle.test.js). */
    /** Set by the file-watching tests (tests/page-lifecycle.test.js): still true if the page did not reload. */
    __sameDocument: boolean;
    /** Set by the pointer test (tests/page-shaders.test.js): the last pointer event's position. */
    __pointer: { clientX: number; clientY: number };
  }
}

declare module 'vitest' {
  interface ProvidedContext {
    harness: HarnessContext;
  }
}
