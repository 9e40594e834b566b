// Which Chrome or Chromium the tests drive: $CHROME_PATH, else the first usual system path that
// exists. The one list of those paths, for the harness, the command line and CI:
//
//   node src/headless/chrome-path.js     prints the path and exits 0, or prints how to install
//                                         one and exits 1
//
// .ci/run calls it before `npm ci`, so this file imports nothing but Node's own modules.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const CHROME_CANDIDATES = [
  '/usr/bin/chromium',
  '/usr/bin/chromium-browser',
  '/usr/bin/google-chrome',
  '/usr/bin/google-chrome-stable',
  '/usr/lib/chromium/chromium',
  '/snap/bin/chromium',
  '/opt/google/chrome/chrome',
  '/Applications/Google Chrome.app/Contents/MacOS/Google Chrome',
  '/Applications/Chromium.app/Contents/MacOS/Chromium',
];

export const INSTALL_HINT =
  'Install one with `apt-get update && apt-get install -y chromium` (Debian/Ubuntu), or point ' +
  'CHROME_PATH at a Chrome or Chromium executable.';

/** The Chromium to test with: $CHROME_PATH, else the first candidate that exists; else it throws. */
export function findChrome(env = process.env, candidates = CHROME_CANDIDATES, exists = fs.existsSync) {
  if (env.CHROME_PATH) {
    if (!exists(env.CHROME_PATH)) throw new Error(`CHROME_PATH is ${env.CHROME_PATH}, which does not exist. ${INSTALL_HINT}`);
    return env.CHROME_PATH;
  }
  const found = candidates.find((p) => exists(p));
  if (!found) throw new Error(`No Chrome or Chromium found (looked in ${candidates.join(', ')}). ${INSTALL_HINT}`);
  return found;
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  try {
    console.log(findChrome());
  } catch (error) {
    console.error(error.message);
    process.exit(1);
  }
}
