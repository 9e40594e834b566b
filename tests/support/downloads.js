// What a page downloads, caught in a folder of its own: the page tests' "Download .glsl",
// "Screenshot" and "Record" buttons.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

/**
 * Saves the page's downloads in a fresh folder; `next()` waits for the next finished file.
 * @param {import('puppeteer-core').Page} page
 */
export async function captureDownloads(page) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'raytracer-downloads-'));
  // the page's own session: the browser target's (browser().target()) was found gone once in a
  // full run ("No target with given id found"), and the Browser domain answers on a page's too
  const session = await page.createCDPSession();
  await session.send('Browser.setDownloadBehavior', { behavior: 'allow', downloadPath: dir });
  const seen = new Set();
  // Chromium may put an empty file of the final name beside the .crdownload it writes into, and
  // move the data over when done (full runs under load read such files: an "unrecognizable
  // format" recording, an empty .glsl): a file is finished when no .crdownload is left and its
  // size, not 0, holds still over two looks.
  /** @type {Map<string, number>} */
  const sizes = new Map();
  const finished = () => {
    const names = fs.readdirSync(dir);
    if (names.some((f) => f.endsWith('.crdownload'))) return [];
    return names.filter((f) => {
      if (seen.has(f)) return false;
      const size = fs.statSync(path.join(dir, f)).size;
      const still = size > 0 && sizes.get(f) === size;
      sizes.set(f, size);
      return still;
    });
  };
  return {
    /** @returns {Promise<{name: string, file: string, bytes: Uint8Array}>} */
    async next(timeoutMs = 60_000) {
      const end = Date.now() + timeoutMs;
      while (Date.now() < end) {
        const done = finished();
        if (done.length) {
          seen.add(done[0]);
          const file = path.join(dir, done[0]);
          return { name: done[0], file, bytes: new Uint8Array(fs.readFileSync(file)) };
        }
        await new Promise((r) => setTimeout(r, 50));
      }
      throw new Error(`no download arrived in ${timeoutMs} ms`);
    },
    /** Files downloaded (or under way) that next() has not handed out. */
    pending: () => fs.readdirSync(dir).filter((f) => !seen.has(f)),
    async close() {
      await session.send('Browser.setDownloadBehavior', { behavior: 'default' }).catch(() => {});
      await session.detach().catch(() => {});
      fs.rmSync(dir, { recursive: true, force: true });
    },
  };
}
