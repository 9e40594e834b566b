// The three things that can draw a picture here, and how Chromium is asked for each: one table,
// read by the launch (browser.js), the command line's --renderer and the harness's
// SHADERPROOF_RENDERER.
//
//   swiftshader  Chromium's own CPU rasterizer (ANGLE on SwiftShader's Vulkan). Bundled with every
//                Chromium, the same bytes on every machine with the same Chromium build: the
//                project's goldens are drawn with it. It shades 2x2 quads as SIMD lanes and runs
//                both sides of every branch.
//   llvmpipe     Mesa's LLVM-compiled rasterizer, reached through ANGLE's OpenGL ES back end on
//                EGL (`--use-angle=gl-egl`). No X display is needed: ANGLE opens Mesa's EGL on
//                its surfaceless platform (tried here on Chromium 156 with Mesa 22.3.6; the
//                desktop-GL back end, `--use-angle=gl`, does need one). 8 lanes wide on AVX2, on
//                every core: 3-8x faster on heavy frames, though LLVM compiles a program more
//                slowly than SwiftShader's Subzero. Like SwiftShader it runs both sides of every
//                branch, masked (docs/benchmark.md, bench:branches).
//   gpu          the machine's own GPU, checked to be hardware, never a software one in its
//                place: for the benchmark and for a person's own renders, never for goldens.

import fs from 'node:fs';
import path from 'node:path';

/** @typedef {'swiftshader' | 'llvmpipe' | 'gpu'} RendererName */

/** @type {readonly RendererName[]} */
export const RENDERER_NAMES = Object.freeze(['swiftshader', 'llvmpipe', 'gpu']);

/** The environment variable that picks the renderer of the project's own suite and benchmarks. */
export const RENDERER_ENV = 'SHADERPROOF_RENDERER';

/** Flags every launch has, whatever draws. */
export const BASE_ARGS = Object.freeze([
  '--no-sandbox',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--disable-default-apps',
  '--disable-extensions',
  '--mute-audio',
  '--lang=en-US',
]);

export const SWIFTSHADER_ARGS = Object.freeze([...BASE_ARGS, '--use-angle=swiftshader', '--enable-unsafe-swiftshader']);

export const LLVMPIPE_ARGS = Object.freeze([
  ...BASE_ARGS,
  '--use-gl=angle',
  '--use-angle=gl-egl',
  // Chromium blocks WebGL on llvmpipe (a software GL) unless told not to.
  '--ignore-gpu-blocklist',
]);

/** The Debian packages that give ANGLE Mesa's EGL and its llvmpipe driver. */
export const MESA_PACKAGES = Object.freeze(['libegl1', 'libegl-mesa0', 'libgl1-mesa-dri']);

const LIBRARY_DIRS = [
  '/usr/lib/x86_64-linux-gnu',
  '/usr/lib/aarch64-linux-gnu',
  '/usr/lib/i386-linux-gnu',
  '/usr/lib64',
  '/usr/lib',
  '/usr/local/lib',
];
const VENDOR_DIRS = ['/usr/share/glvnd/egl_vendor.d', '/etc/glvnd/egl_vendor.d', '/usr/local/share/glvnd/egl_vendor.d'];

/**
 * Where Mesa's EGL and its software driver are, or what is missing: { vendorFile, egl, driver,
 * missing: string[] }. Read from the file system, so that the default renderer is one
 * predictable rule (llvmpipe where Mesa is installed) and a missing piece is named before a
 * browser starts. Mesa up to 23 puts llvmpipe in dri/swrast_dri.so, 24 on in libgallium-*.so.
 * @param {(file: string) => boolean} [exists]
 * @param {(dir: string) => string[]} [list]
 */
