// The benchmark's variants (run.js): the project's shader across its quality controls, in the
// page's uniform form, with its savings switched off (peers/savings-off.glsl) and with one trace
// site, an empty shader (the floor), and four peers (tests/bench/peers/): the assignment's
// algorithm, sphere tracing, a plain analytic tracer spliced into the project's file, and a
// standalone plain tracer that shares no line with the project (standalone.glsl: what the
// project's structure costs); then the other scenes. Each is a whole fragment shader in
// Shadertoy's header.

import fs from 'node:fs';
import path from 'node:path';
import { composeImageShader, hostControlBlock } from '../../src/shadertoy/header.js';
import { parseControls } from '../../src/shadertoy/controls.js';
import { REPO_ROOT, SHADER_FILE } from '../support/config.js';
import { EXTRA_SAMPLES_VIEW } from '../../src/raytracer/extra-samples.js';
import { composePeer } from './peers/compose-peer.js';
import {
  ONE_TRACE_SITE,
  PAGE_FORM,
  PLAIN,
  SAVINGS_OFF,
  SCENES_GROUP,
  STANDALONE,
  sceneVariant,
  adaptiveSamples,
  sphereTracing,
  uniformSamples,
} from './targets.js';

const BENCH_DIR = path.join(REPO_ROOT, 'tests', 'bench');
const read = (file) => fs.readFileSync(file, 'utf8');

export const source = read(SHADER_FILE);
const controls = parseControls(source);
/** The live controls at their defaults, for the variant in the page's uniform form. */
export const uniformValues = controls.filter((c) => c.kind === 'uniform').map((c) => ({ name: c.name, type: c.type, value: c.default }));
const defaults = Object.fromEntries(controls.map((c) => [c.name, c.default]));

// Every variant is compiled in the paste form (the live controls as constants with their
// default values: the shader as Shadertoy compiles it, and as the page runs it while its
// controls rest) but the one marked `uniforms`, the page's form while a control moves.
const pasteForm = (text, defines = {}, extra = '') =>
  composeImageShader(text, { hostBlock: hostControlBlock(controls, defines, defaults) + extra }).code;
/** The project's shader with some compile-time controls changed; one sample per pixel unless they say otherwise. */
const ONE_SAMPLE = { SAMPLES: 1, ADAPTIVE_AA: 0 };
const project = (defines = {}) => pasteForm(source, { ...ONE_SAMPLE, ...defines });
const composed = (file, dir = path.join(BENCH_DIR, 'peers')) => composePeer(source, read(path.join(dir, file)), { peerName: file });
const peer = (file, extra = '') => pasteForm(composed(file), ONE_SAMPLE, extra);
const EMPTY = composeImageShader(
  'void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n    fragColor = vec4(0.5, 0.5, 0.5, 1.0);\n}\n',
).code;

/**
 * @typedef {{name: string, group: string, spp: number, code: () => string, adaptive?: boolean, uniforms?: boolean, scene?: number}} BenchVariant
 * group: which series a variant belongs to on the chart; spp: samples per pixel (an adaptive
 * variant's: what an edge pixel gets, the others take one)
 */

/** @type {BenchVariant[]} */
export const ALL_VARIANTS = [
  { name: 'empty shader (floor)', group: 'floor', spp: 1, code: () => EMPTY },
  ...[1, 4, 9, 16].map((spp) => ({
    name: uniformSamples(spp),
    group: 'project: samples',
    spp,
    code: () => project({ SAMPLES: spp, ADAPTIVE_AA: 0 }),
  })),
  ...[4, 9, 16].map((spp) => ({
    name: adaptiveSamples(spp),
    group: 'project: adaptive',
    spp,
    adaptive: true,
    code: () => project({ SAMPLES: spp, ADAPTIVE_AA: 1 }),
  })),
  ...[0, 1, 2, 4].map((bounces) => ({
    name: `project, bounces ${bounces}`,
    group: 'project: bounces',
    spp: 1,
    code: () => project({ BOUNCES: bounces }),
  })),
  { name: 'project, no shadows', group: 'project: features', spp: 1, code: () => project({ SHADOWS: 0 }) },
  { name: 'project, primary rays only', group: 'project: features', spp: 1, code: () => project({ SHADOWS: 0, BOUNCES: 0 }) },
  { name: 'project, unfiltered stripes', group: 'project: features', spp: 1, code: () => project({ TEXTURE_FILTER: 0 }) },
  {
    name: PAGE_FORM,
    group: 'project: page form',
    spp: 1,
    uniforms: true,
    code: () => composeImageShader(source, { hostBlock: hostControlBlock(controls, ONE_SAMPLE) }).code,
  },
  { name: SAVINGS_OFF, group: 'project: savings off', spp: 1, code: () => pasteForm(composed('savings-off.glsl'), ONE_SAMPLE) },
  { name: ONE_TRACE_SITE, group: 'project: one trace site', spp: 1, code: () => pasteForm(composed('one-trace-site.glsl'), ONE_SAMPLE) },
  { name: 'assignment (peer 1)', group: 'peer: assignment', spp: 1, code: () => peer('assignment.glsl') },
  ...[32, 64, 128, 256].map((steps) => ({
    name: sphereTracing(steps),
    group: 'peer: sphere tracing',
    spp: 1,
    code: () => peer('sdf.glsl', `#define MAX_STEPS ${steps}\n`),
  })),
  { name: PLAIN, group: 'peer: plain analytic', spp: 1, code: () => peer('plain.glsl') },
  // A whole shader of its own, in Shadertoy's header only: none of the project's text.
  {
    name: STANDALONE,
    group: 'peer: standalone plain',
    spp: 1,
    code: () => composeImageShader(read(path.join(BENCH_DIR, 'peers', 'standalone.glsl'))).code,
  },
  // The other scenes (SCENE): their frame times, and their error against their own converged
  // reference (they are other pictures: off the chart and the Pareto front).
  ...[1, 2].map((scene) => ({
    name: sceneVariant(scene),
    group: SCENES_GROUP,
    spp: 1,
    scene,
    code: () => project({ SCENE: scene }),
  })),
];

/** An adaptive variant's "Extra samples" debug view: which pixels took the extra samples. @param {number} spp */
export const extraSamplesView = (spp) => project({ SAMPLES: spp, ADAPTIVE_AA: 1, ...EXTRA_SAMPLES_VIEW });
