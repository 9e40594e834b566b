// `shaderproof open SHADER`: the page served on a file from anywhere on disk. It prints the URL
// and opens nothing; saving the file tells every page that has it open (page-server.js's
// /__events), and the page recompiles it in place (src/studio/main.js), as `npm run dev` does for
// the shaders in this repository. Runs until Ctrl-C (or SIGTERM).

import path from 'node:path';
import { builtPage, startPageServer } from '../headless/page-server.js';
import { io, oneShader } from '../api/io.js';
import { ShaderproofError, shaderKind } from '../headless/session.js';
import { mediaFolders } from '../api/media.js';
import { readMediaOptions, readNumber } from '../api/view-options.js';

/**
 * @param {{values: Record<string, any>, positionals: string[]}} args
 * @param {{stopped?: Promise<unknown>}} [options] when to stop (default: SIGINT or SIGTERM)
 */
export async function runOpen({ values, positionals }, { stopped } = {}) {
  const file = path.resolve(oneShader(positionals));
  shaderKind(file);
  const media = readMediaOptions(values);
  const port = values.port === undefined ? 0 : readNumber(values.port, '--port', { min: 0, whole: true });
  const root = await builtPage({ say: io.err, verbose: Boolean(values.verbose) }).catch((error) => {
    throw new ShaderproofError(error.message);
  });
  const server = await startPageServer({ root, port, fileEvents: true }).catch((error) => {
    throw new ShaderproofError(
      error.code === 'EADDRINUSE' ? `--port ${port}: the port is in use; give another, or none for a free one` : error.message,
    );
  });
  const shaderUrl = server.mount(file);
  server.watch(shaderUrl);
  const folders = await mediaFolders(file, media, io.err);
  const mediaQuery = folders.length ? `&media=${server.mountFolders(folders)}` : '';
  io.out(`${server.baseUrl}/?shader=${shaderUrl.split('/').map(encodeURIComponent).join('/')}${mediaQuery}`);
  io.err(
    `serving ${file}${folders.length ? ` with the site's media from ${folders.filter((f) => typeof f === 'string').join(' and ')}` : ''}; saving it reloads it on the page. Ctrl-C stops.`,
  );
  await (stopped ??
    new Promise((resolve) => {
      process.once('SIGINT', resolve);
      process.once('SIGTERM', resolve);
    }));
  await server.close();
  return 0;
}