export function findMesa(exists = fs.existsSync, list = safeList) {
  const vendorFile = VENDOR_DIRS.map((dir) => path.join(dir, '50_mesa.json')).find(exists);
  const egl = LIBRARY_DIRS.map((dir) => path.join(dir, 'libEGL_mesa.so.0')).find(exists);
  const driver =
    LIBRARY_DIRS.map((dir) => path.join(dir, 'dri', 'swrast_dri.so')).find(exists) ??
    LIBRARY_DIRS.flatMap((dir) =>
      list(dir)
        .filter((name) => /^libgallium[-.].*\.so/.test(name))
        .map((name) => path.join(dir, name)),
    )[0];
  const missing = [];
  if (!vendorFile || !egl) missing.push("Mesa's EGL (libEGL_mesa.so.0 and its glvnd vendor file)");
  if (!driver) missing.push("Mesa's llvmpipe driver (swrast_dri.so or libgallium)");
  return { vendorFile, egl, driver, missing };
}

/** @param {string} dir */
function safeList(dir) {
  try {
    return fs.readdirSync(dir);
  } catch {
    return [];
  }
}

/** The one line a person reads when llvmpipe cannot be had here. @param {string[]} missing */
export function mesaMissingLine(missing) {
  return (
    `llvmpipe needs Mesa, and this machine lacks ${missing.join(' and ')}: ` +
    `install Debian's ${MESA_PACKAGES.join(' ')} (apt-get install -y ${MESA_PACKAGES.join(' ')}), or use --renderer swiftshader`
  );
}

/**
 * The environment Chromium gets for llvmpipe: Mesa's EGL chosen by name (on a machine with a GPU,
 * glvnd would otherwise load the GPU vendor's EGL) and its software rasterizer forced, so that a
 * machine with a GPU still draws with llvmpipe when llvmpipe is asked for.
 * @param {string | undefined} vendorFile
 */
export function llvmpipeEnv(vendorFile) {
  return {
    LIBGL_ALWAYS_SOFTWARE: '1',
    GALLIUM_DRIVER: 'llvmpipe',
    EGL_PLATFORM: 'surfaceless',
    ...(vendorFile ? { __EGL_VENDOR_LIBRARY_FILENAMES: vendorFile } : {}),
  };
}

/**
 * Whether a WebGL2 renderer string is the renderer asked for: SwiftShader's names SwiftShader,
 * llvmpipe's names llvmpipe ("ANGLE (Mesa/X.org, llvmpipe (LLVM 15.0.6 256 bits), OpenGL ES
 * 3.2)"); the GPU's is checked by browser.js (a hardware renderer, whatever its name).
 * @param {RendererName} name @param {string} renderer
 */
export function drawnBy(name, renderer) {
  if (name === 'swiftshader') return /swiftshader/i.test(renderer);
  if (name === 'llvmpipe') return /llvmpipe/i.test(renderer);
  return true;
}

/**
 * The renderer a verb draws with: the one asked for (--renderer, --gpu), else `fallback`
 * ('auto': llvmpipe where Mesa is installed, else SwiftShader). Throws a usage-style Error for an
 * unknown name, or for --gpu with another --renderer.
 * @param {{renderer?: string, gpu?: boolean}} asked
 * @param {RendererName | 'auto'} fallback
 * @returns {RendererName}
 */
export function chooseRenderer({ renderer, gpu }, fallback, mesa = findMesa) {
  if (renderer !== undefined && !RENDERER_NAMES.includes(/** @type {RendererName} */ (renderer)))
    throw new Error(`--renderer ${renderer}: not a renderer; one of ${RENDERER_NAMES.join(', ')}`);
  if (gpu && renderer !== undefined && renderer !== 'gpu') throw new Error(`--gpu and --renderer ${renderer} disagree: give one`);
  if (gpu) return 'gpu';
  if (renderer) return /** @type {RendererName} */ (renderer);
  if (fallback !== 'auto') return fallback;
  return mesa().missing.length === 0 ? 'llvmpipe' : 'swiftshader';
}

/**
 * The renderer the project's own suite, scripts and benchmarks use: $SHADERPROOF_RENDERER, else
 * SwiftShader (the goldens' renderer). An unknown name throws.
 * @returns {RendererName}
 */
export function suiteRenderer(env = process.env) {
  const asked = env[RENDERER_ENV];
  if (!asked) return 'swiftshader';
  if (!RENDERER_NAMES.includes(/** @type {RendererName} */ (asked)))
    throw new Error(`${RENDERER_ENV}=${asked}: not a renderer; one of ${RENDERER_NAMES.join(', ')}`);
  return /** @type {RendererName} */ (asked);
}
