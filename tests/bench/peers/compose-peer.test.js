// composePeer: splicing a benchmark peer's replacement functions into shaders/raytrace.glsl.
// Plain-Node tests of the splice, then the three real peers composed with the real shader,
// compiled in Shadertoy's header and drawn in the harness's Chromium (SwiftShader).
import fs from 'node:fs';
import { afterAll, describe, expect, test } from 'vitest';
import { composeImageShader, hostControlBlock } from '../../../src/shadertoy/header.js';
import { parseControls } from '../../../src/shadertoy/controls.js';
import { SHADER_FILE } from '../../support/config.js';
import { assertNotBlank, differingPixels } from '../../support/images.js';
import { disconnect } from '../../support/page.js';
import { mapShaderLog, renderRawShader } from '../../support/raw-webgl/raw-webgl.js';
import { ComposePeerError, composePeer, replacedNames, scanTopLevel } from './compose-peer.js';

// The peers, and the project's own variants composed the same way (savings off, one trace site).
const PEERS = ['assignment', 'sdf', 'plain', 'savings-off', 'one-trace-site'];
const peerSource = (name) => fs.readFileSync(new URL(`./${name}.glsl`, import.meta.url), 'utf8');

const PROJECT = `// project
const float K = 1.0;
float a(float x) { return x + K; } // a's tail comment
/* a { brace } in a comment */
struct S { float v; };
float b(S s) {
    if (s.v > 0.0) { return a(s.v); }
    return 0.0;
}
#if FEATURE
float c(float x) { return b(S(x)); }
#endif
void mainImage(out vec4 o, in vec2 f) { o = vec4(c(f.x)); }
`;

describe('scanTopLevel', () => {
  test('finds functions, structs and other declarations, skipping comments and directives', () => {
    const items = scanTopLevel(PROJECT);
    expect(items.map((i) => [i.kind, i.name])).toEqual([
      ['other', null],
      ['function', 'a'],
      ['struct', 'S'],
      ['function', 'b'],
      ['function', 'c'],
      ['function', 'mainImage'],
    ]);
    const b = items.find((i) => i.name === 'b');
    expect(PROJECT.slice(b.start, b.end)).toMatch(/^float b\(S s\) \{[\s\S]*return 0\.0;\n\}$/);
  });

  test('a prototype is not a definition; a multi-line #define is skipped whole', () => {
    const items = scanTopLevel('float f(float x);\n#define M(x) { \\\n  x; }\nfloat f(float x) { return x; }\n');
    expect(items.map((i) => [i.kind, i.name])).toEqual([
      ['other', null],
      ['function', 'f'],
    ]);
  });

  test('unbalanced braces fail loudly', () => {
    expect(() => scanTopLevel('void f() { }\n}\n')).toThrow(ComposePeerError);
    expect(() => scanTopLevel('void f() { \n')).toThrow(/unclosed/);
  });
});

