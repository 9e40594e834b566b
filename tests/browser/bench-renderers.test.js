// The benchmark on both CPU renderers (tests/bench/): which renderers a run measures, the results
// file keyed by renderer, the side-by-side report and its targets, the branchy forms' rewrite,
// and the timer drawing the same shaders on SwiftShader and llvmpipe in one run.
import { afterAll, describe, expect, test } from 'vitest';
import { composeImageShader } from '../../src/shadertoy/header.js';
import { disconnect, harnessContext } from '../support/page.js';
import { withRenderers, renderersAsked } from '../bench/renderer-set.js';
import { byRenderer, mergeResults } from '../bench/results-file.js';
import { benchMarkdown, comparisonTable, rendererOrder, sideBySideTable, sizesOf } from '../bench/report.js';
import {
  ONE_TRACE_SITE,
  PAGE_FORM,
  PLAIN,
  SAVINGS_OFF,
  STANDALONE,
  adaptiveSamples,
  evaluateRendererTargets,
  sceneVariant,
  sphereTracing,
  uniformSamples,
} from '../bench/targets.js';
import { timeShadersOn } from '../bench/timer.js';
import { branchyConditions } from '../bench/variant-text.js';

describe('renderersAsked', () => {
  /** @type {Array<[string, string[], Record<string, string>, string[] | RegExp]>} [case, argv, env, renderers or the error] */
  const CASES = [
    ['nothing asked: both CPU renderers', [], {}, ['swiftshader', 'llvmpipe']],
    ['--renderer llvmpipe', ['--quick', '--renderer', 'llvmpipe'], {}, ['llvmpipe']],
    ['--gpu', ['--gpu'], {}, ['gpu']],
    ['$SHADERPROOF_RENDERER', [], { SHADERPROOF_RENDERER: 'swiftshader' }, ['swiftshader']],
    ['--renderer over $SHADERPROOF_RENDERER', ['--renderer', 'llvmpipe'], { SHADERPROOF_RENDERER: 'swiftshader' }, ['llvmpipe']],
    ['an unknown name', ['--renderer', 'lavapipe'], {}, /^--renderer lavapipe: not a renderer; one of swiftshader, llvmpipe, gpu$/],
    ['an unknown name in the environment', [], { SHADERPROOF_RENDERER: 'vulkan' }, /^SHADERPROOF_RENDERER=vulkan: not a renderer/],
    ['--renderer with no name', ['--renderer', '--quick'], {}, /^--renderer: name one of/],
    ['--gpu against --renderer', ['--gpu', '--renderer', 'llvmpipe'], {}, /disagree/],
  ];
  test.each(CASES)('%s', (_, argv, env, expected) => {
    if (expected instanceof RegExp) expect(() => renderersAsked(argv, env)).toThrow(expected);
    else expect(renderersAsked(argv, env)).toEqual(expected);
  });
});

/**
 * A results entry as run.js writes it.
 * @param {string} name @param {number} medianMs
 * @param {{width?: number, group?: string, rmse?: number, over2?: number, extra?: number}} [options]
 */
