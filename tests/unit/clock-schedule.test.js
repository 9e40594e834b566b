// The page's clock under a fixed schedule (ShadertoyInputs.setSchedule: ?date=, ?fps=, the command
// line's defaults), without a browser: nothing the page measures reaches a frame's inputs.
import { describe, expect, test } from 'vitest';
import { ShadertoyInputs, shadertoyDate } from '../../src/player/app/shadertoy-inputs.js';

const NOON = Date.UTC(2024, 0, 15, 12);

/** The inputs of `count` frames begun at the given moments (ms, performance.now()). */
function frames(inputs, moments) {
  return moments.map((now) => {
    const frame = inputs.beginFrame(64, 36, now);
    inputs.endFrame();
    return frame;
  });
}

describe('a fixed schedule', () => {
  test.each([
    ['60 fps, smooth frames', 60, [0, 16.7, 33.3, 50]],
    ['60 fps, frames that stall', 60, [0, 400, 401, 9000]],
    ['24 fps', 24, [0, 5, 10, 15]],
  ])("%s: iTimeDelta and iFrameRate are the schedule's, iTime its steps", (_, fps, moments) => {
    const inputs = new ShadertoyInputs();
    inputs.setSchedule({ date: NOON, fps });
    const drawn = frames(inputs, moments);
    for (const [i, frame] of drawn.entries()) {
      expect(frame.delta).toBeCloseTo(1 / fps, 12);
      expect(frame.frameRate).toBe(fps);
      expect(frame.time).toBeCloseTo(i / fps, 12);
      expect(frame.frame).toBe(i);
    }
  });

  test('iDate is the fixed moment at iTime 0, moving on with iTime, whatever the real date', () => {
    const inputs = new ShadertoyInputs();
    inputs.setSchedule({ date: NOON, fps: 60 });
    inputs.pause();
    inputs.setTime(90);
    expect(inputs.beginFrame(8, 8, 123).date).toEqual(shadertoyDate(new Date(NOON + 90_000)));
    // the same frame a minute of real time later
    expect(inputs.beginFrame(8, 8, 60_123).date).toEqual(shadertoyDate(new Date(NOON + 90_000)));
  });

  test("a paused still has the schedule's step and rate", () => {
    const inputs = new ShadertoyInputs();
    inputs.setSchedule({ fps: 30 });
    inputs.pause();
    const [a, b] = frames(inputs, [0, 1000]);
    expect([a.delta, a.frameRate, b.delta, b.frameRate]).toEqual([1 / 30, 30, 1 / 30, 30]);
    expect(b.time).toBe(0);
  });

  test('without a schedule the date is the real one and the rate is measured (the interactive page)', () => {
    const inputs = new ShadertoyInputs();
    const [, second] = frames(inputs, [0, 50]);
    expect(second.frameRate).toBeCloseTo(20, 9);
    const today = new Date();
    expect(second.date.slice(0, 3)).toEqual([today.getFullYear(), today.getMonth(), today.getDate()]);
  });
});
