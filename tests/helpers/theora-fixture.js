// The Theora video the .ogv tests read (tests/fixtures/theora-colours.ogv, committed: CI installs
// no ffmpeg), what each frame holds, and the shaders that read it back. Made as the site's .ogv
// files are, Theora video (4:2:0) with Vorbis sound, by ffmpeg's libtheora and libvorbis:
//
//   node tests/helpers/theora-fixture.js     (needs ffmpeg; writes the file again from FRAMES below)
//
// Six frames at 10 fps, 40 × 48 pixels (a 48 × 48 Theora frame with a 40-wide picture inside, so
// the crop is read), a keyframe every third frame (frames 0 and 3: frames 1, 2, 4, 5 are inter
// frames, decoded from the keyframe before them). On a still background two 16 × 16 patches
// change: frame i's top patch is COLOURS[i] and its bottom patch COLOURS[(i + 3) % 6], so the
// frame, its rows' order and the colour conversion show in two texels. (A picture that changes
// whole makes libtheora code every frame as a keyframe; so does quality 10.) The sound is a
// 440 Hz sine, read by nothing (the site gives shaders a video's picture only).

import { execFileSync } from 'node:child_process';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { glslVec, input, probeCode, shaderJson } from './media-fixture.js';

export const THEORA_FILE = fileURLToPath(new URL('../fixtures/theora-colours.ogv', import.meta.url));

export const VIDEO = { width: 40, height: 48, fps: 10, frames: 6, keyframeEvery: 3 };
/** The patches: columns 16–31, rows 0–15 (top) and 32–47 (bottom). */
const PATCH = { left: 16, right: 32, top: 16, bottom: 32 };
const BACKGROUND = [60, 90, 120];
export const DURATION = VIDEO.frames / VIDEO.fps;
/** Saturated and far apart: a wrong frame or a wrong patch is off by 160 in some channel. */
const COLOURS = [
  [200, 40, 40],
  [40, 200, 40],
  [40, 40, 200],
  [200, 200, 40],
  [40, 200, 200],
  [200, 40, 200],
];
/** Frame i's colour in its top or bottom patch. */
const patchColour = (/** @type {number} */ i, /** @type {'top' | 'bottom'} */ patch) => COLOURS[patch === 'top' ? i : (i + 3) % 6];
/** Frame i's pixel (x, y), y from the top, as the fixture was made. */
export function pixelOf(/** @type {number} */ i, /** @type {number} */ x, /** @type {number} */ y) {
  if (x < PATCH.left || x >= PATCH.right) return BACKGROUND;
  if (y < PATCH.top) return patchColour(i, 'top');
  if (y >= PATCH.bottom) return patchColour(i, 'bottom');
  return BACKGROUND;
}

/**
 * How far a decoded texel may be from the colour the frame was made of, in 8-bit steps: Y'CbCr
 * bytes round each value (up to 1.6 steps in R, G or B after the conversion back) and Theora's
 * quantisation (quality 7, flat blocks) may move them by about one more (measured: 1 at most); a
 * wrong frame or a wrong patch is 160 away, the padding's grey chroma in the last column 8.
 */
export const COLOUR_TOLERANCE = 3;

/** The frame shown at iTime t (the video looped) and its iChannelTime, computed. */
export function frameAt(/** @type {number} */ t) {
  const local = t % DURATION;
  return { index: Math.floor(local * VIDEO.fps + 1e-9), local };
}

/** The texels probed, (x, y) from the file's top left: the patches' middles, and the picture's last column (its chroma the picture's own, not the frame's padding's). */
const TEXELS = [
  [24, 8],
  [24, 40],
  [VIDEO.width - 1, 24],
];
/** What a channel's probes read: the texels, then iChannelTime and iChannelResolution. */
const probes = (/** @type {number} */ channel, /** @type {boolean} */ vflip) => [
  ...TEXELS.map(([x, y]) => {
    const fromTop = (y + 0.5) / VIDEO.height;
    return `texture(iChannel${channel}, ${glslVec([(x + 0.5) / VIDEO.width, vflip ? 1 - fromTop : fromTop])})`;
  }),
  `vec4(iChannelTime[${channel}] / ${DURATION.toFixed(3)}, iChannelResolution[${channel}].xy / 255.0, 1.0)`,
];

/**
 * What one channel's four probes must show at iTime t: [RGB, tolerance, what] each.
 * @param {number} t
 * @returns {Array<[number[], number, string]>}
 */
export function expectedProbes(t) {
  const { index, local } = frameAt(t);
  return [
    ...TEXELS.map(
      ([x, y]) =>
        /** @type {[number[], number, string]} */ ([
          pixelOf(index, x, y),
          COLOUR_TOLERANCE,
          `iTime ${t}: frame ${index}'s texel (${x}, ${y})`,
        ]),
    ),
    // iChannelTime as a share of the video (1.5 steps: the byte's rounding of the share), the size exactly
    [[(local / DURATION) * 255, VIDEO.width, VIDEO.height], 1, `iTime ${t}: iChannelTime, iChannelResolution`],
  ];
}

/** A .glsl whose pixels 0–3 are the probes of iChannel0, the page's and --channel0's (vflip on). */
export const THEORA_READER = probeCode(probes(0, true));

/**
 * A Shadertoy JSON naming the video as the site's media, `/media/a/<file>`, in iChannel0 with
 * vflip (the site's default) and iChannel1 without: pixels 0–3 and 4–7.
 * @param {string} file
 */
export const theoraJson = (file) =>
  shaderJson(
    [
      input(0, 'video', `/media/a/${file}`, { filter: 'linear', vflip: true }),
      input(1, 'video', `/media/a/${file}`, { filter: 'linear', vflip: false }),
    ],
    probeCode([...probes(0, true), ...probes(1, false)]),
  );

/** Writes the fixture again with ffmpeg (libtheora, libvorbis). */
function make() {
  const { width, height, fps, frames, keyframeEvery } = VIDEO;
  const rgb = Buffer.alloc(width * height * 3 * frames);
  for (let i = 0; i < frames; i++)
    for (let y = 0; y < height; y++) for (let x = 0; x < width; x++) rgb.set(pixelOf(i, x, y), ((i * height + y) * width + x) * 3);
  // ffmpeg's own rgb24 → yuv420p conversion is BT.601 in video range, as Theora's is
  // prettier-ignore
  execFileSync('ffmpeg', [
    '-hide_banner', '-loglevel', 'error', '-y',
    '-f', 'rawvideo', '-pix_fmt', 'rgb24', '-s', `${width}x${height}`, '-r', String(fps), '-i', '-',
    '-f', 'lavfi', '-i', `sine=frequency=440:sample_rate=22050:duration=${DURATION}`,
    '-map', '0:v', '-map', '1:a', '-shortest',
    '-c:v', 'libtheora', '-pix_fmt', 'yuv420p', '-q:v', '7', '-g', String(keyframeEvery),
    '-c:a', 'libvorbis', '-q:a', '0',
    '-fflags', '+bitexact', '-flags:v', '+bitexact', '-flags:a', '+bitexact',
    THEORA_FILE,
  ], { input: rgb });
  console.log(`${path.relative(process.cwd(), THEORA_FILE)}: ${frames} frames of ${width}x${height} at ${fps} fps`);
}

if (process.argv[1] && import.meta.url === pathToFileURL(path.resolve(process.argv[1])).href) make();
