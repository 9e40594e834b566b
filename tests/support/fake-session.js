// A session as src/headless/session.js makes one, without a browser, for the runner's tests
// (tests/unit/test-runner.test.js, tests/unit/test-select.test.js): it draws a colour from the shader's
// name, or never answers, or throws, as the name says.

import path from 'node:path';

/**
 * A session as session.js makes one, without a browser: `draw` answers with a 4×4 image whose
 * colour comes from the shader's name, except for names that say otherwise: "hang" never
 * answers (and has no page to ask), "boom" throws what is not the shader's fault (a bug),
 * "late" throws what a wait of the session's that ran out throws (src/headless/watch.js), "slow"
 * answers after 200 ms (so that workers finish out of order).
 */
export function fakeSession(rendererName = undefined) {
  const mounted = [];
  let killed = false;
  const session = {
    server: {
      mount: (file) => (mounted.push(file), `/__files/${mounted.length}/${path.basename(file)}`),
      mountText: (_text, name) => `/__files/t/${name}`,
      mountFolders: () => '/__media/0',
    },
    environment: async () => ({
      label: 'Fake renderer',
      renderer: 'Fake renderer (0x0)',
      chromium: 'Chrome/0',
      webglVersion: '',
      gpu: false,
      rendererName,
    }),
    async draw(query) {
      if (killed) throw new Error('drawn on a killed session');
      const name = decodeURIComponent(/shader=[^&]*%2F([^&%]+)|shader=[^&]*\/([^&/]+)/.exec(query)?.slice(1).find(Boolean) ?? '');
      if (name.includes('hang')) return new Promise(() => {});
      if (name.includes('boom')) throw new TypeError("Cannot read properties of undefined (reading 'trim')");
      if (name.includes('late')) throw new Error('opening a page: no answer within 120 s');
      if (name.includes('slow')) await new Promise((resolve) => setTimeout(resolve, 200));
      const shade = [...name].reduce((sum, c) => (sum * 31 + c.charCodeAt(0)) % 256, 7);
      const data = new Uint8Array(4 * 4 * 4).map((_, i) => (i % 4 === 3 ? 255 : shade));
      return { width: 4, height: 4, data, info: { controls: {} }, notes: [] };
    },
    drawFloat: async () => ({ width: 0, height: 0, data: new Float32Array() }),
    // no renderer with a loop limit: nothing is ever cut (src/api/loop-limit.js)
    loopReport: async () => null,
    client: () => null,
    takeLogged: () => [],
    async kill() {
      killed = true;
    },
    close: async () => {},
  };
  return session;
}
