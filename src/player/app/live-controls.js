// Which form of the shader the page compiles for its live (`const`) controls.
//
// A `const` control is a uniform in the page so that a slider applies without a compile; but
// then the compiler folds nothing, and the frame costs more than the pasted shader's (measured
// on SwiftShader at 640x360: npm run bench, "page form (uniforms)"). So while the controls are
// still, the page runs the shader exactly as it pastes, with the current values as constants,
// and goes back to the uniform form (kept compiled: renderer.js) as soon as one moves.

/** How long the live controls must rest before the shader is recompiled with them as constants. */
const SPECIALIZE_AFTER_MS = 400;

export class LiveControlForm {
  /** @param {() => void} onRest called once the controls have rested: compile the constant form */
  constructor(onRest) {
    /** Whether the next compile takes the live controls as constants (else as uniforms). */
    this.asConstants = true;
    this._onRest = onRest;
    /** @type {ReturnType<typeof setTimeout> | undefined} */
    this._timer = undefined;
  }

  /** A new shader: its compile takes the live values as constants. */
  reset() {
    clearTimeout(this._timer);
    this.asConstants = true;
  }

  /**
   * A live control moved while a shader is on screen: back to the uniform form, and to the
   * constant form again once the controls rest for SPECIALIZE_AFTER_MS.
   * @returns {boolean} true when the shader on screen has the old values as constants: it must
   *   be compiled again, in the uniform form
   */
  moved() {
    const recompile = this.asConstants;
    this.asConstants = false;
    clearTimeout(this._timer);
    this._timer = setTimeout(() => {
      this.asConstants = true;
      this._onRest();
    }, SPECIALIZE_AFTER_MS);
    return recompile;
  }
}
