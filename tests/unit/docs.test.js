// The docs name files by their repository paths: each path named must exist, so that a move
// that forgets a doc fails here (docs/architecture.md draws the rooms from them).

import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';

const ROOT = path.resolve(import.meta.dirname, '..', '..');

/** Repository paths in `text`: under src/, tests/, bin/ or docs/ (a user's shaders/ is named in docs/ci.md), with a file's extension or a folder's slash. */
function namedPaths(text) {
  const found = new Set();
  for (const [, name] of text.matchAll(/(?<![\w./-])((?:src|tests|bin|docs)\/[\w./-]*[\w/])/g)) {
    if (/\.(js|ts|json|glsl|html|css|md)$/.test(name) || name.endsWith('/')) found.add(name);
  }
  return [...found];
}

/** What a run writes, named in the docs and absent on a fresh clone: the tests' output, a GPU bench's results. */
const WRITTEN_BY_RUNS = ['tests/output/', 'tests/bench/results-gpu.'];

/** The paths of `text` that do not exist. @param {string} text */
const missing = (text) =>
  namedPaths(text).filter((name) => !WRITTEN_BY_RUNS.some((folder) => name.startsWith(folder)) && !fs.existsSync(path.join(ROOT, name)));

const DOCS = [
  'README.md',
  ...fs
    .readdirSync(path.join(ROOT, 'docs'))
    .filter((name) => name.endsWith('.md'))
    .map((name) => `docs/${name}`),
];

describe('every path the docs name exists', () => {
  it.each(DOCS)('%s', (doc) => {
    const text = fs.readFileSync(path.join(ROOT, doc), 'utf8');
    expect(missing(text)).toEqual([]);
  });

  it.each(DOCS)('%s: its relative links lead to files that exist', (doc) => {
    const text = fs.readFileSync(path.join(ROOT, doc), 'utf8');
    const broken = [...text.matchAll(/\]\(([^)#\s]+)(?:#[^)]*)?\)/g)]
      .map(([, target]) => target)
      .filter((target) => !/^[a-z]+:/.test(target))
      .filter((target) => !fs.existsSync(path.join(ROOT, path.dirname(doc), target)));
    expect(broken).toEqual([]);
  });

  it('the docs name paths at all (the pattern reads them)', () => {
    expect(namedPaths(fs.readFileSync(path.join(ROOT, 'docs/architecture.md'), 'utf8')).length).toBeGreaterThan(40);
  });

  it('the check finds a path that is not there', () => {
    expect(missing('see src/player/app/app.js and src/page/app/app.js, tests/unit/')).toEqual(['src/page/app/app.js']);
  });
});

describe('the README is a front door', () => {
  const readme = fs.readFileSync(path.join(ROOT, 'README.md'), 'utf8');
  const lines = readme.split('\n');

  it('of at most 250 lines', () => {
    expect(lines.length).toBeLessThanOrEqual(250);
  });

  it('with no line over 200 characters outside a table', () => {
    expect(lines.filter((line) => !line.startsWith('|') && line.length > 200)).toEqual([]);
  });

  it("naming none of the project's issues, which its readers do not know", () => {
    expect(readme).not.toMatch(/\bissues? #?\d+/i);
  });
});
