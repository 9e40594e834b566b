// What `shaderproof render` costs from the command's start (issue 26: at most 3 s for a 320×180
// shader on this 2-core machine): the command run N times, each a new process as a person runs
// it, with SHADERPROOF_TIMINGS=1 so that it says when each phase ended (src/cli/session.js). Prints
// the median and range of the whole and of each phase, and writes tests/bench/cli-start.md.
// Interleaved with each run, the floor (issue 39: a render within 0.8 s of it): a new Node
// process that launches this Chromium with puppeteer-core and the command line's flags, opens a
// blank page and closes it (baseline-launch.js).
//
//   npm run bench:cli              (7 runs; -- --runs N for another count)

import { execFile } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { promisify } from 'node:util';
import { median } from '../../src/shared/stats.js';
import { REPO_ROOT } from '../harness/config.js';

const run = promisify(execFile);
const runsAt = process.argv.indexOf('--runs');
const RUNS = runsAt > 0 ? Number(process.argv[runsAt + 1]) : 7;
const BIN = path.join(REPO_ROOT, 'bin', 'shaderproof.js');
const SHADER = `void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    vec2 uv = fragCoord / iResolution.xy;
    fragColor = vec4(uv, 0.5 + 0.5 * sin(iTime + 6.0 * uv.x), 1.0);
}
`;

const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-bench-'));
const shader = path.join(dir, 'waves.glsl');
fs.writeFileSync(shader, SHADER);
const args = [BIN, 'render', shader, '-o', path.join(dir, 'out.png'), '--size', '320x180'];
// once to build the page if it is stale (a clone's first run), not timed
await run(process.execPath, args, { cwd: dir });
const samples = [];
const floors = [];
const BASELINE = path.join(REPO_ROOT, 'tests', 'bench', 'baseline-launch.js');
for (let i = 0; i < RUNS; i++) {
  const floorStarted = performance.now();
  await run(process.execPath, [BASELINE], { cwd: dir });
  floors.push(performance.now() - floorStarted);
  const started = performance.now();
  const { stderr } = await run(process.execPath, args, { cwd: dir, env: { ...process.env, SHADERPROOF_TIMINGS: '1' } });
  const wall = performance.now() - started;
  const marks = JSON.parse(/timings: (\{.*\})/.exec(stderr)?.[1] ?? 'null');
  if (!marks) throw new Error(`no timings in the command's output:\n${stderr}`);
  samples.push({ wall, marks });
}
fs.rmSync(dir, { recursive: true, force: true });

const phases = Object.keys(samples[0].marks);
const ms = (x) => String(Math.round(x));
const spread = (values) => `${ms(Math.min(...values))}–${ms(Math.max(...values))}`;
const lines = [
  `\`shaderproof render\` of a 320×180 shader, ${RUNS} runs, each a new process (${os.cpus().length} cores, ${os.cpus()[0]?.model.trim()}); written by \`npm run bench:cli\`.`,
  '',
  '| phase, up to | ends at, ms: median (min–max) | its own ms, median |',
  '|---|---:|---:|',
  ...phases.map((phase, i) => {
    const at = samples.map(({ marks }) => marks[phase]);
    // a phase's own time: its mark minus the one before (the first: from the process's start)
    const own = samples.map(({ marks }) => marks[phase] - (i ? marks[phases[i - 1]] : 0));
    return `| ${phase} | ${ms(median(at))} (${spread(at)}) | ${ms(median(own))} |`;
  }),
  `| the process's exit, as the shell sees it | ${ms(median(samples.map((s) => s.wall)))} (${spread(samples.map((s) => s.wall))}) | |`,
  '',
  `The floor, interleaved with those runs: a Node process that launches this Chromium (puppeteer-core, the same flags), opens a blank page and closes it: ${ms(median(floors))} ms (${spread(floors)}). The render costs ${ms(median(samples.map((s) => s.wall)) - median(floors))} ms over it (medians; issue 39's target: 800).`,
  '',
];
const text = lines.join('\n');
console.log(text);
fs.writeFileSync(path.join(REPO_ROOT, 'tests', 'bench', 'cli-start.md'), text);
