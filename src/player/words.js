// The words the page says of its own state, in one place: the titles of its notes and the
// watchdog's message. The interactive page shows them (ui/notices.js); the engine hook gives the
// same words back as data (hook/engine-hook.js notes(), hang()), so that the command line says
// what a person would read on the page.

/** The title of the note on what a loaded shader goes without. @param {string} name the shader's */
export const missingNotesTitle = (name) => `${name} runs without some of what it asks for`;

/** The title of the note on values not used as given. */
export const VALUE_NOTES_TITLE = 'Some values were not used as given';

/**
 * The watchdog message's title.
 * @param {string} name the shader on the GPU
 * @param {string} phase 'compiling' or 'drawing'
 */
export const watchdogTitle = (name, phase) => (phase === 'compiling' ? `Compiling ${name}…` : `${name} may never finish`);

/**
 * The watchdog message's text, with the seconds as they are now.
 * @param {string} name the shader on the GPU
 * @param {number} seconds how long its band has gone unfinished, whole seconds
 * @param {string} phase 'compiling' or 'drawing'
 * @param {string | null} back the shader "Go back" runs
 */
export function watchdogDetail(name, seconds, phase, back) {
  return [
    phase === 'compiling'
      ? `SwiftShader (the CPU renderer) turns a shader into machine code when it first draws it, and ${name} has been compiling for ${seconds} s. A large shader takes a while; the first frame follows.`
      : `${name} has been drawing one frame for ${seconds} s without finishing a band of it: it may never finish (an endless loop, or far too much work per pixel).`,
    phase === 'compiling'
      ? ''
      : 'On a real GPU the browser resets the GPU after several seconds of this, and the page comes back with the last shader that finished a frame. SwiftShader (the CPU renderer) has no such reset: the draw goes on until the browser is closed.',
    back ? `Going back runs ${back} again; the text of ${name} stays in the editor's undo history (Ctrl+Z).` : '',
  ]
    .filter(Boolean)
    .join('\n');
}
