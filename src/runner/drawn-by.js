// What drew a folder's references: DIR/__references__/drawn-by.json, written by `test --update`
// beside the PNGs, read by every later run. A run draws with that renderer unless --renderer
// says otherwise, so that references are never compared with another renderer's pictures
// silently; and when a comparison fails, what drew the references and what draws now are both
// said, in enough detail to tell why (another renderer, another Chromium, another Mesa and LLVM,
// another processor: llvmpipe compiles for the CPU it runs on, and one with FMA or AVX-512 may
// round differently from the one that drew the references).

import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

const DRAWN_BY_FILE = 'drawn-by.json';

/**
 * @typedef {object} DrawnBy
 * @property {import('../headless/renderers.js').RendererName} renderer
 * @property {string} webgl the WebGL2 renderer string ("ANGLE (Mesa/X.org, llvmpipe (LLVM 15.0.6 256 bits), ...)")
 * @property {string} chromium
 * @property {string | null} mesa Mesa's version, where the package manager says it (llvmpipe only)
 * @property {string} cpu the processor's model
 * @property {string[]} cpuFeatures the vector and FMA features that change what LLVM emits
 * @property {string} platform os and architecture
 */

/** The processor features that change llvmpipe's code (and so, possibly, its rounding). */
const FEATURES = ['sse4_2', 'avx', 'avx2', 'fma', 'f16c', 'avx512f', 'avx512vl', 'asimd', 'neon'];

/** This machine's processor features among FEATURES (Linux: /proc/cpuinfo; else none). */
function cpuFeatures() {
  try {
    const info = fs.readFileSync('/proc/cpuinfo', 'utf8');
    const flags = new Set(/^(?:flags|Features)\s*:\s*(.*)$/m.exec(info)?.[1].split(/\s+/) ?? []);
    return FEATURES.filter((flag) => flags.has(flag));
  } catch {
    return [];
  }
}

/** Mesa's version from the package manager (Debian's libgl1-mesa-dri), or null. */
function mesaVersion() {
  try {
    return (
      execFileSync('dpkg-query', ['-W', '-f=${Version}', 'libgl1-mesa-dri'], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }) ||
      null
    );
  } catch {
    return null;
  }
}

/**
 * What draws in this run, as a reference records it.
 * @param {{rendererName: import('../headless/renderers.js').RendererName, renderer: string, chromium: string}} environment
 * @returns {DrawnBy}
 */
export function drawnByNow(environment) {
  return {
    renderer: environment.rendererName,
    webgl: environment.renderer,
    chromium: environment.chromium,
    mesa: environment.rendererName === 'llvmpipe' ? mesaVersion() : null,
    cpu: os.cpus()[0]?.model ?? 'unknown',
    cpuFeatures: cpuFeatures(),
    platform: `${process.platform}-${process.arch}`,
  };
}

/**
 * What drew the references under `referenceDir`, or null where nothing says: a folder written
 * before the record existed (its references are SwiftShader's, the only renderer there was), or
 * none written yet.
 * @param {string} referenceDir
 * @returns {DrawnBy | null}
 */
export function readDrawnBy(referenceDir) {
  const file = path.join(referenceDir, DRAWN_BY_FILE);
  if (!fs.existsSync(file)) return null;
  try {
    return JSON.parse(fs.readFileSync(file, 'utf8'));
  } catch (error) {
    throw new Error(`${file}: not valid JSON (${error.message.split('\n')[0]}); write it again with test --update`, { cause: error });
  }
}

/** @param {string} referenceDir @param {DrawnBy} drawnBy */
export function writeDrawnBy(referenceDir, drawnBy) {
  fs.mkdirSync(referenceDir, { recursive: true });
  fs.writeFileSync(path.join(referenceDir, DRAWN_BY_FILE), JSON.stringify(drawnBy, null, 2) + '\n');
}

/**
 * The renderer a run uses unless one is asked for: the references' own; SwiftShader for
 * references written before the record (there was no other); 'auto' for a folder with none yet.
 * @param {DrawnBy | null} recorded
 * @param {boolean} hasReferences
 * @returns {import('../headless/renderers.js').RendererName | 'auto'}
 */
export function referenceRenderer(recorded, hasReferences) {
  if (recorded) return recorded.renderer;
  return hasReferences ? 'swiftshader' : 'auto';
}

/**
 * How what draws now differs from what drew the references, in words ('' when in nothing that
 * changes pixels): a failed comparison says it, so a person can tell a renderer's rounding from
 * a change of the shader.
 * @param {DrawnBy} recorded @param {DrawnBy} now
 */
export function drawnByDifference(recorded, now) {
  /** @type {Array<[string, string, string]>} */
  const fields = [
    ['renderer', recorded.renderer, now.renderer],
    ['WebGL2', recorded.webgl, now.webgl],
    ['Chromium', recorded.chromium, now.chromium],
    ['Mesa', recorded.mesa ?? '', now.mesa ?? ''],
    ['CPU', recorded.cpu, now.cpu],
    ['CPU features', recorded.cpuFeatures.join(' '), now.cpuFeatures.join(' ')],
  ];
  return fields
    .filter(([, was, is]) => was !== is)
    .map(([what, was, is]) => `${what} ${was || 'none'} -> ${is || 'none'}`)
    .join('; ');
}
