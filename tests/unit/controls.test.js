import { describe, expect, test } from 'vitest';
import fs from 'node:fs';
import { SHADER_FILE } from '../support/config.js';
import { ControlBlockError, coerceControlValue, controlApplies, controlDefaults, parseControls } from '../../src/shadertoy/controls.js';
import { linkValues, readControlChanges } from '../../src/player/app/control-values.js';

const BLOCK = `// a shader
#define HELPER 2
#ifndef HOST_CONTROLS
#define BOUNCES 3                          // ui: Bounce limit | 0 .. 4
#define SHADOWS 1                          // ui: Shadows | toggle
#define TEXTURE 0                          // ui: Ground texture | Stripes, Checkerboard
#define SAMPLES 1                          // ui: Samples per pixel | 1, 4, 9, 16
#define EXPOSURE 1.5                       // ui: Exposure
// a comment inside the block
#define NOT_A_CONTROL 7
const float CONE_HEIGHT = 1.8;             // ui: Cone height | 0.1 .. 4 step 0.01
const vec3  LIGHT_POSITION = vec3(4, 6, 3); // ui: Light position | -10 .. 10
const vec2  SPLAT = vec2(0.5);             // ui: Splat | 0 .. 1
const bool  FLAG = true;                   // ui: Flag
const int   COUNT = 2;                     // ui: Count | 0 .. 5
#endif
void mainImage(out vec4 c, in vec2 f) { c = vec4(0); }
`;

