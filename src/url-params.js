// The page's URL contract, for sharing a view and for automation:
//
//   ?time=T        render at iTime = T seconds, paused
//   &mouse=x,y,z,w iMouse in device pixels (until the first click)
//   &size=WxH      drawing buffer of W×H device pixels (CSS size W/dpr × H/dpr; no scaling)
//   &scale=s       resolution scale, 0.25 .. 1 of device pixels (ignored with size)
//   &NAME=value    any shader control; vectors as comma lists (LIGHT_POSITION=1,2,3)
//
// Anything unreadable is reported in `warnings` and ignored; the page never fails on a URL.
// Control values are returned as written: the app checks them against the shader's controls
// (coerceControlValue), as it does for the panel and the automation hook.

export const MIN_SCALE = 0.25;
export const MAX_SCALE = 1;
const MAX_SIZE = 16384;

function finiteNumbers(text) {
  const parts = text.split(',').map((s) => (s.trim() === '' ? NaN : Number(s)));
  return parts.every(Number.isFinite) ? parts : null;
}

/**
 * @param {string} search location.search
 * @returns {{time?: number, mouse?: number[], size?: {width:number, height:number},
 *   scale?: number, controls: Record<string, string>, warnings: string[]}}
 */
export function parseUrlParams(search) {
  const out = { controls: {}, warnings: [] };
  const warn = (key, value, why) => out.warnings.push(`URL parameter ${key}=${value} ignored: ${why}`);

  for (const [key, value] of new URLSearchParams(search)) {
    if (key === 'time') {
      const t = finiteNumbers(value);
      if (t && t.length === 1) out.time = t[0];
      else warn(key, value, 'expected a number of seconds');
    } else if (key === 'mouse') {
      const m = finiteNumbers(value);
      if (m && (m.length === 4 || m.length === 2)) out.mouse = m.length === 4 ? m : [...m, 0, 0];
      else warn(key, value, 'expected x,y,z,w');
    } else if (key === 'size') {
      const m = value.trim().match(/^(\d+)\s*[xX×]\s*(\d+)$/);
      const [width, height] = m ? [Number(m[1]), Number(m[2])] : [0, 0];
      if (width >= 1 && height >= 1 && width <= MAX_SIZE && height <= MAX_SIZE) out.size = { width, height };
      else warn(key, value, `expected WxH, 1 .. ${MAX_SIZE} device pixels`);
    } else if (key === 'scale') {
      const s = finiteNumbers(value);
      if (s && s.length === 1 && s[0] > 0) out.scale = Math.min(MAX_SCALE, Math.max(MIN_SCALE, s[0]));
      else warn(key, value, `expected a number in ${MIN_SCALE} .. ${MAX_SCALE}`);
    } else {
      out.controls[key] = value;
    }
  }
  return out;
}
