// shaderproof: the page's engine from the command line (bin/shaderproof.js). Each verb parses its
// flags (node:util parseArgs, strict: an unknown flag is a usage error), starts a session
// (session.js: the built page, a loopback server, headless Chromium on llvmpipe or SwiftShader,
// as MAIN_USAGE says) and says in one line what it made and which renderer drew it. Exit codes:
// 0 done, 1 a case or a shader failed, 2 a bad flag or value. Every error is one line in the
// project's words (a stack only with --verbose), and an output file is written whole after a
// render that succeeded, or not at all (png.js writeWhole).

import fs from 'node:fs';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { runOpen } from './open.js';
import { runRecord } from './record.js';
import { outputFormat, writeFloatImage, writeImage } from '../api/render.js';
import { drawStill, readStill } from '../api/still.js';
import { ShaderproofError, shaderKind, startSession } from '../headless/session.js';
import { LoopLimitFallback, refuseCutLoops } from '../api/loop-limit.js';
import { DEFAULT_JOBS, runTest } from '../runner/corpus.js';
import { DEFAULT_SIZE as TEST_SIZE } from '../runner/manifest.js';
import { UsageError, VIEW_FLAGS, dateLabel, readNumber, readViewOptions } from '../api/view-options.js';
import { frameProgress, io, oneShader, sayNotes, sessionOptions } from '../api/io.js';
import { argumentError, joinDashValues } from './arguments.js';
import { DEFAULT_SOUND_SECONDS, MAX_SOUND_SECONDS, SOUND_SAMPLE_RATE, renderSound, wavSummary, writeWav } from '../api/sound.js';

const NAME = 'shaderproof';

const COMMON_FLAGS = /** @type {const} */ ({
  help: { type: 'boolean', short: 'h' },
  renderer: { type: 'string' },
  gpu: { type: 'boolean' },
  watchdog: { type: 'string' },
  verbose: { type: 'boolean' },
});

const MEDIA_HELP = `  --media DIR           the site's media a Shadertoy JSON's channels name (textures, cubemaps,
                        volumes, videos, music), from DIR laid out as the site's paths:
                        DIR/a/<hash>.jpg for /media/a/<hash>.jpg; a cubemap's other faces
                        beside it as <hash>_1.jpg ... _5; a volume is the site's .bin
  --fetch-media         download what DIR (or, without --media, nothing) lacks from
                        shadertoy.com once, into a cache ($SHADERPROOF_MEDIA_CACHE, else
                        ~/.cache/shaderproof/media), read from there after; off unless given
                        ($SHADERPROOF_MEDIA_ORIGIN: a mirror instead of the site)`;

const VIEW_HELP = `  --size WxH            canvas size in pixels (default 640x360)
  --time T              iTime in seconds, paused (default 0); the still is frame 0 (iFrame 0)
  --frame N             draw frames 0..N (iTime = i/60, iFrame = i) and keep frame N
  --mouse x,y[,z,w]     iMouse in pixels, Shadertoy's signs
  --set NAME=VALUE      a control of the shader (repeatable), as the page's panel has it
  --channel0..3 FILE    an image, video or music file for iChannel0..3, by its type (a video's
                        frame and a music's spectrum are those at the frame's iTime; the
                        webcam and microphone are the page's only); a volume (the site's
                        .bin) as sampler3D; a cubemap as samplerCube: an image whose other
                        faces lie beside it as the site names them (sky_1.png ... sky_5.png)
  --date ISO|now        iDate at iTime 0 (default 2024-01-15T12:00:00Z, so that a clock draws
                        the same on every run; "now" for the real date)
${MEDIA_HELP}`;

const COMMON_HELP = `  --renderer R          what draws: llvmpipe (Mesa, on the CPU: the default where Mesa is
                        installed), swiftshader (Chromium's own, on the CPU: the default
                        elsewhere) or gpu (this machine's GPU); $SHADERPROOF_RENDERER too.
                        llvmpipe ends each pixel's loops after 65,535 trips in all: by
                        default a shader it would cut is drawn with swiftshader; asked
                        for, it fails there, and writes nothing
  --gpu                 the same as --renderer gpu
  --watchdog S          a band of a frame that costs the GPU process S seconds of CPU time
                        without ending fails (default 5 s, and for a program's first draw,
                        which compiles it, 30 s on swiftshader, 60 s on llvmpipe); a busy
                        machine or a stopped process does not count, and a frame that
                        finishes bands goes on. On a GPU, and where /proc is missing, S
                        seconds of the wall clock
  --verbose             an internal error's stack too, and the page's build log when it is
                        built first
  -h, --help            this help`;

