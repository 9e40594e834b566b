// What `shaderproof render` costs from the command's start, on each CPU renderer (the command
// line's --renderer): each run a new process, as a person runs it, with SHADERPROOF_TIMINGS=1 so
// that it says when each phase ended (src/headless/session.js).
//
// - A 320×180 start (issue 26: at most 3 s on this 2-core machine), phase by phase, beside the
//   floor (issue 39: a render within 0.8 s of it): a new Node process that launches this
//   Chromium with puppeteer-core and the renderer's flags, opens a blank page and closes it
//   (baseline-launch.js).
// - Light against heavy at 640×360 (issue 44: "a light render loses a few milliseconds of
//   compiling on llvmpipe, a heavy one gains several times"): a light shader of the kind the site
//   is full of (LIGHT below, written here) and the raytracer at its defaults.
//
// - What llvmpipe's loop guard costs (src/shadertoy/loop-guard.js: on llvmpipe a pass with loops
//   is compiled and drawn in a guarded form): the light shader (its fbm loop) and the raytracer,
//   each also drawn with the guard off (SHADERPROOF_LOOP_GUARD=off), interleaved with the rest.
//
// Every run of every shader on every renderer is interleaved with the others, so that a machine
// whose load comes and goes moves them alike. Prints and writes tests/bench/cli-start.md.
//
//   npm run bench:cli                       (7 runs of each; -- --runs N for another count)
//   npm run bench:cli -- --renderer NAME    one renderer (renderer-set.js)

import { execFile } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { promisify } from 'node:util';
import { median } from '../../src/shared/stats.js';
import { REPO_ROOT, SHADER_FILE } from '../support/config.js';
import { RENDERER_TITLES, renderersAsked } from './renderer-set.js';

const run = promisify(execFile);
const argv = process.argv.slice(2);
const runsAt = argv.indexOf('--runs');
const RUNS = runsAt >= 0 ? Number(argv[runsAt + 1]) : 7;
if (!(Number.isInteger(RUNS) && RUNS > 0)) {
  console.error(`npm run bench:cli -- --runs: expected a whole number of runs, got "${argv[runsAt + 1] ?? ''}"`);
  process.exit(1);
}
let renderers;
try {
  renderers = renderersAsked(argv).filter((name) => name !== 'gpu');
} catch (error) {
  console.error(`npm run bench:cli -- ${error.message}`);
  process.exit(1);
}
if (!renderers.length) {
  console.error('npm run bench:cli -- --renderer gpu: the start is timed on the CPU renderers only (swiftshader, llvmpipe)');
  process.exit(1);
}
const BIN = path.join(REPO_ROOT, 'bin', 'shaderproof.js');
const BASELINE = path.join(REPO_ROOT, 'tests', 'bench', 'baseline-launch.js');
// The start's shader: next to nothing to compile or draw.
const WAVES = `void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    fragColor = vec4(uv, 0.5 + 0.5 * sin(iTime + 6.0 * uv.x), 1.0);
}
`;
// A light shader as the site's light ones are: a warped plasma from a few octaves of value
// noise, a vignette and a colour ramp; compiled in a blink, drawn in a few milliseconds.
const LIGHT = `float hash(vec2 p) { return fract(sin(dot(p, vec2(127.1, 311.7))) * 43758.5453); }
float noise(vec2 p) {
    vec2 i = floor(p), f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(hash(i), hash(i + vec2(1, 0)), u.x), mix(hash(i + vec2(0, 1)), hash(i + vec2(1, 1)), u.x), u.y);
}
float fbm(vec2 p) {
    float v = 0.0, a = 0.5;
    for (int i = 0; i < 5; i++) { v += a * noise(p); p = p * 2.03 + 1.7; a *= 0.5; }
    return v;
}
void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = (2.0 * fragCoord - iResolution.xy) / iResolution.y;
    vec2 q = vec2(fbm(uv * 1.5 + 0.1 * iTime), fbm(uv * 1.5 + 3.1));
    float f = fbm(uv * 2.0 + 2.0 * q);
    vec3 col = mix(vec3(0.1, 0.2, 0.4), vec3(0.9, 0.6, 0.3), f);
    col *= 1.0 - 0.4 * dot(uv, uv) * 0.25;
    fragColor = vec4(pow(col, vec3(0.4545)), 1.0);
}
`;