const entry = (name, medianMs, { width = 640, group = 'project: samples', rmse = 0.01, over2 = 0.03, extra = undefined } = {}) => ({
  name,
  group,
  width,
  height: (width * 9) / 16,
  samplesPerPixel: 1,
  medianMs,
  minMs: medianMs * 0.9,
  maxMs: medianMs * 1.2,
  frames: 15,
  rmse,
  over2,
  ...(extra === undefined ? {} : { extraSampleFraction: extra }),
  chromium: 'Chrome/156',
  renderer: 'test renderer',
});
/** One renderer's figures for the variants the report and targets read, at 640 and 1280 wide. */
const figures = ({ one, standalone, adaptive, torus }) =>
  [640, 1280].flatMap((width) => [
    entry('empty shader (floor)', 1, { width, group: 'floor', rmse: 0.25, over2: 1 }),
    entry(uniformSamples(1), one, { width }),
    entry(uniformSamples(4), one * 4, { width, rmse: 0.008 }),
    entry(uniformSamples(9), one * 9, { width, rmse: 0.006 }),
    entry(uniformSamples(16), one * 16, { width, rmse: 0.0029 }),
    ...[4, 9, 16].map((spp) => entry(adaptiveSamples(spp), adaptive, { width, group: 'project: adaptive', rmse: 0.0033, extra: 0.035 })),
    entry(PLAIN, standalone * 1.05, { width, group: 'peer: plain analytic', rmse: 0.022 }),
    entry(STANDALONE, standalone, { width, group: 'peer: standalone plain', rmse: 0.022 }),
    entry(PAGE_FORM, one * 1.1, { width, group: 'project: page form' }),
    entry(SAVINGS_OFF, one * 2.5, { width, group: 'project: savings off' }),
    entry(ONE_TRACE_SITE, one * 1.5, { width, group: 'project: one trace site' }),
    ...[128, 256].map((steps) => entry(sphereTracing(steps), one * steps * 0.05, { width, group: 'peer: sphere tracing', rmse: 0.15 })),
    entry(sceneVariant(1), one, { width, group: 'project: other scenes' }),
    entry(sceneVariant(2), torus, { width, group: 'project: other scenes', rmse: 0.0104 }),
  ]);
const RUN = {
  started: '2026-12-06T03:00:00.000Z',
  renderers: ['swiftshader', 'llvmpipe'],
  cores: 2,
  cpu: 'a CPU',
  loadAverage: [7.1, 6.2],
  copies: 3,
  frames: 5,
  warmup: 2,
};
const RESULTS = {
  llvmpipe: { run: RUN, results: figures({ one: 6, standalone: 5, adaptive: 12, torus: 15 }) },
  swiftshader: { run: RUN, results: figures({ one: 30, standalone: 25, adaptive: 120, torus: 100 }) },
};

describe('the results file, keyed by renderer', () => {
  test('a file from before renderers were keyed is SwiftShader’s', () => {
    const list = figures({ one: 30, standalone: 25, adaptive: 120, torus: 100 });
    expect(byRenderer(list)).toEqual({ swiftshader: { run: null, results: list } });
    expect(byRenderer(RESULTS)).toBe(RESULTS);
  });

  test('a run on one renderer replaces its figures and keeps the other’s', () => {
    const again = { llvmpipe: { run: { ...RUN, renderers: ['llvmpipe'] }, results: [] } };
    const merged = mergeResults(RESULTS, again);
    expect(merged.llvmpipe).toBe(again.llvmpipe);
    expect(merged.swiftshader).toBe(RESULTS.swiftshader);
  });
});

