// The floor under `shaderproof render`'s start, for npm run bench:cli: this Chromium launched
// headless by puppeteer-core with the command line's own flags for a renderer (argument 1:
// swiftshader, the default, or llvmpipe; src/headless/renderers.js), a blank page opened, and
// everything closed; run as a new process, as the command is.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { launchBrowser } from '../../src/headless/browser.js';
import { LLVMPIPE_ARGS, SWIFTSHADER_ARGS, findMesa, llvmpipeEnv } from '../../src/headless/renderers.js';

const renderer = process.argv[2] ?? 'swiftshader';
if (!['swiftshader', 'llvmpipe'].includes(renderer)) throw new Error(`baseline-launch.js: no floor for renderer "${renderer}"`);
const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-floor-'));
try {
  const browser =
    renderer === 'llvmpipe'
      ? await launchBrowser({ userDataDir, args: LLVMPIPE_ARGS, env: llvmpipeEnv(findMesa().vendorFile) })
      : await launchBrowser({ userDataDir, args: SWIFTSHADER_ARGS });
  const page = await browser.newPage();
  await page.goto('about:blank');
  await browser.close();
} finally {
  fs.rmSync(userDataDir, { recursive: true, force: true });
}