describe('parseControls', () => {
  const controls = parseControls(BLOCK);
  const byName = Object.fromEntries(controls.map((c) => [c.name, c]));

  test('finds every annotated control, in order, and nothing else', () => {
    expect(controls.map((c) => c.name)).toEqual([
      'BOUNCES',
      'SHADOWS',
      'TEXTURE',
      'SAMPLES',
      'EXPOSURE',
      'CONE_HEIGHT',
      'LIGHT_POSITION',
      'SPLAT',
      'FLAG',
      'COUNT',
    ]);
  });

  test.each([
    // name, kind, type, default, extra fields
    ['BOUNCES', 'define', 'int', 3, { label: 'Bounce limit', min: 0, max: 4, step: 1, line: 4 }],
    ['SHADOWS', 'define', 'int', 1, { label: 'Shadows', toggle: true, min: 0, max: 1, step: 1 }],
    [
      'TEXTURE',
      'define',
      'int',
      0,
      {
        options: [
          { label: 'Stripes', value: 0 },
          { label: 'Checkerboard', value: 1 },
        ],
      },
    ],
    ['SAMPLES', 'define', 'int', 1, { options: [1, 4, 9, 16].map((v) => ({ label: String(v), value: v })) }],
    ['EXPOSURE', 'define', 'float', 1.5, { label: 'Exposure' }],
    ['CONE_HEIGHT', 'uniform', 'float', 1.8, { min: 0.1, max: 4, step: 0.01, line: 11 }],
    ['LIGHT_POSITION', 'uniform', 'vec3', [4, 6, 3], { min: -10, max: 10 }],
    ['SPLAT', 'uniform', 'vec2', [0.5, 0.5], {}],
    ['FLAG', 'uniform', 'bool', true, {}],
    ['COUNT', 'uniform', 'int', 2, { step: 1 }],
  ])('%s is a %s %s with default %j', (name, kind, type, value, extra) => {
    expect(byName[name]).toMatchObject({ name, kind, type, default: value, ...extra });
  });

  test('a shader without a block has no controls', () => {
    expect(parseControls('void mainImage(out vec4 c, in vec2 f) { c = vec4(1); }')).toEqual([]);
  });

  test('nested #if inside the block does not end it', () => {
    const src = '#ifndef HOST_CONTROLS\n#if 1\n#endif\n#define A 1 // ui: A\n#endif\n#define B 2 // ui: B\n';
    expect(parseControls(src).map((c) => c.name)).toEqual(['A']);
  });

  test('controlDefaults maps names to defaults', () => {
    expect(controlDefaults(controls)).toMatchObject({ BOUNCES: 3, CONE_HEIGHT: 1.8, LIGHT_POSITION: [4, 6, 3] });
  });

  const block = (line) => `#ifndef HOST_CONTROLS\n${line}\n#endif\n`;
  test.each([
    ['unreadable control line', '#define X foo // ui: X', /cannot read control line.*shader line 2/],
    ['no label', '#define X 1 // ui:  | 0 .. 1', /no label/],
    ['empty range', '#define X 1 // ui: X | 3 .. 1', /range 3 \.\. 1 is empty/],
    ['unreadable range', '#define X 1 // ui: X | lots', /cannot read range/],
    ['wrong vector size', 'const vec3 V = vec3(1, 2); // ui: V', /needs 3 components/],
    ['vector without constructor', 'const vec3 V = 1.0; // ui: V', /must be written vec3/],
    ['bad bool', 'const bool B = 1; // ui: B', /true or false/],
    ['bad number', 'const float F = vec2(1); // ui: F', /is not a number/],
    ['declared twice', '#define X 1 // ui: X\n#define X 2 // ui: X', /declared twice.*shader line 3/],
  ])('%s is an error', (_, line, message) => {
    expect(() => parseControls(block(line))).toThrow(ControlBlockError);
    expect(() => parseControls(block(line))).toThrow(message);
  });

  test('a block without #endif is an error', () => {
    expect(() => parseControls('#ifndef HOST_CONTROLS\n#define X 1 // ui: X\n')).toThrow(/no matching #endif/);
  });
});

describe('coerceControlValue', () => {
  const byName = Object.fromEntries(parseControls(BLOCK).map((c) => [c.name, c]));
  test.each([
    ['BOUNCES', '2', 2],
    ['BOUNCES', 9, 4],
    ['BOUNCES', '-3', 0],
    ['BOUNCES', '2.6', 3],
    ['BOUNCES', 'x', undefined],
    ['BOUNCES', '', undefined],
    ['SHADOWS', '0', 0],
    ['SHADOWS', '5', 1],
    ['TEXTURE', '1', 1],
    ['TEXTURE', '7', 1],
    ['SAMPLES', '5', 4],
    ['SAMPLES', '12', 9],
    ['SAMPLES', 100, 16],
    ['EXPOSURE', '123.5', 123.5],
    ['CONE_HEIGHT', '2.5', 2.5],
    ['CONE_HEIGHT', '0', 0.1],
    ['CONE_HEIGHT', 'Infinity', undefined],
    ['LIGHT_POSITION', '1,2,3', [1, 2, 3]],
    ['LIGHT_POSITION', [20, -20, 0], [10, -10, 0]],
    ['LIGHT_POSITION', '1,2', undefined],
    ['LIGHT_POSITION', '1,,3', undefined],
    ['SPLAT', '0.25, 2', [0.25, 1]],
    ['FLAG', 'false', false],
    ['FLAG', '1', true],
    ['FLAG', 'maybe', undefined],
    ['COUNT', '3.4', 3],
  ])('%s ← %j is %j', (name, value, expected) => {
    expect(coerceControlValue(byName[name], value)).toEqual(expected);
  });
});

// Issue 18: the orbit's azimuth was clamped to ±90° (one range for both angles), so the scene
// could not be seen from behind, and its fields were "x" and "y".
describe('a vector whose components have names and ranges of their own', () => {
  const source = fs.readFileSync(SHADER_FILE, 'utf8');
  const orbit = parseControls(source).find((c) => c.name === 'CAMERA_ORBIT');

  test("the raytracer's orbit: azimuth -180 .. 180, elevation -89 .. 90", () => {
    expect(orbit.components).toEqual([
      { name: 'azimuth', min: -180, max: 180 },
      { name: 'elevation', min: -89, max: 90 },
    ]);
    expect(coerceControlValue(orbit, [170, 50]), 'from behind').toEqual([170, 50]);
    expect(coerceControlValue(orbit, '-200,-95'), 'each clamped to its own range').toEqual([-180, -89]);
  });

  test('named ranges must name every component, and each range must be a range', () => {
    const line = (spec) => `#ifndef HOST_CONTROLS\nconst vec3 P = vec3(0); // ui: P | ${spec}\n#endif\n`;
    expect(() => parseControls(line('a 0 .. 1, b 0 .. 1'))).toThrow(ControlBlockError);
    expect(() => parseControls(line('a 0 .. 1, b 2 .. 1, c 0 .. 1'))).toThrow(/empty/);
    expect(parseControls(line('a 0 .. 1, b -1 .. 1 step 0.5, c 0 .. 2'))[0].components[1]).toEqual({
      name: 'b',
      min: -1,
      max: 1,
      step: 0.5,
    });
  });
});

// Issue 24, items 8-10: a control that matters only in some scene, a component bounded by
// another, and choices given by their names.
describe('clauses: when a control matters, and one component at most another', () => {
  const source = fs.readFileSync(SHADER_FILE, 'utf8');
  const controls = parseControls(source);
  const byName = Object.fromEntries(controls.map((c) => [c.name, c]));
  const shown = (scene) => controls.filter((c) => controlApplies(c, { ...controlDefaults(controls), SCENE: scene })).map((c) => c.name);

  test.each([
    ['Cone', 0, /^CONE_/, /^(CYLINDER|TORUS)_/],
    ['Cylinder', 1, /^CYLINDER_/, /^(CONE|TORUS)_/],
    ['Torus', 2, /^TORUS_/, /^(CONE|CYLINDER)_/],
  ])("the raytracer's %s scene shows its own object's controls and no other's", (_, scene, own, others) => {
    const names = shown(scene);
    expect(names.filter((n) => own.test(n)).length).toBeGreaterThanOrEqual(3);
    expect(names.filter((n) => others.test(n))).toEqual([]);
    expect(names, 'the rest stay').toContain('SPHERE_REFLECTIVITY');
  });

  test('the torus minor radius is kept at most the major one', () => {
    expect(coerceControlValue(byName.TORUS_RADII, '0.05,2')).toEqual([0.05, 0.05]);
    expect(coerceControlValue(byName.TORUS_RADII, [1, 0.2])).toEqual([1, 0.2]);
  });

  test.each([
    ['SCENE', 'Torus', 2],
    ['SCENE', 'torus', 2],
    ['VIEW', 'NORMALS', 1],
    ['VIEW', 'Extra samples', 5],
    ['SCENE', '1', 1],
    ['SCENE', 'Teapot', undefined],
  ])('a choice by its name: %s ← %j is %j', (name, value, expected) => {
    expect(coerceControlValue(byName[name], value)).toEqual(expected);
  });

  const block = (lines) => `#ifndef HOST_CONTROLS\n${lines}\n#endif\n`;
  test.each([
    ['a when naming no control above', '#define X 1 // ui: X | 0 .. 1 | when MODE = A', /no control MODE is declared above X/],
    [
      'a when naming no such choice',
      '#define MODE 0 // ui: M | A, B\n#define X 1 // ui: X | 0 .. 1 | when MODE = C',
      /MODE has no choice C/,
    ],
    ['a bound on an unnamed component', 'const vec2 V = vec2(1); // ui: V | a 0 .. 1, b 0 .. 1 | a <= c', /c is not a named component/],
    ['an unreadable clause', '#define X 1 // ui: X | 0 .. 1 | sometimes', /cannot read "sometimes"/],
    ['a fourth part', '#define X 1 // ui: X | 0 .. 1 | when X = 1 | more', /more than three/],
  ])('%s is an error', (_, lines, message) => {
    expect(() => parseControls(block(lines))).toThrow(message);
  });
});

describe('what the page says of a value it did not use as written', () => {
  const controls = parseControls(fs.readFileSync(SHADER_FILE, 'utf8'));
  test.each([
    ['BOUNCES', '2.5', /BOUNCES=2\.5 is not a whole number: using 3\./],
    ['BOUNCES', '9', /BOUNCES=9 is out of range \(0 \.\. 4\): using 4\./],
    ['SAMPLES', '5', /SAMPLES=5 is not one of 1, 4, 9, 16: using 4\./],
    ['TORUS_RADII', '0.05,2', /TORUS_RADII=0\.05,2 has minor 2 above major 0\.05 \(minor <= major\): using 0\.05,0\.05\./],
    ['CAMERA_ORBIT', '200,0', /CAMERA_ORBIT=200,0 is out of range \(azimuth -180 \.\. 180\): using 180,0\./],
    ['SCENE', 'Teapot', /SCENE=Teapot ignored: not one of Cone, Cylinder, Torus; the shader's value 0 is used\./],
    ['BOUNCES', 'two', /BOUNCES=two ignored: not a valid int; the shader's value 3 is used\./],
  ])('%s=%s', (name, value, said) => {
    const { warnings } = readControlChanges(controls, { [name]: value }, 'URL');
    expect(warnings).toHaveLength(1);
    expect(warnings[0]).toMatch(said);
  });

  test.each([
    ['SCENE', 'Torus'],
    ['VIEW', 'normals'],
    ['BOUNCES', '2'],
  ])('%s=%s is used as written, without a word', (name, value) => {
    expect(readControlChanges(controls, { [name]: value }, 'URL').warnings).toEqual([]);
  });

  test('a link writes a choice by its name', () => {
    const values = { ...controlDefaults(controls), SCENE: 2, VIEW: 1, SAMPLES: 4 };
    expect(linkValues(controls, values)).toEqual({ SCENE: 'Torus', VIEW: 'Normals', SAMPLES: 4 });
  });
});
