// The two frames that miss issue 28's targets, taken apart: the adaptive frame (target: 2.0x the
// 1-spp frame) and the torus scene (target: 1.3x the cone scene). Each row is the project's text
// with one edit (or a design tried in its place), all timed in one page at 640x360, interleaved,
// and each compared with the converged float64 reference of its scene. What a part costs is the
// difference between two rows; the designs tried are rows of their own.
//
//   npm run bench:apart              640x360, 3 compilations x 5 frames each; writes the two tables
//                                    between the apart markers in docs/benchmark.md
//   npm run bench:apart -- --quick   every variant once at 160x90, nothing written (CI)
//   npm run bench:apart -- --copies 5 --frames 8   more of each, for a noisy machine
//   SHADERPROOF_RENDERER=llvmpipe npm run bench:apart
//                                    the same on llvmpipe, between the apart-llvmpipe markers

import fs from 'node:fs';
import path from 'node:path';
import { REPO_ROOT, SHADER_FILE } from '../support/config.js';
import { rendererLabel } from '../../src/headless/browser.js';
import { withHarness } from '../support/setup.js';
import { renderRawShader } from '../support/raw-webgl/raw-webgl.js';
import { EXTRA_SAMPLES_VIEW, countExtraSamplePixels } from '../../src/raytracer/extra-samples.js';
import { replaceMarkedSection } from '../scripts/readme-section.js';
import { measureVariants } from './measure.js';
import { edit, pasteFormOf, uniformFormOf } from './variant-text.js';
import { composeImageShader } from '../../src/shadertoy/header.js';
import { median } from '../../src/shared/stats.js';

const quick = process.argv.includes('--quick');
/** The number after `flag` on the command line, else `fallback`. */
function countArg(flag, fallback) {
  const at = process.argv.indexOf(flag);
  if (at < 0) return fallback;
  const n = Number(process.argv[at + 1]);
  if (!Number.isInteger(n) || n < 1) {
    console.error(`npm run bench:apart -- ${flag} N: N must be a whole number of at least 1 (got ${process.argv[at + 1]})`);
    process.exit(2);
  }
  return n;
}
const COPIES = quick ? 1 : countArg('--copies', 3);
const FRAMES = quick ? 1 : countArg('--frames', 5);
const PEERS = path.join(REPO_ROOT, 'tests', 'bench', 'peers');
const read = (file) => fs.readFileSync(file, 'utf8');
const source = read(SHADER_FILE);
const pasteForm = pasteFormOf(source);
const ADAPTIVE = { SAMPLES: 16, ADAPTIVE_AA: 1 };
const TORUS = { SCENE: 2 };

/** The first sample's cone test `name` (silhouette, shadow, reflection) never marks a pixel. */
function withoutConeTest(text, name) {
  const at = text.indexOf(`    bool ${name} = `, text.indexOf('vec3 centreEdges('));
  if (at < 0) throw new Error(`benchmark: centreEdges has no test named ${name}`);
  return text.slice(0, at) + `    bool ${name} = false;` + text.slice(text.indexOf('\n', at));
}

// The torus's two loops, by the exit test that ends each (its trip cap).
const BEND_EXIT = 'if (any(bvec2(done, trip == 12))) break;';
const ROOT_EXIT = 'if (any(bvec2(done, trip == 16))) break;';
const BEND_LOOP = 'for (int trip = 1;; trip++) {\n        vec3 dF, ddF;';
const ROOT_LOOP = 'for (int trip = 1;; trip++) {\n        vec2 g = torusDistance';

/** The loop that starts with `head` and ends with `exit` compiled out: its values stay at their starts. */
const withoutLoop = (text, head, exit) => edit(edit(text, head, `#if 0\n    ${head}`), `${exit}\n    }\n`, `${exit}\n    }\n#endif\n`);

