// The page's production timeouts (src/shared/timeouts.js), held here: the page tests run with
// shortened ones (tests/support/config.js's SHORT_TIMEOUTS), so this is where a change of a
// production value shows. And a harness's overrides take only known, positive, finite values.
import { describe, expect, test } from 'vitest';
import { PRODUCTION_TIMEOUTS, timeoutsWith } from '../../src/shared/timeouts.js';
import { SHORT_TIMEOUTS } from '../support/config.js';

describe('the page timeouts', () => {
  test('production values', () => {
    expect(PRODUCTION_TIMEOUTS).toEqual({ loadMs: 15_000, hangMs: 5_000, compileHangMs: 30_000, workerStartMs: 20_000 });
  });

  test.each([
    ['nothing', undefined, PRODUCTION_TIMEOUTS],
    ['the tests', SHORT_TIMEOUTS, SHORT_TIMEOUTS],
    ['a partial set', { hangMs: 700 }, { ...PRODUCTION_TIMEOUTS, hangMs: 700 }],
    ['unknown, zero, negative and non-numbers', { nope: 1, loadMs: 0, hangMs: -5, workerStartMs: '9' }, PRODUCTION_TIMEOUTS],
  ])('overridden by %s', (_, overrides, expected) => {
    expect(timeoutsWith(/** @type {any} */ (overrides))).toEqual(expected);
  });
});
