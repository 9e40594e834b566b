// `shaderproof record SHADER -o OUT.webm|OUT.zip`: the flags read, then the Node API's own
// recording (src/api/record.js recordFrames), written whole, and its one result line.

import { writeWhole } from '../headless/png.js';
import { shaderKind, startSession } from '../headless/session.js';
import { frameProgress, io, oneShader, sessionOptions } from '../api/io.js';
import { readRecording, recordFrames } from '../api/record.js';
import { hasSoundTab } from '../api/sound.js';
import { UsageError } from '../api/view-options.js';

/** @param {{values: Record<string, any>, positionals: string[]}} args */
export async function runRecord({ values, positionals }) {
  const file = oneShader(positionals);
  const output = values.output;
  if (!output) throw new UsageError('-o OUT.webm or -o OUT.zip is required');
  const format = /\.webm$/i.test(output) ? 'webm' : /\.zip$/i.test(output) ? 'png' : null;
  if (!format) throw new UsageError(`-o ${output}: a recording is a .webm video or a .zip of PNGs`);
  const recording = readRecording(values);
  const { frames, view } = recording;
  const fps = view.fps;
  shaderKind(file); // a file that is not a shader is said before any browser starts
  const started = Date.now();
  const session = await startSession({ ...sessionOptions(values, 'auto'), say: io.err, progress: frameProgress() });
  try {
    const result = await recordFrames(session, file, recording, { format, strict: values.strict, progress: true, say: io.err });
    writeWhole(output, result.data);
    // a WebM carries the Sound tab (the recorder's Opus track); a zip of PNGs has no place for it
    if (format === 'png' && hasSoundTab(file)) {
      const wav = output.replace(/\.zip$/i, '.wav');
      io.err(
        `warning: ${output}: ${file} has a Sound tab, and a zip of PNGs holds no sound; shaderproof render ${file} -o ${wav} --duration ${Number((frames / fps).toFixed(6))} writes it (or record -o OUT.webm, which carries it)`,
      );
    }
    const what = format === 'webm' ? `${result.codec} video${result.audio ? `, its Sound tab in ${result.audio}` : ''}` : 'PNGs in a zip';
    io.out(
      `${output}: ${result.frames} frames at ${result.fps} fps, ${result.width}x${result.height}, ${what}, ${result.renderer}, ${((Date.now() - started) / 1000).toFixed(1)} s`,
    );
  } finally {
    await session.close();
  }
  return 0;
}
