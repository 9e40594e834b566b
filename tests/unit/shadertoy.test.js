import { describe, expect, test } from 'vitest';
import { parseControls } from '../../src/shadertoy/controls.js';
import {
  HOST_CONTROLS_MACRO,
  SHADERTOY_HEADER,
  SHADERTOY_IMAGE_MAIN,
  SHADERTOY_UNIFORMS,
  composeImageShader,
  hostControlBlock,
} from '../../src/shadertoy/header.js';

const SOURCE = 'void mainImage(out vec4 c, in vec2 f) {\n    c = vec4(f / iResolution.xy, 0.0, 1.0);\n}\n';

describe('Shadertoy header and its main', () => {
  test('the header is a WebGL2 (GLSL ES 3.00) header: #version on the very first line', () => {
    expect(SHADERTOY_HEADER.startsWith('#version 300 es\n')).toBe(true);
  });

  test.each(Object.entries(SHADERTOY_UNIFORMS))('the header declares %s as %s', (name, type) => {
    const array = type.match(/^(\w+)\[(\d+)\]$/);
    const declaration = array ? `uniform ${array[1]} ${name}[${array[2]}];` : `uniform ${type} ${name};`;
    expect(SHADERTOY_HEADER.split('\n')).toContain(declaration);
  });

  test('main starts the colour at 1e20 and forces alpha to 1', () => {
    expect(SHADERTOY_IMAGE_MAIN).toMatch(/vec4 color = vec4\(1e20\);/);
    expect(SHADERTOY_IMAGE_MAIN).toMatch(/mainImage\(color, gl_FragCoord\.xy\);/);
    expect(SHADERTOY_IMAGE_MAIN).toMatch(/vec4\(color\.xyz, 1\.0\)/);
  });

  test('main follows the forward declaration of mainImage, before any user text (as the site places it)', () => {
    const { code, firstSourceLine } = composeImageShader(SOURCE);
    const lines = code.split('\n');
    const declaration = lines.indexOf('void mainImage(out vec4 c, in vec2 f);');
    const main = lines.indexOf('void main(void) {');
    expect(declaration).toBeGreaterThanOrEqual(0);
    expect(main).toBeGreaterThan(declaration);
    expect(main).toBeLessThan(firstSourceLine - 1);
  });
});

describe('composeImageShader', () => {
  const headerLines = (SHADERTOY_HEADER + SHADERTOY_IMAGE_MAIN).split('\n').length - 1;
  const hostBlock = hostControlBlock(parseControls('#ifndef HOST_CONTROLS\n#define A 1 // ui: A\nconst float B = 2.0; // ui: B\n#endif\n'));

  test.each([
    ['no host block, trailing newline', SOURCE, undefined],
    ['no host block, no trailing newline', SOURCE.trimEnd(), undefined],
    ['with a host block', SOURCE, hostBlock],
    ['empty host block', SOURCE, ''],
  ])("%s: firstSourceLine is the line of the file's first line", (_, source, block) => {
    const { code, firstSourceLine } = composeImageShader(source, block === undefined ? undefined : { hostBlock: block });
    const lines = code.split('\n');
    expect(lines[firstSourceLine - 1]).toBe(source.split('\n')[0]);
    // every line of the file follows in order
    source
      .split('\n')
      .filter(Boolean)
      .forEach((line, i) => expect(lines[firstSourceLine - 1 + i]).toBe(line));
    expect(firstSourceLine).toBe(headerLines + (block ? block.split('\n').length - 1 : 0) + 1);
    expect(code.startsWith(SHADERTOY_HEADER + SHADERTOY_IMAGE_MAIN)).toBe(true);
    expect(code.endsWith(source)).toBe(true);
  });

  test('without a host block the code is exactly header + main + file (what Shadertoy compiles)', () => {
    expect(composeImageShader(SOURCE).code).toBe(SHADERTOY_HEADER + SHADERTOY_IMAGE_MAIN + SOURCE);
  });
});

describe('hostControlBlock', () => {
  const controls = parseControls(
    '#ifndef HOST_CONTROLS\n#define BOUNCES 3 // ui: B | 0 .. 4\n#define GAIN 0.5 // ui: G\nconst vec3 L = vec3(1, 2, 3); // ui: L\nconst bool F = true; // ui: F\n#endif\n',
  );

  test.each([
    ['defaults', {}, ['#define BOUNCES 3', '#define GAIN 0.5']],
    ['overridden define', { BOUNCES: 0 }, ['#define BOUNCES 0']],
    ['boolean value', { BOUNCES: true }, ['#define BOUNCES 1']],
  ])('%s', (_, values, expectedLines) => {
    const lines = hostControlBlock(controls, values).split('\n');
    expect(lines[0]).toBe(`#define ${HOST_CONTROLS_MACRO}`);
    for (const line of expectedLines) expect(lines).toContain(line);
    expect(lines).toContain('uniform vec3 L;');
    expect(lines).toContain('uniform bool F;');
  });
});
