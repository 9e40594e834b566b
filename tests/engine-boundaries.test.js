// The engine page has one client (src/engine/client.js): no other module under src/ runs code on a
// page, and the command line and the engine modules read no DOM of the page (its ids, selectors,
// data- attributes are the page's own; what they say comes back as data through the hook). These
// read the source, so that a second way in fails here rather than drifting unseen.

import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';

const ROOT = path.resolve(import.meta.dirname, '..');

/** The .js files under `folder` (relative to the repository). @param {string} folder */
function sources(folder) {
  return fs
    .readdirSync(path.join(ROOT, folder), { recursive: true, encoding: 'utf8' })
    .filter((file) => file.endsWith('.js'))
    .map((file) => path.join(folder, file).split(path.sep).join('/'))
    .sort();
}

/** A module's code without its comments (a comment may name what the code must not). @param {string} text */
const code = (text) => text.replace(/\/\*[\s\S]*?\*\//g, '').replace(/(^|[^:\\'"`])\/\/.*$/gm, '$1');

/** The modules of `files` whose code matches `pattern`. @param {string[]} files @param {RegExp} pattern */
const matching = (files, pattern) => files.filter((file) => pattern.test(code(fs.readFileSync(path.join(ROOT, file), 'utf8'))));

describe('the engine client is the one way into the page', () => {
  it.each([
    // a call of page.evaluate, evaluateOnNewDocument or evaluateHandle, on any object
    ['runs code on a page', /\.evaluate(OnNewDocument|Handle)?\s*\(/, sources('src'), ['src/engine/client.js']],
    // a DOM lookup, an id or selector of the page, or a data- attribute: what the page says comes
    // back as data (window.raytracer notes(), hang(), info()). The exceptions: client.js's
    // describePage() (what a page that does not answer was doing: it may have no hook yet) and
    // watch.js, which says what describePage() read in the page's own words; the test report's
    // HTML (html-report.js, report-page.js) is the command line's own page, not the engine's.
    [
      'reads the DOM of the page',
      /getElementById|querySelector|\.dataset\b|data-[a-z]|role=|#(load|value)-notes/,
      [...sources('src/engine'), ...sources('src/cli')].filter((file) => !/\/(html-report|report-page)\.js$/.test(file)),
      ['src/engine/client.js', 'src/engine/watch.js'],
    ],
  ])('only the client %s', (_, pattern, files, allowed) => {
    expect(matching(files, pattern)).toEqual(allowed);
  });

  it('the check finds a call when there is one', () => {
    expect(code('await page\n  .evaluate(() => 0); // page.evaluate')).toMatch(/\.evaluate(OnNewDocument|Handle)?\s*\(/);
    expect(code('// a trivial page.evaluate(() => 0)')).not.toMatch(/\.evaluate\s*\(/);
  });

  it('outside describePage, the client reads no DOM either', () => {
    const client = code(fs.readFileSync(path.join(ROOT, 'src/engine/client.js'), 'utf8'));
    const outside = client.slice(0, client.indexOf('export function describePage'));
    expect(outside).not.toMatch(/getElementById|querySelector|\.dataset\b|data-[a-z]|role=/);
  });
});

it('both pages start their app in one place (start-page.js)', () => {
  expect(matching(sources('src/page'), /RaytracerApp\.start\s*\(/)).toEqual(['src/page/start-page.js']);
});
