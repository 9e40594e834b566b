// The harness checks itself: the deterministic injection freezes what it promises and leaves the
// animation loop running, and the page under test is the real one, drawn by SwiftShader.
import { afterAll, describe, expect, test } from 'vitest';
import { disconnect, harnessContext, openPage } from '../support/page.js';
import { CHROME_ARGS, GPU_CHROME_ARGS, rendererKind } from '../../src/headless/browser.js';

afterAll(disconnect);

async function sample(page) {
  return page.evaluate(async () => {
    const frames = [];
    await new Promise((resolve) => {
      const step = (t) => {
        frames.push([t, performance.now()]);
        if (frames.length < 4) requestAnimationFrame(step);
        else resolve();
      };
      requestAnimationFrame(step);
    });
    const d = new Date();
    return {
      random: [Math.random(), Math.random(), Math.random()],
      bytes: Array.from(crypto.getRandomValues(new Uint8Array(4))),
      now: Date.now(),
      date: d.toISOString(),
      dateString: typeof Date(),
      parsed: new Date(0).toISOString(),
      instance: d instanceof Date,
      iDate: [d.getFullYear(), d.getMonth(), d.getDate(), d.getHours() * 3600 + d.getMinutes() * 60 + d.getSeconds()],
      frames,
    };
  });
}

describe('deterministic injection', () => {
  test('two pages see the same random numbers, the same frozen date, and a running 60 Hz clock', async () => {
    const results = [];
    for (let i = 0; i < 2; i++) {
      const { page, errors } = await openPage();
      try {
        await page.goto('data:text/html,<!doctype html><title>injection</title>');
        results.push(await sample(page));
        expect(errors).toEqual([]);
      } finally {
        await page.close();
      }
    }
    const [a, b] = results;
    expect(a.random).toEqual(b.random);
    expect(new Set(a.random).size).toBe(3); // a sequence, not a constant
    expect(a.bytes).toEqual(b.bytes);
    expect(a.date).toBe('2024-01-15T12:00:00.000Z');
    expect(a.now).toBe(Date.UTC(2024, 0, 15, 12));
    expect(a.parsed).toBe('1970-01-01T00:00:00.000Z'); // dates with arguments still work
    expect(a.instance).toBe(true);
    expect(a.dateString).toBe('string');
    expect(a.iDate).toEqual([2024, 0, 15, 12 * 3600]); // the browser runs in UTC
    // rAF keeps running; its timestamps and performance.now() advance exactly one frame each.
    expect(a.frames.length).toBe(4);
    for (let i = 1; i < a.frames.length; i++) {
      expect(a.frames[i][0] - a.frames[i - 1][0]).toBeCloseTo(1000 / 60, 9);
      expect(a.frames[i][1]).toBe(a.frames[i][0]);
    }
    expect(a.frames).toEqual(b.frames);
  });
});

describe('environment', () => {
  test('the browser draws with SwiftShader WebGL2 and the page is served', async () => {
    const { environment, baseUrl } = await harnessContext();
    expect(environment.renderer).toMatch(/SwiftShader/i);
    expect(environment.webglVersion).toMatch(/WebGL 2\.0/);
    const response = await fetch(`${baseUrl}/`);
    expect(response.status).toBe(200);
    expect(await response.text()).toMatch(/<canvas/);
  });
});

describe('npm run bench -- --gpu', () => {
  test('software renderers are never taken for a hardware GPU', () => {
    for (const software of [
      'ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero) (0x0000C0DE)), SwiftShader driver)',
      'Google SwiftShader',
      'llvmpipe (LLVM 15.0.6, 256 bits)',
      'ANGLE (Mesa, llvmpipe (LLVM 15.0.6 256 bits), OpenGL 4.5)',
      'softpipe',
      'ANGLE (Microsoft, Microsoft Basic Render Driver (0x0000008C) Direct3D11 vs_5_0 ps_5_0, D3D11)',
      'Apple Software Renderer',
    ]) {
      expect(rendererKind(software), software).toBe('software');
    }
    for (const unknown of [undefined, null, '', '  ', 'WebKit WebGL']) expect(rendererKind(unknown), String(unknown)).toBe('unknown');
  });

  test('GPU renderer strings are hardware', () => {
    for (const hardware of [
      'ANGLE (NVIDIA Corporation, NVIDIA GeForce RTX 3080/PCIe/SSE2, OpenGL 4.5.0)',
      'ANGLE (NVIDIA, Vulkan 1.3.277 (NVIDIA Tesla T4 (0x00001EB8)), NVIDIA)',
      'ANGLE (Intel, Mesa Intel(R) UHD Graphics 620 (KBL GT2), OpenGL 4.6)',
      'ANGLE (AMD, AMD Radeon RX 6800 XT (radeonsi, navi21, LLVM 15.0.7, DRM 3.49, 6.1.0), OpenGL 4.6)',
      'ANGLE (Apple, ANGLE Metal Renderer: Apple M2, Unspecified Version)',
      'ANGLE (Intel, Intel(R) Iris(R) Xe Graphics (0x00009A49) Direct3D11 vs_5_0 ps_5_0, D3D11)',
    ]) {
      expect(rendererKind(hardware), hardware).toBe('hardware');
    }
  });

  test('its flags keep the harness flags but never ask for SwiftShader', () => {
    expect(GPU_CHROME_ARGS.length).toBeGreaterThan(0);
    for (const args of GPU_CHROME_ARGS) {
      expect(args.filter((arg) => /swiftshader/i.test(arg))).toEqual([]);
      expect(args).toEqual(expect.arrayContaining(CHROME_ARGS.filter((arg) => !/swiftshader/i.test(arg))));
      expect(args).toContain('--enable-gpu');
      expect(args.some((arg) => arg.startsWith('--use-angle='))).toBe(true);
    }
  });
});
