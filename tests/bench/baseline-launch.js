// The floor under `shaderproof render`'s start, for npm run bench:cli: this Chromium launched
// headless by puppeteer-core with the command line's own flags (src/engine/browser.js), a blank
// page opened, and everything closed; run as a new process, as the command is.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { launchBrowser } from '../../src/engine/browser.js';

const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-floor-'));
try {
  const browser = await launchBrowser({ userDataDir });
  const page = await browser.newPage();
  await page.goto('about:blank');
  await browser.close();
} finally {
  fs.rmSync(userDataDir, { recursive: true, force: true });
}
