// The note on what a loaded shader goes without says each thing once (issue 45, item 12): one
// missing video that three passes name was three identical lines over most of an 800x600
// canvas; it is one line that names the passes. The merging (src/shared/said-once.js sayOnce, the command line's too), case by case;
// then the page at 800x600.

import { afterAll, describe, expect, test } from 'vitest';
import { sayOnce } from '../../src/shared/said-once.js';
import { disconnect } from '../support/page.js';
import { withPage } from '../support/page-helpers.js';
import { loadNotes } from '../support/page-multipass-helpers.js';
import { hook } from '../support/hook.js';

afterAll(disconnect);

const VIDEO = "the site's video /media/a/clip.webm: a/clip.webm is not in the media folder";
const TEXTURE = "the site's texture /media/a/tex.png is not available here";

describe('sayOnce: the same thing said of several channels is one line naming them', () => {
  test.each([
    ['one line: as it is', [`Image, iChannel0: ${VIDEO}; the channel is black`], [`Image, iChannel0: ${VIDEO}; the channel is black`]],
    [
      'three passes, one channel each: the passes named once',
      [
        `Buffer A, iChannel0: ${VIDEO}; the channel is black`,
        `Buffer B, iChannel0: ${VIDEO}; the channel is black`,
        `Image, iChannel0: ${VIDEO}; the channel is black`,
      ],
      [`Buffer A, Buffer B and Image, iChannel0: ${VIDEO}; all 3 channels are black`],
    ],
    [
      'other channels: each pass with its channel',
      [`Buffer A, iChannel1: ${VIDEO}; the channel is black`, `Image, iChannel0: ${VIDEO}; the channel is black`],
      [`Buffer A's iChannel1 and Image's iChannel0: ${VIDEO}; both channels are black`],
    ],
    [
      'two things: each said once, in the order first said',
      [
        `Buffer A, iChannel0: ${VIDEO}; the channel is black`,
        `Buffer A, iChannel1: ${TEXTURE}; the channel is black`,
        `Image, iChannel0: ${VIDEO}; the channel is black`,
        `Image, iChannel1: ${TEXTURE}; the channel is black`,
      ],
      [
        `Buffer A and Image, iChannel0: ${VIDEO}; both channels are black`,
        `Buffer A and Image, iChannel1: ${TEXTURE}; both channels are black`,
      ],
    ],
    [
      "the site's own wording after the channel: kept",
      [
        'Buffer A, iChannel2: reads Buffer C, which no pass writes; the channel is black, as on the site',
        'Image, iChannel2: reads Buffer C, which no pass writes; the channel is black, as on the site',
      ],
      ['Buffer A and Image, iChannel2: reads Buffer C, which no pass writes; both channels are black, as on the site'],
    ],
    [
      'a line of no channel, and one said twice: once',
      ['iChannel0: cannot load x.png as an image; the channel is black', 'Cube A is not drawn', 'Cube A is not drawn'],
      ['iChannel0: cannot load x.png as an image; the channel is black', 'Cube A is not drawn'],
    ],
  ])('%s', (_, lines, said) => {
    expect(sayOnce(lines)).toEqual(said);
  });
});

/** A pass of a Shadertoy export whose iChannel0 is the site's video /media/a/clip.webm. */
const videoPass = (name, type, id) => ({
  inputs: [
    {
      channel: 0,
      type: 'video',
      filepath: '/media/a/clip.webm',
      previewfilepath: '/media/ap/clip.webm',
      sampler: { filter: 'linear', wrap: 'clamp', vflip: 'true', srgb: 'false', internal: 'byte' },
      published: 1,
    },
  ],
  outputs: [{ id, channel: 0 }],
  code: 'void mainImage(out vec4 c, in vec2 f) { c = vec4(f / iResolution.xy, texture(iChannel0, f / iResolution.xy).r, 1.0); }',
  name,
  description: '',
  type,
});
const THREE_PASSES = JSON.stringify({
  Shader: {
    ver: '0.1',
    info: { name: 'three' },
    renderpass: [
      videoPass('Buffer A', 'buffer', '4dXGR8'),
      videoPass('Buffer B', 'buffer', 'XsXGR8'),
      videoPass('Image', 'image', '4dfGRr'),
    ],
  },
});
/** The most of the canvas the note may cover at 800x600 (three lines of it covered 49%, 70% with a media folder given). */
const MOST_COVERED = 0.25;

describe('the page says a missing video three passes name once', () => {
  test('at 800x600: one line naming Buffer A, Buffer B and Image, over a quarter of the canvas at most', async () => {
    await withPage(
      async ({ page, goto }) => {
        await goto('?time=0&scale=0.25'); // the canvas fills the stage, at a sixteenth of its pixels
        const result = await hook(page).setProject(THREE_PASSES);
        expect(result.ok, result.error).toBe(true);
        const notes = await loadNotes(page);
        expect(notes?.lines, JSON.stringify(notes)).toHaveLength(1);
        expect(notes?.lines[0]).toMatch(
          /^Buffer A, Buffer B and Image, iChannel0: the site's video \/media\/a\/clip\.webm .*; all 3 channels are black$/,
        );
        const covered = await page.evaluate(() => {
          const note = /** @type {Element} */ (document.getElementById('load-notes')).getBoundingClientRect();
          const stage = /** @type {Element} */ (document.getElementById('stage')).getBoundingClientRect();
          return (note.width * note.height) / (stage.width * stage.height);
        });
        expect(covered, 'the share of the canvas the note covers').toBeLessThanOrEqual(MOST_COVERED);
      },
      { viewport: { width: 800, height: 600, deviceScaleFactor: 1 } },
    );
  });
});
