// Injected into every test page before any of its own scripts run (page.evaluateOnNewDocument in
// tests/support/page.js). It removes every source of nondeterminism a frame could pick up, while the
// page's requestAnimationFrame loop keeps running:
//
//   Math.random, crypto.getRandomValues, crypto.randomUUID   seeded generator, same per document
//   Date (new Date(), Date(), Date.now())                     frozen at FIXED_TIME, so iDate is fixed
//   performance.now() and rAF timestamps                      a virtual clock that advances exactly
//                                                             1/60 s per animation frame, so
//                                                             iTimeDelta / iFrameRate are fixed
//
// The browser is launched with TZ=UTC, so the local-time fields of the frozen date (which
// iDate uses) are the same on every machine.
//
// This file is a plain script, not a module: the harness reads its text and injects it.
(() => {
  'use strict';

  const FIXED_TIME = Date.UTC(2024, 0, 15, 12, 0, 0); // 2024-01-15 12:00:00 UTC
  const FRAME_MS = 1000 / 60;

  // --- Math.random: mulberry32 with a fixed seed -------------------------------------------------
  let seed = 0x2f6b1c3d;
  function nextRandom() {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = seed;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  }
  Object.defineProperty(Math, 'random', { value: nextRandom, writable: true, configurable: true });

  if (globalThis.crypto) {
    const fill = function getRandomValues(array) {
      const bytes = new Uint8Array(array.buffer, array.byteOffset, array.byteLength);
      for (let i = 0; i < bytes.length; i++) bytes[i] = Math.floor(nextRandom() * 256);
      return array;
    };
    try {
      Object.defineProperty(crypto, 'getRandomValues', { value: fill, writable: true, configurable: true });
      if (typeof crypto.randomUUID === 'function') {
        const uuid = function randomUUID() {
          const b = fill(new Uint8Array(16));
          b[6] = (b[6] & 0x0f) | 0x40;
          b[8] = (b[8] & 0x3f) | 0x80;
          const h = Array.from(b, (x) => x.toString(16).padStart(2, '0')).join('');
          return `${h.slice(0, 8)}-${h.slice(8, 12)}-${h.slice(12, 16)}-${h.slice(16, 20)}-${h.slice(20)}`;
        };
        Object.defineProperty(crypto, 'randomUUID', { value: uuid, writable: true, configurable: true });
      }
    } catch {
      // crypto is not writable in this context; nothing in the page should depend on it.
    }
  }

  // --- Date: frozen ------------------------------------------------------------------------------
  const RealDate = Date;
  function FixedDate(...args) {
    // Called without `new`, Date() returns the current time as a string.
    if (!new.target) return new RealDate(FIXED_TIME).toString();
    return Reflect.construct(RealDate, args.length === 0 ? [FIXED_TIME] : args, new.target);
  }
  FixedDate.prototype = RealDate.prototype;
  Object.defineProperty(RealDate.prototype, 'constructor', { value: FixedDate, writable: true, configurable: true });
  FixedDate.now = () => FIXED_TIME;
  FixedDate.parse = RealDate.parse;
  FixedDate.UTC = RealDate.UTC;
  Object.defineProperty(FixedDate, 'name', { value: 'Date' });
  globalThis.Date = /** @type {DateConstructor} */ (FixedDate);

  // --- Clock: virtual, one 60 Hz frame per animation frame ---------------------------------------
  let virtualNow = 0;
  let lastRealFrame = -1;
  const perf = globalThis.performance;
  if (perf) Object.defineProperty(perf, 'now', { value: () => virtualNow, writable: true, configurable: true });

  if (typeof globalThis.requestAnimationFrame === 'function') {
    const realRequest = globalThis.requestAnimationFrame.bind(globalThis);
    // All callbacks of one real frame share its timestamp, so they must share the virtual one too.
    globalThis.requestAnimationFrame = function requestAnimationFrame(callback) {
      return realRequest((realTimestamp) => {
        if (realTimestamp !== lastRealFrame) {
          lastRealFrame = realTimestamp;
          virtualNow += FRAME_MS;
        }
        callback(virtualNow);
      });
    };
  }

  globalThis.__deterministic = Object.freeze({ fixedTime: FIXED_TIME, frameMs: FRAME_MS });
})();
