// The names of a shader and of the files the page saves from it, in one place: an edited
// shader's name ("scene.glsl (edited)"), a name as a file-name stem ("scene-edited"), and
// each download's name built from that stem (a tab, a screenshot, a recording, a JSON export).

const EDITED = ' (edited)';

/** A name without its folders. @param {string} name */
function baseName(name) {
  return name.slice(name.lastIndexOf('/') + 1);
}

/**
 * The name of an edited shader: the file's own name marked as edited.
 * @param {string} name
 */
export function editedName(name) {
  const base = baseName(name);
  return base.endsWith(EDITED) ? base : base + EDITED;
}

/**
 * A shader's name as a file-name stem (no folders, no extension): "scene", "scene-edited",
 * "untitled".
 * @param {string} name
 */
export function fileStem(name) {
  let base = baseName(name);
  const edited = base.endsWith(EDITED);
  if (edited) base = base.slice(0, -EDITED.length);
  base = base.replace(/\.[^.]*$/, '') || 'shader';
  return edited ? `${base}-edited` : base;
}

/**
 * The name of a saved tab: "NAME.glsl" for a single-pass shader, "NAME - Buffer A.glsl" for a
 * tab of a multipass one.
 * @param {string} name the shader's name
 * @param {string} tab
 * @param {boolean} multipass
 */
export const tabFileName = (name, tab, multipass) => (multipass ? `${fileStem(name)} - ${tab}.glsl` : `${fileStem(name)}.glsl`);

/** The whole shader as Shadertoy's JSON export: "NAME.json". @param {string} name */
export const jsonFileName = (name) => `${fileStem(name)}.json`;

/**
 * A screenshot: "NAME-t1.25-640x360.png".
 * @param {string} name
 * @param {{time: number, width: number, height: number}} shot
 */
export const screenshotFileName = (name, { time, width, height }) => `${fileStem(name)}-t${time.toFixed(2)}-${width}x${height}.png`;

/**
 * A recording: "NAME-640x360-30fps-60f.webm" (or .zip of PNGs).
 * @param {string} name
 * @param {{format: 'webm' | 'png', width: number, height: number, fps: number, frames: number}} recording
 */
export const recordingFileName = (name, { format, width, height, fps, frames }) =>
  `${fileStem(name)}-${width}x${height}-${fps}fps-${frames}f.${format === 'webm' ? 'webm' : 'zip'}`;
