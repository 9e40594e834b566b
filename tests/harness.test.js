// The harness checks itself: the deterministic injection freezes what it promises and leaves the
// animation loop running, and the page under test is the real one, drawn by SwiftShader.
import { afterAll, describe, expect, test } from 'vitest';
import { disconnect, harnessContext, openPage } from './harness.js';

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