const VERBS = {
  render: {
    summary: 'draw one still of a shader into a PNG, or its sound into a WAV',
    usage: `${NAME} render SHADER -o OUT.png [options]

Draws SHADER (a .glsl Image tab, or a Shadertoy JSON export) as the page does, and writes it.

${VIEW_HELP}
  --fps F               the frame schedule: iTimeDelta = 1/F, iFrameRate = F, and --frame N
                        at iTime N/F (default 60)
  --tile PX             draw in tiles of PX pixels (even): a still larger than the browser
                        draws at once, the same pixels as one draw where both fit
  --converge N          N progressive samples a pixel (the page's "Converge when still"), a
                        print-quality still: for a shader with a progressive form (today the
                        studio's built-in shader and its edits); another is an error
  -o, --output FILE     OUT.png, or OUT.pfm: the colours in float as the shader wrote them
                        (Portable FloatMap, unclamped), or OUT.wav: the Sound tab (mainSound)
                        as stereo 16-bit at 44100 Hz, from --time (required)
  --duration S          a .wav's length in seconds (default 60, at most 180)
  --strict              a shader that went without an input or a pass it asks for is an
                        error, and nothing is written (else a warning line for each)
${COMMON_HELP}`,
    flags: {
      ...COMMON_FLAGS,
      ...VIEW_FLAGS,
      output: { type: 'string', short: 'o' },
      strict: { type: 'boolean' },
      fps: { type: 'string' },
      converge: { type: 'string' },
      tile: { type: 'string' },
      duration: { type: 'string' },
    },
    run: runRender,
  },
  record: {
    summary: 'record frames of a shader into a WebM video or a zip of PNGs',
    usage: `${NAME} record SHADER -o OUT.webm|OUT.zip [options]

Records SHADER frame by frame as the page's Record button does: frame i has iTime = i/fps and
iFrame = i, whatever a frame costs to draw.

  --frames N            how many frames (default 60, at most 36000)
  --fps F               frames a second (default 30, at most 120)
  --size WxH            the frames' size in pixels (default 640x360)
  --mouse x,y[,z,w]     iMouse in pixels
  --set NAME=VALUE      a control of the shader (repeatable)
  --channel0..3 FILE    an image, video, music, volume (.bin) or cubemap file, as for render
  --date ISO|now        iDate at iTime 0 (default 2024-01-15T12:00:00Z; "now": the real date)
${MEDIA_HELP}
  -o, --output FILE     OUT.webm (VP9 or VP8) or OUT.zip (frame-0000.png, ...) (required)
  --strict              a shader that went without an input or a pass is an error
${COMMON_HELP}`,
    flags: {
      ...COMMON_FLAGS,
      ...VIEW_FLAGS,
      strict: { type: 'boolean' },
      frames: { type: 'string' },
      fps: { type: 'string' },
      output: { type: 'string', short: 'o' },
    },
    run: runRecord,
  },
  open: {
    summary: 'serve the page on a shader file, reloading it when the file is saved',
    usage: `${NAME} open SHADER [--port P] [--media DIR] [--fetch-media]

Serves the page on SHADER (from anywhere on disk) and prints its URL; opens no browser. Saving
the file recompiles it on every page that has it open. Ctrl-C stops. With --fetch-media,
what the shader names is downloaded when open starts (run it again for media a later save names).
It answers only requests for 127.0.0.1, localhost or [::1] on its port: another host name gets
403, so that no other site can read it by pointing its name at this machine (DNS rebinding).

  --port P              the port to listen on (default: a free one)
${MEDIA_HELP}
  --verbose             the page's build log, when it is built first
  -h, --help            this help`,
    flags: {
      help: { type: 'boolean', short: 'h' },
      verbose: { type: 'boolean' },
      port: { type: 'string' },
      media: { type: 'string' },
      'fetch-media': { type: 'boolean' },
    },
    run: runOpen,
  },
  test: {
    summary: 'render every shader of a folder and compare with its reference',
    usage: `${NAME} test DIR|CASE... [-g PATTERN] [--last-failed] [--watch] [--update] [--shard i/n] [options]

Every .glsl and .json file under DIR is a case, drawn at ${TEST_SIZE.width}x${TEST_SIZE.height} and iTime 0 (render draws
640x360) unless DIR/shaderproof.json (optional) sets its view; it sets tolerance and checks too:

  { "defaults": { "size": "640x360" },
    "cases": { "waves.glsl": { "time": 2, "set": { "SPEED": 2 },
                               "tolerance": { "threshold": 0.1, "maxDiffPixels": 0 },
                               "checks": { "deterministic": true, "halfSize": true,
                                           "maxFrameMs": 500 } } } }

A case that goes without an input it asks for fails, unless allowed:
"allowMissing": ["iChannel2", "Sound", "Image/iChannel1"].

A case whose name is no file under DIR is a view of a shader elsewhere, one of many:
"orbit": { "shader": "../scene.glsl", "mouse": [240, 120, 160, -90] }. A renderer may have
a tolerance of its own: "tolerance": { "maxDiffPixels": 50, "llvmpipe": { "maxDiffPixels": 500 } }.
"//" is a comment, in a case or at the top.

A case is drawn at 320x180 unless the manifest gives a "size". References are
DIR/__references__/<case>.png, written only by --update. A case with "sound": {"time": T,
"duration": S, "tolerance": {"rms": r, "spectrum": s}} also compares its Sound tab with
DIR/__references__/<case>.wav (RMS of the difference, and the spectrum). A failing case leaves
actual, reference and diff PNGs in the output folder, and the run its reports there; it exits 1
when a case fails. A case whose browser stops answering fails, and the run goes on in another.

What draws: --renderer R, else the renderer that drew the references (--update records it in
DIR/__references__/drawn-by.json; references written before that record are SwiftShader's).
--update, and a folder with no references yet, draw as render does.

Choosing cases: give files, sub-folders or view names of one test folder (the nearest folder
above, or the folder itself, with a shaderproof.json or __references__), and filter them:

  ${NAME} test shaders/waves.glsl shaders/sky/   a case and a sub-folder's cases, one run
  ${NAME} test tests/golden -g '^view-'          the cases whose name matches
  ${NAME} test shaders --last-failed             what failed in the last run, again
  ${NAME} test shaders --watch                   again on each save; Ctrl-C ends

  -g, --grep PATTERN    only the cases whose name (path under DIR, or view name) matches a
                        regular expression, case-insensitive (/PATTERN/ as written)
  --grep-invert PATTERN only the cases whose name does not match
  --last-failed         only the cases that failed in the last run (OUT/.last-run.json,
                        written by every run); none failed: says so and exits 0
  --watch               run, then rerun a case when its shader, its manifest entry, its
                        reference or a channel's image is saved, in the same browsers; the
                        reports follow each rerun; Ctrl-C exits 1 if a case fails, else 0
  --update              write the references (and pass): of the chosen cases only, the
                        others' files left as they are
  --shard i/n           run the i-th of n shares of the cases (1-based)
  --jobs N              cases drawn at once, each worker its own Chromium (default ${DEFAULT_JOBS} here)
  --reporter R          dot (a line a case), junit (junit.xml), html (index.html, to open in a
                        browser); repeat it or give a comma list (default: all three)
  --out DIR             output folder (default ./shaderproof-output)
  --date ISO|now        iDate at iTime 0 for cases whose manifest gives none (default
                        2024-01-15T12:00:00Z; "now" makes a clock's reference go stale)
${MEDIA_HELP}
${COMMON_HELP}`,
    flags: {
      ...COMMON_FLAGS,
      date: { type: 'string' },
      media: { type: 'string' },
      'fetch-media': { type: 'boolean' },
      update: { type: 'boolean' },
      shard: { type: 'string' },
      jobs: { type: 'string' },
      reporter: { type: 'string', multiple: true },
      out: { type: 'string' },
      grep: { type: 'string', short: 'g' },
      'grep-invert': { type: 'string' },
      'last-failed': { type: 'boolean' },
      watch: { type: 'boolean' },
    },
    run: runTest,
  },
};