const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-bench-'));
const write = (name, text) => {
  fs.writeFileSync(path.join(dir, name), text);
  return path.join(dir, name);
};
const SHADERS = [
  { key: 'start', label: 'a 320×180 start', file: write('waves.glsl', WAVES), size: '320x180' },
  { key: 'light', label: 'a light shader (warped fbm plasma), 640×360', file: write('plasma.glsl', LIGHT), size: '640x360' },
  { key: 'heavy', label: 'the raytracer at its defaults (adaptive 16), 640×360', file: SHADER_FILE, size: '640x360' },
];
const render = (shader, renderer) => [
  BIN,
  'render',
  shader.file,
  '-o',
  path.join(dir, 'out.png'),
  '--size',
  shader.size,
  '--renderer',
  renderer,
];

/** @type {Record<string, {floor: number[], [key: string]: any}>} renderer -> the floor's times and each shader's runs */
const samples = Object.fromEntries(renderers.map((r) => [r, { floor: [], ...Object.fromEntries(SHADERS.map((s) => [s.key, []])) }]));
/** The shaders with loops, drawn on llvmpipe with the loop guard off too: key -> runs. @type {Record<string, {wall: number, marks: any}[]>} */
const unguarded = { light: [], heavy: [] };
/** One timed render: its wall time and its phases' marks. */
async function timed(shader, renderer, env = {}) {
  const started = performance.now();
  const { stderr } = await run(process.execPath, render(shader, renderer), {
    cwd: dir,
    env: { ...process.env, SHADERPROOF_TIMINGS: '1', ...env },
  });
  const wall = performance.now() - started;
  const marks = JSON.parse(/timings: (\{.*\})/.exec(stderr)?.[1] ?? 'null');
  if (!marks) throw new Error(`no timings in the output of shaderproof ${render(shader, renderer).slice(1).join(' ')}:\n${stderr}`);
  return { wall, marks };
}
const loadAverage = [os.loadavg()[0]];
try {
  // once each to build the page if it is stale (a clone's first run) and warm the disk, not timed
  for (const renderer of renderers) await run(process.execPath, render(SHADERS[0], renderer), { cwd: dir });
  for (let i = 0; i < RUNS; i++) {
    for (const renderer of i % 2 ? [...renderers].reverse() : renderers) {
      const floorStarted = performance.now();
      await run(process.execPath, [BASELINE, renderer], { cwd: dir });
      samples[renderer].floor.push(performance.now() - floorStarted);
      for (const shader of SHADERS) {
        samples[renderer][shader.key].push(await timed(shader, renderer));
        if (renderer === 'llvmpipe' && shader.key in unguarded)
          unguarded[shader.key].push(await timed(shader, renderer, { SHADERPROOF_LOOP_GUARD: 'off' }));
      }
      process.stdout.write(`${i + 1}:${renderer} `);
    }
  }
  console.log('done');
} finally {
  fs.rmSync(dir, { recursive: true, force: true });
}
loadAverage.push(os.loadavg()[0]);

