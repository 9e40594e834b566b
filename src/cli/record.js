// `shaderproof record SHADER -o OUT.webm|OUT.zip`: the page's recorder (src/page/io/recorder.js),
// headless: frame i at iTime = i / fps, iFrame = i, into a WebM (WebCodecs VP9 or VP8, muxed by
// mediabunny) or a zip of PNGs, with a progress bar on a terminal.

import fs from 'node:fs';
import path from 'node:path';
import { io, oneShader, watchdog } from './io.js';
import { renderShader } from './render.js';
import { shaderKind, startSession } from './session.js';
import { UsageError, readNumber, readViewOptions } from './view-options.js';

/** @param {number} done @param {number} total */
function bar(done, total) {
  const width = 30;
  const filled = total ? Math.round((done / total) * width) : 0;
  return `[${'#'.repeat(filled)}${'.'.repeat(width - filled)}] ${done}/${total} frames`;
}

/** @param {{values: Record<string, any>, positionals: string[]}} args */
export async function runRecord({ values, positionals }) {
  const file = oneShader(positionals, 'record');
  const output = values.output;
  if (!output) throw new UsageError('record: -o OUT.webm or -o OUT.zip is required');
  const format = /\.webm$/i.test(output) ? 'webm' : /\.zip$/i.test(output) ? 'png' : null;
  if (!format) throw new UsageError(`-o ${output}: a recording is a .webm video or a .zip of PNGs`);
  if (values.time !== undefined || values.frame !== undefined)
    throw new UsageError("record: --time and --frame are a render's; a recording starts at frame 0");
  const frames = values.frames === undefined ? 60 : readNumber(values.frames, '--frames', { min: 1, whole: true });
  const fps = values.fps === undefined ? 30 : readNumber(values.fps, '--fps', { min: 1 });
  const view = readViewOptions(values, { width: 640, height: 360 });
  shaderKind(file); // a file that is not a shader is said before any browser starts
  const started = Date.now();
  const session = await startSession({ gpu: values.gpu, ...watchdog(values.watchdog), say: io.err });
  try {
    await renderShader(session, file, view); // compiles it and draws its first frame (errors said as a render's)
    const page = /** @type {import('puppeteer-core').Page} */ (session.page());
    const request = { format, frames, fps, width: view.size.width, height: view.size.height };
    const recording = page.evaluate((r) => window.raytracer.record(/** @type {any} */ (r)), request);
    let shown = '';
    const ticker = setInterval(async () => {
      const { done, total } = await page.evaluate(() => window.raytracer.recording()).catch(() => ({ done: 0, total: 0 }));
      const line = bar(done, total || frames);
      if (io.isTerminal() && line !== shown) process.stderr.write(`\r${line}`);
      shown = line;
    }, 250);
    let result;
    try {
      result = await recording;
    } finally {
      clearInterval(ticker);
      if (io.isTerminal() && shown) process.stderr.write(`\r${bar(frames, frames)}\n`);
    }
    fs.mkdirSync(path.dirname(path.resolve(output)), { recursive: true });
    fs.writeFileSync(output, Buffer.from(result.data, 'base64'));
    const { label: renderer } = await session.environment();
    const what = format === 'webm' ? `${result.codec} video` : 'PNGs in a zip';
    io.out(
      `${output}: ${result.frames} frames at ${result.fps} fps, ${result.width}x${result.height}, ${what}, ${renderer}, ${((Date.now() - started) / 1000).toFixed(1)} s`,
    );
  } finally {
    await session.close();
  }
  return 0;
}