/** iq's closed-form torus (peers/iq/torus.glsl: the resolvent cubic, no shift or polish) in the scene. */
function withIqTorus(text) {
  const iq = read(path.join(PEERS, 'iq', 'torus.glsl')).replace(/^#define .*$/gm, '');
  const out = edit(text, '// ---- the new object ----', `${iq}\n// ---- the new object ----`);
  return edit(
    out,
    'return intersectTorus(ro, rd, torus, tMax);',
    'return iqTorus(ro, rd, IqTorus(torus.center, torus.axis, torus.majorRadius, torus.tubeRatio * torus.majorRadius), tMax);',
  );
}

/** The whole top-level function of `text` that starts with `signature`. */
function functionText(text, signature) {
  const at = text.indexOf(signature);
  if (at < 0) throw new Error(`benchmark: no ${signature} in the shader`);
  return text.slice(at, text.indexOf('\n}\n', at) + 3);
}

/**
 * Shadow rays through a copy of the scene walk whose torus runs its root loop once: the most an
 * any-hit torus could save (a shadow ray needs only whether a root lies before the light, not
 * where), with the nearest-hit walk left for the eye and reflected rays. Timing only: the copy's
 * one trip does not settle every root.
 */
function withOneTripShadowTorus(text) {
  let out = text;
  const copy = (signature, renames) => {
    const original = functionText(out, signature);
    out = edit(out, original, `${original}\n${renames.reduce((t, [from, to]) => t.replace(from, to), original)}`);
  };
  copy('vec4 intersectTorus(', [
    ['vec4 intersectTorus(', 'vec4 intersectTorusShadow('],
    [ROOT_EXIT, 'break;'],
  ]);
  copy('vec4 intersectObject(vec3 ro, vec3 rd, Object torus', [
    ['intersectObject(', 'intersectObjectShadow('],
    ['intersectTorus(', 'intersectTorusShadow('],
  ]);
  copy('Hit traceScene(', [
    ['Hit traceScene(', 'Hit traceShadow('],
    ['intersectObject(', 'intersectObjectShadow('],
  ]);
  return edit(out, 'bool blocked = traceScene(', 'bool blocked = traceShadow(');
}

// table: which table the row is in; shows: what the row tells. `edgeView` (adaptive rows made
// by an edit): the fraction of pixels that took extra samples is counted on its debug view.
const VARIANTS = [
  { table: 'adaptive', name: '1 sample per pixel', shows: 'the ratio is to this', code: () => pasteForm(source) },
  {
    table: 'adaptive',
    name: 'the sample loop, never an edge (the edge tests compiled out)',
    shows: 'the loop form around the first sample',
    code: () =>
      pasteForm(
        edit(
          edit(source, 'edge = marked > 0.0;', 'edge = false;'),
          'edges = vec4(centreEdges(s, ray.dir, eyeHit, pixelSpread), float(quad));',
          'edges = vec4(0.0);',
        ),
        ADAPTIVE,
      ),
  },
  {
    table: 'adaptive',
    name: 'every edge test computed, never an edge',
    shows: 'what the tests cost a pixel that takes no extra samples',
    code: () => pasteForm(edit(source, 'edge = marked > 0.0;', 'edge = marked > 2.0;'), ADAPTIVE),
  },
  { table: 'adaptive', name: 'adaptive 16 at edges, as it is', shows: '', edgeView: (t) => t, code: () => pasteForm(source, ADAPTIVE) },
  ...['silhouette', 'shadow', 'reflection'].map((name) => ({
    table: 'adaptive',
    name: `without the ${name} cone test`,
    shows: `what the ${name} test costs, and the error it removes`,
    edgeView: (t) => withoutConeTest(t, name),
    code: () => pasteForm(withoutConeTest(source, name), ADAPTIVE),
  })),
  {
    table: 'adaptive',
    name: "the quad's derivative test alone (no cone tests)",
    shows: 'the cheapest marking: it misses the edges that run between quads',
    edgeView: (t) => edit(t, '#define EDGE_TESTS (ADAPTIVE_AA == 1 && SAMPLES > 1)', '#define EDGE_TESTS 0'),
    code: () => pasteForm(edit(source, '#define EDGE_TESTS (ADAPTIVE_AA == 1 && SAMPLES > 1)', '#define EDGE_TESTS 0'), ADAPTIVE),
  },
  { table: 'adaptive', name: 'uniform 4', shows: 'the >2/255 target', code: () => pasteForm(source, { SAMPLES: 4 }) },
  {
    table: 'adaptive',
    name: 'uniform 16',
    shows: 'the RMSE target (within 1.15x of this)',
    code: () => pasteForm(source, { SAMPLES: 16 }),
  },

  { table: 'torus', name: 'the cone scene', shows: 'the ratio is to this', code: () => pasteForm(source) },
  {
    table: 'torus',
    scene: 2,
    name: 'the torus compiled out (never hit): the floor',
    shows: 'the scene without the torus',
    code: () => pasteForm(edit(source, 'return intersectTorus(ro, rd, torus, tMax);', 'return MISS;'), TORUS),
  },
  {
    table: 'torus',
    scene: 2,
    name: 'no loops (critical points and roots left at their starts)',
    shows: 'the straight-line code: the shift, the frame, the range, the cube root, the starts, the normal',
    code: () => pasteForm(withoutLoop(withoutLoop(source, BEND_LOOP, BEND_EXIT), ROOT_LOOP, ROOT_EXIT), TORUS),
  },
  {
    table: 'torus',
    scene: 2,
    name: 'the bend loop (critical points) removed',
    shows: 'what the bend loop costs',
    code: () => pasteForm(withoutLoop(source, BEND_LOOP, BEND_EXIT), TORUS),
  },
  {
    table: 'torus',
    scene: 2,
    name: 'the root loop removed',
    shows: 'what the root loop costs',
    code: () => pasteForm(withoutLoop(source, ROOT_LOOP, ROOT_EXIT), TORUS),
  },
  {
    table: 'torus',
    scene: 2,
    name: 'each loop capped at 1 trip',
    shows: 'what the trips past the first cost',
    code: () => pasteForm(edit(edit(source, BEND_EXIT, 'break;'), ROOT_EXIT, 'break;'), TORUS),
  },
  { table: 'torus', scene: 2, name: 'the torus scene, as it is', shows: '', code: () => pasteForm(source, TORUS) },
  {
    table: 'torus',
    scene: 2,
    name: "design tried: iq's closed form (peers/iq/torus.glsl)",
    shows: 'a bound: no origin shift, no polish, wrong on about half the hard cases (bench:primitives)',
    code: () => pasteForm(withIqTorus(source), TORUS),
  },
  {
    table: 'torus',
    scene: 2,
    name: 'design tried: shadow rays with the root loop cut to one trip',
    shows: 'the most an any-hit torus for shadow rays could save',
    code: () => pasteForm(withOneTripShadowTorus(source), TORUS),
  },
];

// What a program costs before its first frame, in each scene and form (the default view,
// adaptive 16): the wall time of renderRawShader at 2x2, which is the compile, the link and one
// tiny frame, plus opening a page, which the empty shader's row measures. Each program text is
// new to the browser (a comment numbers it), so no cache answers.
const COMPILE_ROUNDS = quick ? 1 : 3;
/** @type {Array<{scene: string, SCENE: number}>} */
const SCENES = [
  { scene: 'cone', SCENE: 0 },
  { scene: 'cylinder', SCENE: 1 },
  { scene: 'torus', SCENE: 2 },
];
const uniformForm = uniformFormOf(source);

async function compileTimes() {
  const DEFAULT_VIEW = { SAMPLES: 16, ADAPTIVE_AA: 1 };
  const programs = [
    { scene: 'the empty shader (opening the page, the floor)', form: 'paste', code: composeImageShader(EMPTY).code },
    ...SCENES.flatMap(({ scene, SCENE }) => [
      { scene, form: 'paste', code: pasteForm(source, { ...DEFAULT_VIEW, SCENE }) },
      { scene, form: 'uniform', code: uniformForm(source, { ...DEFAULT_VIEW, SCENE }) },
    ]),
  ];
  /** @type {Map<object, number[]>} */
  const seconds = new Map(programs.map((p) => [p, []]));
  let n = 0;
  for (let round = 0; round < COMPILE_ROUNDS; round++) {
    for (const program of programs) {
      const started = performance.now();
      const shown = await renderRawShader(`${program.code}\n// compile ${n++}\n`, { width: 2, height: 2 });
      if (shown.stage) throw new Error(`${program.scene} (${program.form} form): ${shown.stage}: ${shown.log}`);
      seconds.get(program)?.push((performance.now() - started) / 1000);
    }
  }
  return programs.map((p) => ({ scene: p.scene, form: p.form, seconds: seconds.get(p) ?? [] }));
}
const EMPTY = 'void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n    fragColor = vec4(0.5, 0.5, 0.5, 1.0);\n}\n';

const [width, height] = quick ? [160, 90] : [640, 360];
const results = await withHarness(async (context) => {
  const measured = await measureVariants(VARIANTS, {
    source,
    width,
    height,
    copies: COPIES,
    frames: FRAMES,
    warmup: quick ? 1 : 2,
    referenceSamplesPerAxis: quick ? 2 : 8,
  });
  /** @type {Map<string, number>} the fraction of pixels that took extra samples, by variant */
  const extras = new Map();
  for (const m of measured) {
    if (m.error || !m.variant.edgeView) continue;
    const shown = await renderRawShader(pasteForm(m.variant.edgeView(source), { ...ADAPTIVE, ...EXTRA_SAMPLES_VIEW }), { width, height });
    if (shown.stage) throw new Error(`${m.variant.name}, edge view: ${shown.stage}: ${shown.log}`);
    extras.set(m.variant.name, countExtraSamplePixels(shown) / (width * height));
  }
  return { environment: context.environment, measured, extras, compiles: await compileTimes() };
});
const failed = results.measured.filter((m) => m.error);
if (failed.length) {
  console.error(failed.map((m) => `bench:apart: ${m.variant.name}: ${m.error}`).join('\n'));
  process.exit(1);
}
for (const m of results.measured)
  console.log(`  ${m.variant.name}: ${m.medianMs.toFixed(1)} ms, RMSE ${m.rmse.toFixed(4)}, >2/255 ${(100 * m.over2).toFixed(2)}%`);
for (const c of results.compiles) console.log(`  compile: ${c.scene}, ${c.form} form: ${c.seconds.map((x) => x.toFixed(2)).join(', ')} s`);
if (quick) {
  console.log(`\nquick run: all ${VARIANTS.length} variants compiled, rendered and measured; nothing written.`);
  process.exit(0);
}

/** One table: each row's time, its ratio to the table's first row, its error and what it shows. */
function table(name, ratioTo) {
  const rows = results.measured.filter((m) => m.variant.table === name);
  const base = rows[0].medianMs;
  return [
    `| variant | ms | × ${ratioTo} | extra samples | RMSE | >2/255 | what it shows |`,
    '|---|---|---|---|---|---|---|',
    ...rows.map(
      (m) =>
        `| ${m.variant.name} | ${m.medianMs.toFixed(1)} (${m.minMs.toFixed(1)}–${m.maxMs.toFixed(1)}) | ${(m.medianMs / base).toFixed(2)} | ${results.extras.has(m.variant.name) ? `${(100 * (results.extras.get(m.variant.name) ?? 0)).toFixed(2)}%` : ''} | ${m.rmse.toFixed(4)} | ${(100 * m.over2).toFixed(2)}% | ${m.variant.shows} |`,
    ),
  ].join('\n');
}
const frames = results.measured[0].frames;
const text = [
  `Measured by \`npm run bench:apart\` on ${rendererLabel(results.environment.renderer)}, ${results.environment.chromium}, ${width}×${height}: median (min–max) of ${frames} frames (${COPIES} compilations × ${FRAMES}), all rows of both tables interleaved in one page; error against the converged float64 reference of the row's scene (64 spp). *Extra samples*: the pixels that took them, counted on the row's "Extra samples" view.`,
  '',
  table('adaptive', '1 spp'),
  '',
  table('torus', 'cone scene'),
  '',
  `The compile before the first frame (the default view, adaptive 16; wall time of a 2×2 render, median (min–max) of ${COMPILE_ROUNDS} rounds, interleaved):`,
  '',
  '| scene | paste form s | uniform form s |',
  '|---|---|---|',
  ...[...new Set(results.compiles.map((c) => c.scene))].map((scene) => {
    const cell = (form) => {
      const c = results.compiles.find((k) => k.scene === scene && k.form === form);
      return c ? `${median(c.seconds).toFixed(2)} (${Math.min(...c.seconds).toFixed(2)}–${Math.max(...c.seconds).toFixed(2)})` : '';
    };
    return `| ${scene} | ${cell('paste')} | ${cell('uniform')} |`;
  }),
].join('\n');
// SwiftShader's tables between the apart markers, another renderer's ($SHADERPROOF_RENDERER)
// between its own (apart-llvmpipe), so that neither overwrites the other
const marker = results.environment.rendererName === 'swiftshader' ? 'apart' : `apart-${results.environment.rendererName}`;
replaceMarkedSection(path.join(REPO_ROOT, 'docs', 'benchmark.md'), marker, text);
console.log(`\n${text}\n\nwrote the tables between the ${marker} markers in docs/benchmark.md`);
