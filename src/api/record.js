// A recording: the page's recorder (src/player/io/recorder.js), headless: frame i at iTime =
// i / fps, iFrame = i, into a WebM (WebCodecs VP9 or VP8, muxed by mediabunny) or a zip of PNGs,
// with a progress bar on a terminal when asked. `shaderproof record` (src/cli/record.js) and the
// Node API's record() both run it.

import { runLong } from '../headless/long-work.js';
import { hungLine } from '../headless/watchdog/limits.js';
import { progressBar, sayNotes } from './io.js';
import { renderShader } from './render.js';
import { ShaderproofError } from '../headless/session.js';
import { UsageError, readNumber, readViewOptions } from './view-options.js';
import { refuseCutLoops } from './loop-limit.js';

/** The recorder's limits (src/player/io/recorder.js MAX_FRAMES, MAX_FPS): a recording past them is refused here. */
const MAX_FRAMES = 36_000;
const MAX_FPS = 120;
/** A recording's default rate. */
const RECORD_FPS = 30;

/**
 * A recording's options from parseArgs-shaped values (--frames, --fps, --size, ...), checked;
 * a UsageError says the first that cannot be.
 * @param {Record<string, any>} values
 */
export function readRecording(values) {
  if (values.time !== undefined || values.frame !== undefined)
    throw new UsageError("--time and --frame are a render's; a recording starts at frame 0");
  const frames = values.frames === undefined ? 60 : readNumber(values.frames, '--frames', { min: 1, max: MAX_FRAMES, whole: true });
  const view = readViewOptions(values, { width: 640, height: 360 }, { fps: RECORD_FPS, maxFps: MAX_FPS });
  return { frames, view };
}

/**
 * Records `frames` frames of the shader `file` on `session`, as the page's recorder does: the
 * file's bytes (a WebM, or a zip of PNGs) and what they hold, and the renderer's label. The first
 * frame is drawn as a render's (its errors and notes said alike).
 * @param {import('../headless/session.js').Session} session
 * @param {string} file
 * @param {ReturnType<typeof readRecording>} recording
 * @param {{format: 'webm' | 'png', strict?: boolean, progress?: boolean, say: (line: string) => void}} options
 */
export async function recordFrames(session, file, { frames, view }, { format, strict = false, progress = false, say }) {
  const first = await renderShader(session, file, view, { say }); // compiles it and draws its first frame
  sayNotes(file, first.notes, { strict, say });
  const client = /** @type {import('../headless/client.js').EngineClient} */ (session.client());
  const request = { format, frames, fps: view.fps, width: view.size.width, height: view.size.height };
  const bar = progressBar('frames');
  let result;
  try {
    result = await runLong(client, {
      method: 'record',
      request,
      total: frames,
      progress: progress ? bar.update : undefined,
      limits: session.limits,
      clock: session.clock(),
    });
  } catch (error) {
    const said = error.hung ? hungLine(session.limits, session.clock().measure) : error.message.split('\n')[0];
    throw Object.assign(new ShaderproofError(`${file}: ${said}`), { hung: Boolean(error.hung) });
  } finally {
    bar.end();
  }
  await refuseCutLoops(session, file);
  const { label: renderer } = await session.environment();
  return {
    data: Buffer.from(result.data, 'base64'),
    format,
    frames: result.frames,
    fps: result.fps,
    width: result.width,
    height: result.height,
    codec: result.codec ?? null,
    audio: result.audio ?? null,
    renderer,
  };
}