const MAIN_USAGE = `${NAME}: run, render, record and test Shadertoy shaders in headless Chromium,
on the CPU (no GPU needed): llvmpipe draws where Mesa is installed, else SwiftShader; test
draws with the renderer its references were drawn with; --renderer R chooses

Usage: ${NAME} VERB [options]   (${NAME} VERB --help for each)

${Object.entries(VERBS)
  .map(([verb, { summary }]) => `  ${verb.padEnd(8)} ${summary}`)
  .join('\n')}

Chromium is found at $CHROME_PATH, else the usual system paths.`;

/** @param {{values: Record<string, any>, positionals: string[]}} args */
async function runRender({ values, positionals }) {
  const file = oneShader(positionals);
  if (!values.output) throw new UsageError('-o is required: the file to write, OUT.png, OUT.pfm or OUT.wav');
  if (/\.wav$/i.test(values.output)) return runRenderWav({ values, positionals });
  if (values.duration !== undefined) throw new UsageError('--duration: the length of a .wav; a picture is one instant (--time)');
  const format = outputFormat(values.output);
  const still = readStill(values, { float: format === 'pfm' });
  shaderKind(file); // a file that is not a shader is said before any browser starts
  const text = fs.readFileSync(file, 'utf8');
  const started = Date.now();
  const session = await startSession({ ...sessionOptions(values, 'auto'), say: io.err, progress: frameProgress() });
  try {
    const { image, floats, renderer } = await drawStill(session, file, still, {
      float: format === 'pfm',
      strict: values.strict,
      progress: true,
      say: io.err,
    });
    if (floats) writeFloatImage(values.output, floats);
    else writeImage(values.output, image);
    const date = /\biDate\b/.test(text) ? `, iDate ${dateLabel(still.view.date)}` : '';
    io.out(`${values.output}: ${image.width}x${image.height}, ${renderer}${date}, ${((Date.now() - started) / 1000).toFixed(1)} s`);
  } finally {
    await session.close();
  }
  return 0;
}

