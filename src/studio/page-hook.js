// window.shaderEngine on the interactive page (index.html, main.js): the engine's hook
// (engine-hook.js) and the methods of the page's own widgets, which its tests drive: the
// inspector, the float64 comparison, the link, the editor and the Sound tab's player. The engine
// page (engine-main.js) has none of these widgets, and so none of these methods.
//
//   inspect(x, y)         Promise<Readout>: Inspect on, pixel (x, y) pinned (y from the bottom:
//                         fragCoord - 0.5) and read: its float colour, the canvas's byte, each
//                         buffer, and for the raytracer its ray path and the float64 reference's
//                         colour and path (inspect/inspector.js: Readout); resolves once all of
//                         it is in (a path probe that compiles first included).
//   inspection()          {active, pinned, problem, readout}: the inspector as it is now.
//   unpin()               unpins the pixel (Esc).
//   compareWithFloat64()  Promise<{width, height, figures: {float, canvas}, extraSampleShare,
//                         frame, ms, caveat}>: "Compare with float64" on the frame on the canvas
//                         (inspect/compare.js; figures as src/reference/error.js gives them);
//                         rejects with why it cannot.
//   comparison()          {running, error, stale, shown}: the comparison's state on the page.
//   shareUrl()            Promise<string>: the link "Copy link" copies (reproduces this view).
//   editorSource()        the text of the editor's current tab (what it holds, compiled or not).
//   soundState()          {available (the shader that runs has a Sound tab), context (the
//                         AudioContext's state, null before the first click or key), muted,
//                         plan ({sample, when, rate, time}: sample `sample` plays at
//                         audio-clock time `when`, planned at iTime `time`: sound/schedule.js;
//                         null when silent), now (the audio clock), sources (blocks playing or
//                         scheduled), level (RMS)}
//   setMuted(on)          the Sound tab's mute button

import { EngineHook, hookOnWindow } from '../player/hook/engine-hook.js';
import { markApp } from '../player/page-marks.js';

/** @typedef {ReturnType<typeof import('./wiring.js').installUi>} PageUi */

export class PageHook extends EngineHook {
  /** The page's widgets. @type {PageUi} */
  #ui;

  /**
   * @param {import('../player/app/app.js').ShaderApp} app
   * @param {import('../player/hook/engine-hook.js').EngineHost} host
   * @param {PageUi} ui
   */
  constructor(app, host, ui) {
    super(app, host);
    this.#ui = ui;
  }

  /** @param {number} x @param {number} y */
  async inspect(x, y) {
    await this.settled();
    const { inspection } = this.#ui;
    inspection.pin(x, y);
    return structuredClone(await inspection.inspector.complete());
  }
  inspection() {
    const { inspector } = this.#ui.inspection;
    return structuredClone({
      active: inspector.active,
      pinned: inspector.pinned,
      problem: inspector.problem,
      readout: inspector.readout,
    });
  }
  unpin() {
    this.#ui.inspection.inspector.unpin();
  }

  async compareWithFloat64() {
    await this.settled();
    const { figures, width, height, extraSampleShare, frame, ms, caveat } = await this.#ui.inspection.comparison.run();
    return { figures, width, height, extraSampleShare, frame, ms, caveat };
  }
  comparison() {
    const { running, error, stale, result } = this.#ui.inspection.comparison;
    return structuredClone({ running, error, stale, shown: result ? { width: result.width, height: result.height } : null });
  }

  shareUrl() {
    return this.#ui.shareUrl();
  }
  editorSource() {
    return this.#ui.editor.text;
  }

  soundState() {
    const player = this.#ui.sound;
    const context = player.context;
    return structuredClone({
      available: player.available,
      context: context?.state ?? null,
      muted: player.muted,
      plan: player.plan,
      now: context?.currentTime ?? null,
      sources: player.sourceCount,
      level: player.level(),
    });
  }
  /** @param {boolean} muted */
  setMuted(muted) {
    this.#ui.sound.setMuted(Boolean(muted));
  }
}

/**
 * Installs the interactive page's hook on the window for `app`: the engine's, and its widgets'.
 * @param {import('../player/app/app.js').ShaderApp} app
 * @param {import('../player/hook/engine-hook.js').EngineHost} host
 * @param {PageUi} ui
 */
export function installPage(app, host, ui) {
  markApp(app);
  return hookOnWindow(new PageHook(app, host, ui));
}
