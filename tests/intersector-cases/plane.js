// The plane hard cases (see index.js for what each expectation means).

import { normalize } from '../../src/reference/vec3.js';

const plane = (name, ro, rd, expect, note, planeEq = [0, 1, 0, 0]) => ({ name, kind: 'plane', ro, rd, params: planeEq, expect, note });

export const PLANE_CASES = [
  plane('plane: parallel ray above', [0, 1, 0], [1, 0, 0], 'miss', 'dot(n, rd) = 0: a miss, never 0/0 or inf'),
  plane(
    'plane: parallel ray on the plane',
    [0, 0, 0],
    [1, 0, 0],
    'miss',
    'origin on the plane and parallel: 0/0 in the textbook form; must be a clean miss',
  ),
  plane('plane: parallel ray on the plane, -0 direction', [3, 0, -2], [-1, -0, 0], 'miss', '-0 approach is still parallel'),
  plane('plane: nearly parallel, 1e-6', [0, 1, 0], normalize([1, -1e-6, 0]), 'hit', 't = 1e6: far but finite'),
  plane(
    'plane: nearly parallel, 1e-3',
    [0, 0.001, 0],
    normalize([1, -1e-3, 0]),
    'hit',
    'the eye a millimetre above the ground, looking at the horizon',
  ),
  plane(
    'plane: camera below, looking up',
    [0, -2, 0],
    normalize([0.3, 1, 0.2]),
    'hit',
    'hit from below: the plane normal as given (the shader flips it for shading)',
  ),
  plane('plane: camera below, looking down', [0, -2, 0], normalize([0.3, -1, 0.2]), 'miss', 'plane behind the ray'),
  plane('plane: straight down from high', [0.5, 1000, 0.5], [0, -1, 0], 'hit', 'perpendicular incidence'),
];
