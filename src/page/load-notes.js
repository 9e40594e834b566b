// What the page says about a shader it loaded but cannot give everything it asks for (media its
// Shadertoy JSON names, sound and cubemap passes), or about a file it could not read as a shader:
// a note at the top of the canvas that blocks nothing, stays until closed or until another
// shader is loaded, and says nothing when there is nothing to say.

const NOTE_ID = 'load-notes';

/**
 * Shows the note (replacing the one shown), or removes it when `lines` is empty.
 * @param {HTMLElement} parent the stage
 * @param {string} title
 * @param {string[]} lines one a line
 * @param {'note' | 'error'} [kind] an error is marked as one
 * @returns {HTMLElement | null}
 */
export function showLoadNotes(parent, title, lines, kind = 'note') {
  document.getElementById(NOTE_ID)?.remove();
  if (!lines.length) return null;
  const note = document.createElement('div');
  note.id = NOTE_ID;
  note.className = kind;
  note.setAttribute('role', 'status');
  const heading = document.createElement('strong');
  heading.textContent = title;
  const list = document.createElement('ul');
  for (const line of lines) {
    const item = document.createElement('li');
    item.textContent = line;
    list.append(item);
  }
  const close = document.createElement('button');
  close.type = 'button';
  close.textContent = '✕';
  close.setAttribute('aria-label', 'Close this note');
  close.addEventListener('click', () => note.remove());
  note.append(heading, close, list);
  parent.append(note);
  return note;
}

/** Removes the note, if one is shown. */
export const hideLoadNotes = () => document.getElementById(NOTE_ID)?.remove();
