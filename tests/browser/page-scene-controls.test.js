// The panel shows the controls of the scene that is on, and the URL takes the panel's words
// (issue 24, items 8-10): a control's `| when SCENE = Torus` clause hides it in other scenes; a
// torus minor radius above the major one is said, as other values a link cannot use are; SCENE
// and VIEW are read by their names and Copy link writes the names.

import { expect, test } from 'vitest';
import { info, withPage, sharePageAcrossTests } from '../support/page-helpers.js';
import { hook } from '../support/hook.js';

// not a test of loading the page: the tests share one, brought to each view by open()
sharePageAcrossTests();

const SIZE = 'size=64x36&time=0&SAMPLES=1&BOUNCES=1';

/** The lines of the note on values not used as given (empty when there is none). */
const valueNotes = (page) => page.$$eval('#value-notes li', (items) => items.map((i) => i.textContent));

/** The names of the shader controls the panel shows (a vector: its folder's title). */
const shownControls = (page) =>
  page.evaluate(() => {
    const folder = [...document.querySelectorAll('.lil-gui .lil-gui')].find(
      (f) => f.querySelector(':scope > .lil-title')?.textContent.trim() === 'Shader controls',
    );
    const children = folder?.querySelector(':scope > .lil-children');
    return [...(children?.children ?? [])]
      .filter((e) => /** @type {HTMLElement} */ (e).checkVisibility())
      .map((e) => (e.querySelector(':scope > .lil-title') ?? e.querySelector('.lil-name'))?.textContent?.trim());
  });

test("the Torus scene's panel shows the torus's controls and no other scene's; switching scene switches them", async () => {
  await withPage(async ({ page, goto }) => {
    await goto(`?${SIZE}&SCENE=Torus&VIEW=normals`);
    expect(await valueNotes(page), 'names, in any case, are read as the panel shows them').toEqual([]);
    expect((await info(page)).controls).toMatchObject({ SCENE: 2, VIEW: 1 });
    const torus = await shownControls(page);
    expect(torus).toEqual(expect.arrayContaining(['Torus centre', 'Torus radii', 'Torus reflectivity', 'Sphere radius']));
    for (const dead of ['Cone height', 'Cone base centre', 'Cone reflectivity', 'Cylinder radius', 'Cylinder reflectivity'])
      expect(torus, `${dead} changes nothing in the Torus scene`).not.toContain(dead);

    await hook(page).setControls({ SCENE: 0 });
    await page.waitForFunction(() => window.shaderEngine.info().controls.SCENE === 0, { polling: 50 });
    const cone = await shownControls(page);
    expect(cone).toEqual(expect.arrayContaining(['Cone height', 'Cone reflectivity']));
    expect(cone).not.toContain('Torus radii');
  });
});

test('Copy link writes a choice by its name, which reads back to the same controls', async () => {
  await withPage(async ({ page, goto }) => {
    await goto(`?${SIZE}&SCENE=2&VIEW=1`);
    const url = new URL(await hook(page).shareUrl());
    expect([url.searchParams.get('SCENE'), url.searchParams.get('VIEW')]).toEqual(['Torus', 'Normals']);
  });
});

test.each([
  [
    'a minor radius above the major one',
    'SCENE=2&TORUS_RADII=0.05,2',
    /TORUS_RADII=0\.05,2 has minor 2 above major 0\.05 \(minor <= major\): using 0\.05,0\.05/,
  ],
  ['a bounce limit that is not whole', 'BOUNCES=2.5', /BOUNCES=2\.5 is not a whole number: using [23]/],
  ['a scene that is not one', 'SCENE=Teapot', /SCENE=Teapot ignored: not one of Cone, Cylinder, Torus; the shader's value 0 is used/],
])('%s is said in a note, with what was used', async (_, query, said) => {
  await withPage(async ({ page, goto }) => {
    await goto(`?size=64x36&time=0&SAMPLES=1&${query}`);
    const lines = await valueNotes(page);
    expect(
      lines.some((line) => said.test(line)),
      `a note line like ${said}; got ${JSON.stringify(lines)}`,
    ).toBe(true);
  });
});
