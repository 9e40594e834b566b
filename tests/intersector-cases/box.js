// The box hard cases (see index.js for what each expectation means).

import { normalize } from '../../src/reference/vec3.js';
import { aim } from './rays.js';

const box = (name, ray, center, halfSize, expect, note) => ({ name, kind: 'box', ...ray, params: [...center, ...halfSize], expect, note });

const B = { center: [0, 0, 0], half: [1, 1, 1] };
export const BOX_CASES = [
  box(
    'box: axis ray with +0 components',
    { ro: [-5, 0.5, 0.25], rd: [1, 0, 0] },
    B.center,
    B.half,
    'hit',
    'rd.y = rd.z = +0: inside those slabs for all t',
  ),
  box(
    'box: axis ray with -0 components',
    { ro: [5, 0.5, 0.25], rd: [-1, -0, -0] },
    B.center,
    B.half,
    'hit',
    '-0 must act as 0, not as -inf slabs',
  ),
  box('box: zero component, outside that slab', { ro: [-5, 1.5, 0], rd: [1, 0, 0] }, B.center, B.half, 'miss', 'never inside the y slab'),
  box(
    'box: origin on a slab plane, zero component',
    { ro: [-5, 1, 0], rd: [1, 0, 0] },
    B.center,
    B.half,
    'hit',
    'y = 1 exactly and rd.y = 0: (1 - 1) * inf = NaN in the naive form; the ray lies in the top face plane and the closed box counts it',
  ),
  box(
    'box: ray lying in a face plane',
    { ro: [-5, 0.3, 1], rd: [1, 0, -0] },
    B.center,
    B.half,
    'hit',
    'grazes along the z = 1 face: enters through the x = -1 face at its edge',
  ),
  box(
    'box: exact edge hit',
    aim([-3, -3, 0.2], [-1, -1, 0.2]),
    B.center,
    B.half,
    'edge',
    'hits the edge x = y = -1: the normal is one face normal, unit length',
  ),
  box(
    'box: exact corner hit',
    aim([-4, -4, -4], [-1, -1, -1]),
    B.center,
    B.half,
    'edge',
    'hits the corner: one face normal, never sqrt(2) or sqrt(3) long',
  ),
  box(
    'box: origin inside',
    { ro: [0.1, -0.2, 0.3], rd: normalize([0.3, 0.5, -0.8]) },
    B.center,
    B.half,
    'hit',
    'hits the far side with the exit face normal',
  ),
  box('box: origin inside, axis ray', { ro: [0.1, -0.2, 0.3], rd: [0, 0, -1] }, B.center, B.half, 'hit', 'exit through z = -1'),
  box('box: behind the ray', { ro: [0, 0, 5], rd: [0, 0, 1] }, B.center, B.half, 'miss', 'the whole box at t < 0'),
  box('box: far, thin', aim([1e3, 2e2, -3e2], [0.49, 0.0, 0.01]), [0.5, 0, 0], [0.01, 0.5, 0.5], 'hit', 'a thin slab seen from 1e3'),
];