/** `render -o OUT.wav`: the Sound tab's samples from --time for --duration seconds (sound.js). */
async function runRenderWav({ values, positionals }) {
  const file = oneShader(positionals);
  for (const flag of ['frame', 'converge', 'tile'])
    if (values[flag] !== undefined)
      throw new UsageError(`--${flag}: not for a .wav, which is the Sound tab from --time for --duration seconds`);
  const view = readViewOptions(values, { width: 64, height: 36 });
  const time = view.time ?? 0;
  const duration =
    values.duration === undefined
      ? DEFAULT_SOUND_SECONDS
      : readNumber(values.duration, '--duration', { min: 1 / SOUND_SAMPLE_RATE, max: MAX_SOUND_SECONDS });
  shaderKind(file);
  const started = Date.now();
  const session = await startSession({ ...sessionOptions(values, 'auto'), say: io.err, progress: frameProgress() });
  try {
    const sound = await renderSound(session, file, view, { time, duration });
    sayNotes(file, sound.notes, { strict: values.strict });
    await refuseCutLoops(session, file);
    writeWav(values.output, sound);
    const { label: renderer } = await session.environment();
    io.out(`${values.output}: ${wavSummary(sound)}, from ${time} s, ${renderer}, ${((Date.now() - started) / 1000).toFixed(1)} s`);
  } finally {
    await session.close();
  }
  return 0;
}

/**
 * Runs the command line with `argv` (without node and the script), and returns the exit code.
 * @param {string[]} argv
 */
export async function main(argv) {
  const [verb, ...rest] = argv;
  if (!verb || verb === '--help' || verb === '-h' || verb === 'help') {
    io.out(MAIN_USAGE);
    return verb ? 0 : 2;
  }
  if (verb === '--version') {
    const pkg = JSON.parse(fs.readFileSync(path.join(import.meta.dirname, '../../package.json'), 'utf8'));
    io.out(pkg.version);
    return 0;
  }
  const spec = VERBS[/** @type {keyof typeof VERBS} */ (verb)];
  if (!spec) {
    io.err(`${NAME}: no verb "${verb}"\n\n${MAIN_USAGE}`);
    return 2;
  }
  const seeHelp = `(${NAME} ${verb} --help lists the flags)`;
  /** @type {{values: Record<string, any>, positionals: string[]}} */
  let args;
  try {
    const flags = /** @type {Record<string, {type: string}>} */ (spec.flags);
    args = parseArgs({ args: joinDashValues(rest, flags), options: /** @type {any} */ (flags), allowPositionals: true, strict: true });
  } catch (error) {
    io.err(`${NAME} ${verb}: ${argumentError(error)} ${seeHelp}`);
    return 2;
  }
  if (args.values.help) {
    io.out(spec.usage);
    return 0;
  }
  try {
    try {
      return await spec.run(/** @type {any} */ (args));
    } catch (error) {
      if (!(error instanceof LoopLimitFallback)) throw error;
      // llvmpipe, the default, would have cut a loop short: the whole verb again with SwiftShader
      io.err(`note: ${error.message}`);
      return await spec.run(/** @type {any} */ ({ ...args, values: { ...args.values, renderer: 'swiftshader' } }));
    }
  } catch (error) {
    if (error instanceof UsageError) {
      io.err(`${NAME} ${verb}: ${error.message} ${seeHelp}`);
      return 2;
    }
    if (error instanceof ShaderproofError) {
      io.err(`${NAME} ${verb}: ${error.message}`);
      return error.exitCode;
    }
    // not one of ours: still one line, and the stack for a report with --verbose
    const message = String(error?.message ?? error).split('\n')[0];
    io.err(`${NAME} ${verb}: internal error: ${message} (run again with --verbose for its stack, and report it)`);
    if (args.values.verbose) io.err(String(error?.stack ?? error));
    return 1;
  }
}