describe('composePeer', () => {
  test('replaces a listed function in place and keeps the rest of the project byte for byte', () => {
    const peer = '// @replaces b\nfloat b(S s) { return 2.0 * s.v; }\n';
    const out = composePeer(PROJECT, peer, { peerName: 'p' });
    expect(out).toContain('float b(S s) { return 2.0 * s.v; }');
    expect(out).not.toContain('return a(s.v)');
    const [before, after] = PROJECT.split(/float b\(S s\) \{[\s\S]*?return 0\.0;\n\}/);
    expect(out.startsWith(before)).toBe(true);
    expect(out.endsWith(after)).toBe(true);
    expect(out).toContain("// ---- p: replaces the project's b ----");
  });

  test('helpers land right before the replacement they precede, trailing text after the last', () => {
    const peer = [
      '// @replaces a, c',
      'const float H = 3.0;',
      'float helperA(float x) { return x * H; }',
      'float a(float x) { return helperA(x); }',
      'float helperC(float x) { return x; }',
      'float c(float x) { return helperC(x); }',
      'float tail(float x) { return x; }',
      '',
    ].join('\n');
    const out = composePeer(PROJECT, peer);
    const at = (s) => out.indexOf(s);
    expect(at('const float K')).toBeLessThan(at('const float H'));
    expect(at('const float H')).toBeLessThan(at('float helperA'));
    expect(at('float helperA')).toBeLessThan(at('float a(float x) { return helperA'));
    expect(at('float a(float x) { return helperA')).toBeLessThan(at('struct S'));
    // helperC goes inside the project's #if FEATURE, where c was
    expect(at('#if FEATURE')).toBeLessThan(at('float helperC'));
    expect(at('float c(float x) { return helperC(x); }')).toBeLessThan(at('float tail'));
    expect(at('float tail')).toBeLessThan(at('#endif'));
    expect(out).not.toContain('return x + K');
    expect(out).not.toContain('return b(S(x))');
  });

  test('replaces a struct by name', () => {
    const out = composePeer(PROJECT, '// @replaces S\nstruct S { float v; float w; };\n');
    expect(out).toContain('struct S { float v; float w; };');
    expect(out.match(/struct S/g)).toHaveLength(1);
  });

  test.each([
    ['no @replaces line', 'float a(float x) { return x; }\n', /no "\/\/ @replaces/],
    ['a name the project lacks (renamed)', '// @replaces zz\nfloat zz() { return 1.0; }\n', /zz, which the project does not define/],
    ['a listed name the peer lacks', '// @replaces a\nfloat q() { return 1.0; }\n', /lists a in @replaces but does not define it/],
    [
      'an unlisted project name',
      '// @replaces a\nfloat a(float x) { return x; }\nfloat b(S s) { return 1.0; }\n',
      /defines b, which the project also defines/,
    ],
    ['the project order broken', '// @replaces a b\nfloat b(S s) { return 1.0; }\nfloat a(float x) { return x; }\n', /defines b before a/],
    ['a name listed twice', '// @replaces a a\nfloat a(float x) { return x; }\n', /listed twice/],
    [
      'a peer definition given twice',
      '// @replaces a\nfloat a(float x) { return x; }\nfloat a(int x) { return 1.0; }\n',
      /defines a 2 times/,
    ],
    [
      'an #if spanning a replacement',
      '// @replaces a b\n#if X\nfloat a(float x) { return x; }\n#endif\nfloat b(S s) { return 1.0; }\n',
      /#if without its #endif/,
    ],
  ])('fails loudly on %s', (_, peer, message) => {
    expect(() => composePeer(PROJECT, peer)).toThrow(ComposePeerError);
    expect(() => composePeer(PROJECT, peer)).toThrow(message);
  });

  test('fails loudly on an overloaded project function', () => {
    const project = 'float f(float x) { return x; }\nfloat f(vec2 x) { return x.x; }\n';
    expect(() => composePeer(project, '// @replaces f\nfloat f(float x) { return 0.0; }\n')).toThrow(/defines f 2 times/);
  });
});

describe('the real peers with the real shader', () => {
  const project = fs.readFileSync(SHADER_FILE, 'utf8');
  const projectDefined = scanTopLevel(project)
    .filter((i) => i.kind !== 'other')
    .map((i) => i.name);

  test.each(PEERS)('%s composes: each replaced definition once, the control block untouched', (name) => {
    const peer = peerSource(name);
    const out = composePeer(project, peer, { peerName: name });
    const defined = scanTopLevel(out)
      .filter((i) => i.kind !== 'other')
      .map((i) => i.name);
    for (const replaced of replacedNames(peer))
      expect(
        defined.filter((n) => n === replaced),
        replaced,
      ).toHaveLength(1);
    // The new object's interface (placeObject, intersectObject, ...) is defined once in each of
    // the shader's #if SCENE branches; every other name once.
    const branches = new Set(projectDefined.filter((n, i) => projectDefined.indexOf(n) !== i));
    const once = defined.filter((n) => !branches.has(n));
    expect(new Set(once).size).toBe(once.length);
    for (const name of branches)
      expect(defined.filter((n) => n === name).length, name).toBe(projectDefined.filter((n) => n === name).length);
    expect(parseControls(out)).toEqual(parseControls(project));
    expect(out).toContain('void mainImage(');
  });

  test('the sdf peer takes MAX_STEPS and HIT_THRESHOLD from a prefix, with defaults', () => {
    const out = composePeer(project, peerSource('sdf'));
    expect(out).toMatch(/#ifndef MAX_STEPS\s+#define MAX_STEPS 128\s+#endif/);
    expect(out).toMatch(/#ifndef HIT_THRESHOLD\s+#define HIT_THRESHOLD 1e-4\s+#endif/);
  });
});

// ---- in the browser ------------------------------------------------------------------------
// Each variant the benchmark builds must compile in Shadertoy's header and draw a scene. The SDF
// peer at 256 steps must also draw the project's scene: below the horizon band (where sphere
// tracing runs out of steps on the grazing ground) nearly every pixel matches the project's. The
// plain analytic peer must draw the project's scene with unfiltered stripes: it differs only at
// edges (its camera's built-in sin/cos, its fixed epsilon).
describe('composed peers in WebGL2 (SwiftShader)', () => {
  afterAll(disconnect);
  const project = fs.readFileSync(SHADER_FILE, 'utf8');
  const WIDTH = 160;
  const HEIGHT = 90;

  async function render(source, hostBlock, label) {
    const { code, firstSourceLine } = composeImageShader(source, { hostBlock });
    const raw = await renderRawShader(code, { width: WIDTH, height: HEIGHT });
    if (raw.stage)
      throw new Error(`${label} fails to ${raw.stage}:\n${mapShaderLog(raw.log, { code, firstSourceLine, source, fileName: label })}`);
    expect(raw.glError, `${label}: WebGL error`).toBe(0);
    assertNotBlank(raw, label);
    return raw;
  }

  // Fraction of pixels from row `fromRow` down whose largest channel difference exceeds `levels`
  // (alpha is 1 in both: Shadertoy's main forces it).
  const differing = (a, b, levels, fromRow) => differingPixels(a, b, levels, { fromRow }).fraction;

  test("every variant compiles and draws; sdf at 256 steps and plain draw the project's scene", async () => {
    // At one sample per pixel, as the benchmark runs the peers: a peer's own radiance() does not
    // record the first path the adaptive anti-aliasing's edge tests read.
    const oneSample = project.replace(/^#define SAMPLES 16\b/m, '#define SAMPLES 1 ');
    expect(oneSample, "the project's SAMPLES default line").not.toBe(project);
    const projectImage = await render(oneSample, '', 'project');
    const assignment = composePeer(oneSample, peerSource('assignment'), { peerName: 'assignment' });
    const assignmentImage = await render(assignment, '', 'assignment');
    // Its funnel-shaped "cone" covers much of the lower half.
    expect(differing(assignmentImage, projectImage, 16, HEIGHT / 3)).toBeGreaterThan(0.05);
    const sdf = composePeer(oneSample, peerSource('sdf'), { peerName: 'sdf' });
    for (const steps of [32, 64, 128]) await render(sdf, `#define MAX_STEPS ${steps}\n`, `sdf ${steps}`);
    const sdf256 = await render(sdf, '#define MAX_STEPS 256\n', 'sdf 256');
    expect(differing(sdf256, projectImage, 16, HEIGHT / 3)).toBeLessThan(0.02);
    const unfiltered = oneSample.replace(/^#define TEXTURE_FILTER 1\b/m, '#define TEXTURE_FILTER 0');
    expect(unfiltered, "the project's TEXTURE_FILTER default line").not.toBe(oneSample);
    const unfilteredImage = await render(unfiltered, '', 'project, unfiltered stripes');
    const plain = composePeer(oneSample, peerSource('plain'), { peerName: 'plain' });
    const plainImage = await render(plain, '', 'plain');
    expect(differing(plainImage, unfilteredImage, 16, 0)).toBeLessThan(0.02);
  });

  test("the peers honour the project's compile-time controls through a host block", async () => {
    for (const name of PEERS) {
      const source = composePeer(project, peerSource(name), { peerName: name });
      const controls = parseControls(source);
      const values = { BOUNCES: 0, SHADOWS: 0, TEXTURE: 1, TEXTURE_FILTER: 0, SAMPLES: 4 };
      // A host block declares the live controls as uniforms; unset uniforms read 0, so this
      // checks compilation and a draw, not the picture.
      const { code, firstSourceLine } = composeImageShader(source, { hostBlock: hostControlBlock(controls, values) });
      const raw = await renderRawShader(code, { width: 32, height: 18 });
      if (raw.stage)
        throw new Error(
          `${name} with a host block fails to ${raw.stage}:\n${mapShaderLog(raw.log, { code, firstSourceLine, source, fileName: name })}`,
        );
      expect(raw.glError).toBe(0);
    }
  });
});
