// One view of the page drawn and read back: the step that every picture of this project goes
// through, the render tests' and goldens' (tests/harness/page.js renderView), the scripts' and
// the command line's (src/cli/render.js). A view is a query of the page's URL contract
// (src/shared/url-params.js: ?shader=…&size=…&time=…&NAME=value); a fresh page loads it, a page
// that is already loaded is brought to it by window.raytracer.open(), which gives what a fresh
// load gives (tests/page-open.test.js).

/**
 * What drawView found: the frame's pixels (base64 RGBA8, rows top to bottom), what the page said
 * of itself and its notes (PageNote), or `error` (why there is no frame) with `hung` when the
 * watchdog gave up on the shader (it may never finish) and `compile` when it did not compile.
 * @typedef {{pixels: {width: number, height: number, data: string}, frame: number, info: any,
 *   notes: {kind: 'missing' | 'values', title: string, lines: string[]}[], datasetError: string | undefined, error?: undefined}
 *   | {error: string, hung?: boolean, compile?: boolean}} DrawnView
 */

/**
 * A note the page shows beside the picture, a title and its lines: what a shader went without
 * (kind 'missing', the page's load-notes: media, passes), or values not used as given ('values':
 * a control clamped into range), which a person sees on the page and the command line prints.
 * @typedef {{kind: 'missing' | 'values', title: string, lines: string[]}} PageNote
 */

/**
 * Brings `page` to the view `query` and reads one frame. `fresh`: the page is loaded at
 * baseUrl + query (else it is a loaded page, and open() brings it there).
 * @param {import('puppeteer-core').Page} page
 * @param {{baseUrl: string, query: string, fresh: boolean}} view
 * @returns {Promise<DrawnView>}
 */
export async function drawView(page, { baseUrl, query, fresh }) {
  if (fresh) {
    const response = await page.goto(baseUrl + query, { waitUntil: 'load' });
    if (!response || (!response.ok() && response.status() !== 304)) return { error: `the page answered HTTP ${response?.status()}` };
    await page.waitForFunction(() => window.raytracer || document.documentElement.dataset.error, { polling: 100 });
  }
  return page.evaluate(
    async (opening) => {
      const datasetError = () => document.documentElement.dataset.error;
      if (!window.raytracer) return { error: `page error: ${datasetError()}` };
      // the watchdog's verdict (data-hung="true": a band unfinished for TIMEOUTS.hangMs) ends
      // the wait: a shader that never finishes never resolves `ready`
      let stopWatching = () => {};
      const hung = new Promise((resolve) => {
        const id = setInterval(() => {
          if (document.documentElement.dataset.hung === 'true') resolve('hung');
        }, 100);
        stopWatching = () => clearInterval(id);
      });
      try {
        const opened = opening === null ? window.raytracer.ready : window.raytracer.open(opening);
        if ((await Promise.race([opened.then(() => 'ok'), hung])) === 'hung') {
          const alert = document.querySelector('[role="alert"]')?.textContent?.trim().replace(/\s+/g, ' ');
          return {
            error: `the shader did not finish drawing a frame: the watchdog gave up on it${alert ? ` ("${alert}")` : ''}`,
            hung: true,
          };
        }
      } catch (error) {
        const report = error?.report ?? error?.message ?? String(error);
        return { error: report, compile: Boolean(error?.report) };
      } finally {
        stopWatching();
      }
      const pixels = await window.raytracer.readPixels();
      const canvas = /** @type {HTMLCanvasElement | null} */ (document.querySelector('canvas[data-frame]'));
      const frame = canvas ? Number(canvas.dataset.frame) : NaN;
      const info = window.raytracer.info();
      const notes = /** @type {const} */ ([
        ['load-notes', 'missing'],
        ['value-notes', 'values'],
      ]).flatMap(([id, kind]) => {
        const note = document.getElementById(id);
        if (!note) return [];
        const text = (/** @type {Element | null} */ element) => element?.textContent?.trim().replace(/\s+/g, ' ') ?? '';
        return [{ kind, title: text(note.querySelector('strong')), lines: [...note.querySelectorAll('li')].map(text) }];
      });
      return { pixels, frame, info: JSON.parse(JSON.stringify(info)), notes, datasetError: datasetError() };
    },
    fresh ? null : query,
  );
}
