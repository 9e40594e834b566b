// `shaderproof record SHADER -o OUT.webm|OUT.zip`: the page's recorder (src/player/io/recorder.js),
// headless: frame i at iTime = i / fps, iFrame = i, into a WebM (WebCodecs VP9 or VP8, muxed by
// mediabunny) or a zip of PNGs, with a progress bar on a terminal.

import { runLong } from '../headless/long-work.js';
import { hungLine } from '../headless/watchdog/limits.js';
import { writeWhole } from '../headless/png.js';
import { frameProgress, io, oneShader, progressBar, sayNotes, sessionOptions } from './io.js';
import { renderShader } from './render.js';
import { CliError, shaderKind, startSession } from '../headless/session.js';
import { UsageError, readNumber, readViewOptions } from './view-options.js';
import { hasSoundTab } from './sound.js';
import { refuseCutLoops } from './loop-limit.js';

/** The recorder's limits (src/player/io/recorder.js MAX_FRAMES, MAX_FPS): a recording past them is refused here. */
const MAX_FRAMES = 36_000;
const MAX_FPS = 120;
/** A recording's default rate. */
const RECORD_FPS = 30;

/** @param {{values: Record<string, any>, positionals: string[]}} args */
export async function runRecord({ values, positionals }) {
  const file = oneShader(positionals);
  const output = values.output;
  if (!output) throw new UsageError('-o OUT.webm or -o OUT.zip is required');
  const format = /\.webm$/i.test(output) ? 'webm' : /\.zip$/i.test(output) ? 'png' : null;
  if (!format) throw new UsageError(`-o ${output}: a recording is a .webm video or a .zip of PNGs`);
  if (values.time !== undefined || values.frame !== undefined)
    throw new UsageError("--time and --frame are a render's; a recording starts at frame 0");
  const frames = values.frames === undefined ? 60 : readNumber(values.frames, '--frames', { min: 1, max: MAX_FRAMES, whole: true });
  const view = readViewOptions(values, { width: 640, height: 360 }, { fps: RECORD_FPS, maxFps: MAX_FPS });
  const fps = view.fps;
  shaderKind(file); // a file that is not a shader is said before any browser starts
  const started = Date.now();
  const session = await startSession({ ...sessionOptions(values, 'auto'), say: io.err, progress: frameProgress() });
  try {
    const first = await renderShader(session, file, view); // compiles it and draws its first frame (errors said as a render's)
    sayNotes(file, first.notes, { strict: values.strict });
    const client = /** @type {import('../headless/client.js').EngineClient} */ (session.client());
    const request = { format, frames, fps, width: view.size.width, height: view.size.height };
    const bar = progressBar('frames');
    let result;
    try {
      result = await runLong(client, {
        method: 'record',
        request,
        total: frames,
        progress: bar.update,
        limits: session.limits,
        clock: session.clock(),
      });
    } catch (error) {
      const said = error.hung ? hungLine(session.limits, session.clock().measure) : error.message.split('\n')[0];
      throw Object.assign(new CliError(`${file}: ${said}`), { hung: Boolean(error.hung) });
    } finally {
      bar.end();
    }
    await refuseCutLoops(session, file);
    writeWhole(output, Buffer.from(result.data, 'base64'));
    // a WebM carries the Sound tab (the recorder's Opus track); a zip of PNGs has no place for it
    if (format === 'png' && hasSoundTab(file)) {
      const wav = output.replace(/\.zip$/i, '.wav');
      io.err(
        `warning: ${output}: ${file} has a Sound tab, and a zip of PNGs holds no sound; shaderproof render ${file} -o ${wav} --duration ${Number((frames / fps).toFixed(6))} writes it (or record -o OUT.webm, which carries it)`,
      );
    }
    const { label: renderer } = await session.environment();
    const what = format === 'webm' ? `${result.codec} video${result.audio ? `, its Sound tab in ${result.audio}` : ''}` : 'PNGs in a zip';
    io.out(
      `${output}: ${result.frames} frames at ${result.fps} fps, ${result.width}x${result.height}, ${what}, ${renderer}, ${((Date.now() - started) / 1000).toFixed(1)} s`,
    );
  } finally {
    await session.close();
  }
  return 0;
}