const ms = (x) => String(Math.round(x));
const spread = (values) => `${ms(Math.min(...values))}–${ms(Math.max(...values))}`;
const cell = (values) => `${ms(median(values))} (${spread(values)})`;
const title = (r) => RENDERER_TITLES[r];
const walls = (r, key) => samples[r][key].map((s) => s.wall);
/** A phase's own time: its mark less the one before (the first: from the process's start). */
const own = (r, key, phase) => {
  const phases = Object.keys(samples[r][key][0].marks);
  const i = phases.indexOf(phase);
  return samples[r][key].map(({ marks }) => marks[phase] - (i ? marks[phases[i - 1]] : 0));
};
const phases = Object.keys(samples[renderers[0]].start[0].marks);
const lines = [
  `\`shaderproof render\`, ${RUNS} runs of each, each a new process (${os.cpus().length} cores, ${os.cpus()[0]?.model.trim()}; load average ${loadAverage.map((l) => l.toFixed(1)).join(' at the start, ')} at the end), every shader on every renderer interleaved run by run; written by \`npm run bench:cli\`. Times in ms: median (min–max).`,
  '',
  '### A 320×180 start, phase by phase',
  '',
  `| phase, up to | ${renderers.map((r) => `${title(r)}: ends at | its own, median`).join(' | ')} |`,
  `|---|${renderers.map(() => '---:|---:|').join('')}`,
  ...phases.map(
    (phase) =>
      `| ${phase} | ${renderers.map((r) => `${cell(samples[r].start.map(({ marks }) => marks[phase]))} | ${ms(median(own(r, 'start', phase)))}`).join(' | ')} |`,
  ),
  `| the process's exit, as the shell sees it | ${renderers.map((r) => `${cell(walls(r, 'start'))} | `).join(' | ')} |`,
  '',
  `The floor, interleaved with those runs: a Node process that launches this Chromium (puppeteer-core, the renderer's flags), opens a blank page and closes it: ${renderers.map((r) => `${cell(samples[r].floor)} for ${title(r)}`).join(', ')}. The render costs ${renderers.map((r) => `${ms(median(walls(r, 'start')) - median(samples[r].floor))} ms over it on ${title(r)}`).join(', ')} (medians; issue 39's target: 800 ms).`,
  '',
  '### Light against heavy, 640×360',
  '',
  `| shader | ${renderers.map((r) => `${title(r)}: the whole command | drawing the view`).join(' | ')} |${renderers.length === 2 ? ` ${title(renderers[1])} against ${title(renderers[0])} |` : ''}`,
  `|---|${renderers.map(() => '---:|---:|').join('')}${renderers.length === 2 ? '---|' : ''}`,
  ...SHADERS.map((shader) => {
    const cells = renderers.map((r) => `${cell(walls(r, shader.key))} | ${cell(own(r, shader.key, 'view drawn'))}`);
    let versus = '';
    if (renderers.length === 2) {
      const [a, b] = renderers.map((r) => median(walls(r, shader.key)));
      const [da, db] = renderers.map((r) => median(own(r, shader.key, 'view drawn')));
      versus = ` ${b <= a ? `${ms(a - b)} ms sooner` : `${ms(b - a)} ms later`} (${(a / b).toFixed(2)}× the speed); the view ${db <= da ? `${ms(da - db)} ms sooner` : `${ms(db - da)} ms later`} (${(da / db).toFixed(2)}×) |`;
    }
    return `| ${shader.label} | ${cells.join(' | ')} |${versus}`;
  }),
  '',
  '*Drawing the view*: the phase from the page ready to the frame read back, which holds the compile of the shader and its first frame; the whole command holds the browser start and the page besides, alike for both.',
  '',
  ...(renderers.includes('llvmpipe') ? guardLines() : []),
];

/** The loop guard's section: llvmpipe with the guard against without, drawing the view. */
function guardLines() {
  const drawn = (runs) => runs.map(({ marks }) => marks['view drawn'] - marks['page loaded, first frame, WebGL2 checked']);
  return [
    "### What llvmpipe's loop guard costs",
    '',
    '| shader | drawing the view, guarded | without the guard | the guard costs |',
    '|---|---:|---:|---:|',
    ...SHADERS.filter((shader) => shader.key in unguarded).map((shader) => {
      const [on, off] = [drawn(samples.llvmpipe[shader.key]), drawn(unguarded[shader.key])];
      const cost = median(on) - median(off);
      return `| ${shader.label} | ${cell(on)} | ${cell(off)} | ${ms(cost)} ms (${((100 * cost) / median(off)).toFixed(0)}%) |`;
    }),
    '',
    'Guarded, a pass with loops compiles twice (as written, for its errors; guarded, to draw) and draws a second output; the guard is off only here (`SHADERPROOF_LOOP_GUARD=off`).',
    '',
  ];
}
const text = lines.join('\n');
console.log(text);
fs.writeFileSync(path.join(REPO_ROOT, 'tests', 'bench', 'cli-start.md'), text);
