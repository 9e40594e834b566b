// The command line's page server (src/headless/page-server.js: `open`, and every render session)
// answers only a request for its own host: a site whose name was pointed at 127.0.0.1 (DNS
// rebinding) gets 403 and a line that says which address to use, as Vite's dev server refuses
// one (server.allowedHosts).

import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { startPageServer } from '../../src/headless/page-server.js';

/** @type {Awaited<ReturnType<typeof startPageServer>>} */
let server;
let port = 0;
let root = '';

beforeAll(async () => {
  root = fs.mkdtempSync(path.join(os.tmpdir(), 'shaderproof-host-'));
  fs.writeFileSync(path.join(root, 'index.html'), '<!doctype html><head><meta charset="utf-8" /><title>page</title></head>\n');
  server = await startPageServer({ root, fileEvents: true });
  port = Number(new URL(server.baseUrl).port);
});

afterAll(async () => {
  await server?.close();
  fs.rmSync(root, { recursive: true, force: true });
});

/**
 * GET `pathname` from the server with the Host header `host`: its status and body.
 * @param {string} pathname
 * @param {string} host
 * @returns {Promise<{status: number, body: string}>}
 */
const get = (pathname, host) =>
  new Promise((resolve, reject) => {
    const req = http.request({ host: '127.0.0.1', port, path: pathname, headers: { host } });
    req.on('response', (res) => {
      let body = '';
      res.setEncoding('utf8');
      res.on('data', (chunk) => (body += chunk));
      res.on('end', () => resolve({ status: res.statusCode ?? 0, body }));
    });
    req.on('error', reject);
    req.end();
  });

describe('the page server answers its own host only', () => {
  test.each([['127.0.0.1'], ['localhost'], ['LOCALHOST'], ['[::1]']])('Host %s on its port is served', async (name) => {
    const { status, body } = await get('/', `${name}:${port}`);
    expect(status).toBe(200);
    expect(body).toContain('shaderproof-file-events');
  });

  test.each([
    ['another name', () => `evil.example:${port}`, '/'],
    ['another name on a mounted file', () => `evil.example:${port}`, '/__files/0/x.glsl'],
    ['another name on the file events', () => `evil.example:${port}`, '/__events'],
    ['its own name on another port', () => `127.0.0.1:${port + 1}`, '/'],
    ['its own name without the port', () => 'localhost', '/'],
  ])('%s is refused with 403 and one line naming the address to use', async (_, host, pathname) => {
    const { status, body } = await get(pathname, host());
    expect(status).toBe(403);
    expect(body.trimEnd().split('\n')).toEqual([expect.stringContaining(`open http://127.0.0.1:${port}/`)]);
  });
});