describe('the report: both renderers side by side', () => {
  test('SwiftShader first, then llvmpipe, whatever the file’s order', () => {
    expect(rendererOrder(RESULTS)).toEqual(['swiftshader', 'llvmpipe']);
    expect(sizesOf(RESULTS)).toEqual([
      [640, 360],
      [1280, 720],
    ]);
  });

  test('a size’s table: each renderer’s median (min–max), how many times faster the second is, the error once where they agree', () => {
    const table = sideBySideTable(RESULTS, 640);
    expect(table.split('\n')[0]).toBe(
      '| variant | spp | SwiftShader ms | llvmpipe ms | faster on llvmpipe | RMSE | >2/255 | Pareto (SwiftShader, llvmpipe) |',
    );
    const row = table.split('\n').find((line) => line.startsWith(`| ${uniformSamples(1)} |`));
    expect(row).toBe(`| ${uniformSamples(1)} | 1 | 30.0 (27.0–36.0) | 6.0 (5.4–7.2) | 5.00× | 0.0100 | 3.00% | ● ● |`);
    // slower than the standalone peer at the same error: off both fronts
    expect(table.split('\n').find((line) => line.startsWith(`| ${PLAIN} |`))).toMatch(/ \| · · \|$/);
    expect(table).toContain(`| ${adaptiveSamples(16)} | 1 at edges (3.50% of pixels) |`);
    expect(table).toContain('Floor: the empty shader takes 1.0 ms on SwiftShader, 1.0 ms on llvmpipe at this size.');
  });

  test('the comparisons: the project against its peers, the torus against the cone, adaptive against 1 and uniform 16 spp', () => {
    const lines = comparisonTable(RESULTS, 640).split('\n');
    expect(lines[0]).toBe('| ratio of times | SwiftShader | llvmpipe |');
    expect(lines).toContain(
      '| the project at 1 spp, against the standalone plain peer (time) | 1.20× (30.0 / 25.0 ms) | 1.20× (6.0 / 5.0 ms) |',
    );
    expect(lines).toContain('| the torus scene, against the cone scene | 3.33× (100.0 / 30.0 ms) | 2.50× (15.0 / 6.0 ms) |');
    expect(lines).toContain('| adaptive 16 at edges, against 1 spp | 4.00× (120.0 / 30.0 ms) | 2.00× (12.0 / 6.0 ms) |');
    expect(lines).toContain('| adaptive 16 at edges, against uniform 16 spp | 0.25× (120.0 / 480.0 ms) | 0.13× (12.0 / 96.0 ms) |');
  });

  test('issue 44’s targets: met and missed by the figures', () => {
    const at640 = (results) => results.filter((r) => r.width === 640);
    expect(evaluateRendererTargets(at640(RESULTS.llvmpipe.results)).map((t) => t.met)).toEqual([false, false, false]);
    const met = figures({ one: 6, standalone: 6, adaptive: 9, torus: 9 }).filter((r) => r.width === 640);
    expect(evaluateRendererTargets(met).map((t) => t.met)).toEqual([true, true, true]);
    expect(evaluateRendererTargets(met)[0].text).toMatch(/^the project at 1 spp runs at 1\.00× the standalone plain peer's speed/);
  });

  test('the whole report names both renderers, says they ran interleaved, and has each one’s targets', () => {
    const markdown = benchMarkdown(RESULTS);
    expect(markdown).toContain('and the renderers round by round in the same run');
    expect(markdown).toContain('load average 7.1 at its start, 6.2 at its end');
    expect(markdown).toContain('### Targets on SwiftShader at 640×360');
    expect(markdown).toContain('### Targets on llvmpipe at 640×360');
    const separate = { ...RESULTS, llvmpipe: { ...RESULTS.llvmpipe, run: { ...RUN, started: '2026-12-07T00:00:00.000Z' } } };
    expect(benchMarkdown(separate)).toContain('the renderers in separate runs');
  });
});

describe('the branchy forms (bench:forms)', () => {
  test('all() and any() of a bvec become && and ||, nested ones too; other all() calls stay', () => {
    expect(branchyConditions('bool a = all(bvec3(x > 0.0, f(y, z), any(bvec2(p, !q))));')).toBe(
      'bool a = (x > 0.0 && f(y, z) && (p || !q));',
    );
    expect(branchyConditions('bool b = all(lessThan(v, w));')).toBe('bool b = all(lessThan(v, w));');
  });
});

describe('the timer on both CPU renderers', () => {
  afterAll(disconnect);

  test('the same shaders drawn and timed on SwiftShader and llvmpipe in one run, each by its own renderer', async () => {
    const shader = composeImageShader('void mainImage(out vec4 c, in vec2 f) { c = vec4(f.x / iResolution.x, 0.25, 0.75, 1.0); }\n').code;
    // the harness's own browser (SwiftShader, `on: undefined`) beside an llvmpipe one
    const drawn = await withRenderers(['llvmpipe'], async ([llvmpipe]) => ({
      names: [(await harnessContext()).environment.renderer, llvmpipe.environment.renderer],
      runs: await timeShadersOn([{ on: undefined }, llvmpipe], [{ code: shader }, { code: 'not a shader' }], {
        width: 16,
        height: 9,
        frames: 2,
        warmup: 1,
      }),
    }));
    expect(drawn.names[0]).toMatch(/SwiftShader/);
    expect(drawn.names[1]).toMatch(/llvmpipe/);
    for (const [good, bad] of drawn.runs) {
      expect(good.times).toHaveLength(2);
      expect(good.data[0]).toBe(8); // the first pixel: x = 0.5 / 16, in 8 bits
      expect(bad.error).toMatch(/^compile: /);
    }
    expect(drawn.runs[0][0].data).toEqual(drawn.runs[1][0].data);
  });
});
