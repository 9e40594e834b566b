// The stale-build check (src/headless/page-server.js staleSources) reads the build's own list of
// its sources, made from the page's and its workers' module graphs (vite.config.js
// pageSources), not a hand-written list of folders, which missed src/raytracer and
// src/reference (issue 39, item 3): a clone could render with a stale page.
import fs from 'node:fs';
import path from 'node:path';
import { afterEach, expect, test } from 'vitest';
import { builtPage, staleSources } from '../../src/headless/page-server.js';
import { REPO_ROOT } from '../support/config.js';

/** Files whose modification time a test moved, and the time to put back. */
const moved = [];
afterEach(() => {
  for (const [file, atime, mtime] of moved.splice(0)) fs.utimesSync(file, atime, mtime);
});

/** Makes `file` look edited after the build, until the test ends. */
function touchLater(relative) {
  const file = path.join(REPO_ROOT, relative);
  const { atime, mtime } = fs.statSync(file);
  moved.push([file, atime, mtime]);
  const later = new Date(Date.now() + 60_000);
  fs.utimesSync(file, later, later);
}

test('the build lists what the page and its workers bundle, and no file the tests write', async () => {
  const dist = await builtPage(); // the harness built dist/ for this run
  const listed = JSON.parse(fs.readFileSync(path.join(dist, 'page-sources.json'), 'utf8'));
  for (const file of [
    'src/studio/main.js',
    'src/player/gpu/render-worker.js', // the render worker's own bundle
    'src/raytracer/progressive.js',
    'src/reference/render.js', // the float64 reference's worker threads
    'src/shadertoy/header.js',
    'src/shared/canvas-limits.js',
    'shaders',
    'public',
    'vite.config.js',
  ])
    expect(listed, file).toContain(file);
  expect(listed.filter((f) => f.includes('node_modules'))).toEqual([]);
  expect(staleSources(dist)).toEqual([]);
});

// the lock files: an npm install or upgrade (three.js, say) changes what the bundles hold (issue 46)
test.each([
  ['src/reference/vec3.js'],
  ['src/raytracer/path-probe.js'],
  ['shaders/raytrace.glsl'],
  ['src/player/gpu/protocol.js'],
  ['package-lock.json'],
  ['node_modules/.package-lock.json'],
])('an edit of %s after the build makes it stale', async (file) => {
  const dist = await builtPage();
  touchLater(file);
  expect(staleSources(dist)).toContain(file.startsWith('shaders/') ? 'shaders' : file);
});

test('a file the tests write into public/ does not make the build stale', async () => {
  const dist = await builtPage();
  const written = path.join(REPO_ROOT, 'public', 'test-sources-check.glsl');
  fs.writeFileSync(written, 'void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n');
  try {
    const later = new Date(Date.now() + 60_000);
    fs.utimesSync(written, later, later);
    expect(staleSources(dist)).toEqual([]);
  } finally {
    fs.rmSync(written, { force: true });
  }
});
