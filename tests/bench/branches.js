// Does this WebGL skip a branch that no pixel takes? The experiment behind the README's
// "What bounds the targets": the same 200 sin() calls, run straight, behind an `if` no pixel
// takes, and as a 200-iteration loop behind that `if`; then the project's shader with one extra
// radiance() call behind `if (iFrame < 0)`, which never runs. On a GPU the guarded versions cost
// next to nothing; on SwiftShader only the loop is skipped.
//
//   npm run bench:branches        (640x360, median of 9 interleaved frames)

import fs from 'node:fs';
import { composeImageShader } from '../../src/shadertoy.js';
import { SHADER_FILE, disconnect, startHarness, timeShaders, useHarness } from '../harness.js';

const CALLS = 200;
const straight = Array.from({ length: CALLS }, (_, i) => `    x = sin(x * 1.${i % 10} + 0.${i % 7});`).join('\n');
const image = (body) => composeImageShader(`void mainImage(out vec4 c, in vec2 f) {\n    float x = f.x * 0.001;\n${body}\n    c = vec4(x);\n}\n`).code;
const project = fs.readFileSync(SHADER_FILE, 'utf8');
const call = '            sum += radiance(s, rd, coneSpread);';
if (!project.includes(call)) throw new Error(`branches: ${SHADER_FILE} no longer has "${call.trim()}"`);

const CASES = [
  ['200 sin() calls, straight', image(straight)],
  ['the same behind if (fragCoord.x < -1.0), never taken', image(`    if (f.x < -1.0) {\n${straight}\n    }`)],
  ['a 200-iteration sin() loop behind the same if', image(`    if (f.x < -1.0) {\n        for (int i = 0; i < ${CALLS}; i++) x = sin(x * 1.1 + 0.3);\n    }`)],
  ['the project shader', composeImageShader(project).code],
  ['the project shader + radiance() behind if (iFrame < 0)', composeImageShader(project.replace(call, `${call}\n            if (iFrame < 0) sum += radiance(s, rd.zyx, coneSpread);`)).code],
];

const { context, close } = await startHarness();
useHarness(context);
try {
  const results = await timeShaders(CASES.map(([, code]) => ({ code })), { width: 640, height: 360, frames: 9, warmup: 2 });
  console.log(`640x360 on ${context.environment.renderer}, median of 9 interleaved frames:`);
  results.forEach((r, i) => {
    if (r.error) throw new Error(`${CASES[i][0]}: ${r.error}`);
    const sorted = [...r.times].sort((a, b) => a - b);
    console.log(`  ${sorted[4].toFixed(1).padStart(7)} ms  ${CASES[i][0]}`);
  });
} finally {
  await disconnect();
  await close();
}
