// Every way a shader's text arrives (a ?shader= URL, a link's #source=, a dropped file, a paste,
// the hook, the dev server's reload) ends here: the text is read as Shadertoy's JSON
// export or as a plain Image-tab shader (project-files.js), named, and run.

import { isJsonName, readShaderText } from './project-files.js';
import { fetchShader, shaderName } from './shader-loader.js';

/** @typedef {import('../app/app.js').ShaderApp} ShaderApp */
/** @typedef {import('../../shadertoy/multipass.js').MultipassShader} MultipassShader */

/**
 * Where a shader's text came from.
 * @typedef {object} ShaderFrom
 * @property {ShaderApp['origin']} origin
 * @property {string} [name] its name in messages and downloads; omitted: a Shadertoy export's
 *   own name (else `fileName`, else "untitled"), and a plain shader `fileName` or, without one,
 *   the page's current name
 * @property {string} [fileName] the name of the file it was read from (a dropped file): a
 *   dropped export goes by the shader's own name, as the same export pasted does
 * @property {string | null} [url] the URL it was fetched from (origin 'url')
 * @property {boolean} [json] it is Shadertoy's JSON export whatever it looks like (a .json file)
 */

/**
 * A shader's text read and named, ready for app.loadProject. Throws, with a readable reason, for
 * JSON that is not a Shadertoy shader.
 * @param {string} text
 * @param {ShaderFrom} from
 * @returns {{project: MultipassShader, notes: string[], from: {name?: string, origin: ShaderApp['origin'], url: string | null, info: object | null}}}
 */
export function readShader(text, { origin, name, fileName, url = null, json = false }) {
  const { model, info, notes } = readShaderText(text, { json: json || (url !== null && isJsonName(url)) });
  const ownName = info ? String(info.name || fileName || 'untitled') : fileName;
  return { project: model, notes, from: { name: name ?? ownName, origin, url, info } };
}

/**
 * Reads a shader's text and runs it. Throws at once, with a readable reason, for a text that is
 * not a shader; else returns it as read, with `running`, which resolves once it runs and rejects
 * with the compile error (the last shader that compiled keeps running then).
 * @param {ShaderApp} app
 * @param {string} text
 * @param {ShaderFrom} from
 * @param {(loaded: ReturnType<typeof readShader>) => void} [beforeRun] called between reading and running
 */
export function openShader(app, text, from, beforeRun = () => {}) {
  const loaded = readShader(text, from);
  beforeRun(loaded);
  const running = app.setProject(loaded.project, loaded.from);
  return { ...loaded, running };
}

/**
 * Fetches a shader from the page's own server and runs it, as ?shader= does: resolves once it
 * runs, rejects with why it could not be had, read or compiled.
 * @param {ShaderApp} app
 * @param {string} url
 */
export async function openShaderUrl(app, url) {
  const opened = openShader(app, await fetchShader(url), { name: shaderName(url), origin: 'url', url });
  await opened.running;
  return opened;
}
