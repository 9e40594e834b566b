// The actions behind the page's buttons and keys, as plain functions of the app and the page:
// what Play, Restart, Copy for Shadertoy, Download, Export JSON, Screenshot, Fullscreen and Copy
// link do. The toolbar, the shortcuts and the page's hook all call these.

import { copyText, pngBlob, saveBlob } from './dom.js';
import { MAX_LINK_LENGTH, shareLink } from '../../player/io/share-link.js';
import { exportJson, projectTabs, tabCode } from '../../player/io/project-files.js';
import { fileStem, jsonFileName, screenshotFileName, tabFileName } from '../../player/io/file-names.js';

/** @typedef {import('../../player/app/app.js').ShaderApp} ShaderApp */

/**
 * Enters fullscreen with `element`, or leaves it when the page is fullscreen.
 * @param {HTMLElement} element
 * @returns {Promise<boolean>} whether the page is fullscreen afterwards
 */
async function toggleFullscreen(element) {
  try {
    if (document.fullscreenElement) await document.exitFullscreen();
    else await element.requestFullscreen({ navigationUI: 'hide' });
  } catch (error) {
    console.warn(`Fullscreen refused: ${error.message}`);
  }
  return document.fullscreenElement !== null;
}

/**
 * The page's actions.
 * @param {ShaderApp} app
 * @param {object} page
 * @param {HTMLElement} page.stage what goes fullscreen
 * @param {(text: string) => void} page.toast a short confirmation
 * @param {() => string} page.activeTab the editor's tab ('Image' for a single-pass shader)
 * @param {() => void} page.toggleEditor
 * @param {(width: number, height: number) => {width: number, height: number} | null} page.screenshotSize
 *   the size chosen in the panel for a canvas of width × height (null: the canvas's)
 * @param {() => {base: string, source: string} | null} page.shipped the file the page ships that
 *   the editor's text is an edit of (a link carries such an edit as a patch against it)
 */
export function pageActions(app, { stage, toast, activeTab, toggleEditor, screenshotSize, shipped }) {
  /** The editor's tab and its text as the page runs it (the whole file for a single-pass shader). */
  const shownTab = () => {
    const multipass = projectTabs(app.project).length > 1;
    const tab = multipass ? activeTab() : 'Image';
    return { tab, multipass, code: tabCode(app.project, tab) ?? app.source };
  };

  return {
    togglePlay: () => app.togglePlay(),
    restart: () => app.restart(),
    resetView: () => app.resetView(),
    /** @param {number} t */
    setTime: (t) => app.setTime(t),
    /** @param {number} s */
    setSpeed: (s) => app.setSpeed(s),
    toggleEditor,
    toggleFullscreen: () => toggleFullscreen(stage),

    /**
     * Exactly the text Shadertoy's tab takes: the shader file, or the editor's tab of a multipass
     * shader (Shadertoy adds the header).
     */
    async copyForShadertoy() {
      const { tab, code, multipass } = shownTab();
      const ok = await copyText(code);
      const what = multipass ? `${tab} of ${app.fileName}` : app.fileName;
      toast(
        ok
          ? `Copied ${what} (${code.split('\n').length} lines): paste it into Shadertoy's ${tab} tab`
          : 'The browser refused to copy; use Download .glsl instead',
      );
      return ok;
    },

    /** Saves the shader file, or the editor's tab of a multipass shader ("NAME - Buffer A.glsl"). */
    download() {
      const { tab, code, multipass } = shownTab();
      const name = tabFileName(app.fileName, tab, multipass);
      saveBlob(new Blob([code], { type: 'text/plain;charset=utf-8' }), name);
      toast(`Saved ${name}`);
      return name;
    },

    /** Saves the whole shader, every tab and channel, as Shadertoy's JSON export ("NAME.json"). */
    exportJson() {
      const name = jsonFileName(app.fileName);
      saveBlob(new Blob([exportJson(app.project, app.projectInfo, fileStem(app.fileName))], { type: 'application/json' }), name);
      const tabs = projectTabs(app.project).length;
      toast(`Saved ${name} (Shadertoy's JSON format, ${tabs} ${tabs === 1 ? 'tab' : 'tabs'})`);
      return name;
    },

    /**
     * A PNG of the current frame, at the size chosen in the panel (canvas size by default).
     * @param {{width: number, height: number} | null} [size]
     */
    async screenshot(size = null) {
      try {
        const { width, height } = app.frames.size;
        const image = await app.frames.capture(size ?? screenshotSize(width, height));
        const name = screenshotFileName(app.fileName, { time: image.time, width: image.width, height: image.height });
        saveBlob(await pngBlob(image), name);
        toast(`Saved ${name}`);
        return { name, width: image.width, height: image.height };
      } catch (error) {
        console.warn(`Screenshot failed: ${error.message}`);
        toast(`Screenshot failed: ${error.message}`);
        return null;
      }
    },

    /** Copies the view's link, saying what it leaves out; a link too long to travel is not copied. */
    async copyLink() {
      const { url, omitted, tooLong } = await shareLink(app, shipped());
      if (tooLong) {
        toast(
          `Not copied: the link would be ${url.length} characters, too long for many browsers and apps (over ${MAX_LINK_LENGTH}); share the shader with Download .glsl`,
        );
        return null;
      }
      const ok = await copyText(url);
      const caveat = omitted.length ? ` (${omitted.join(', ')} ${omitted.length > 1 ? 'are' : 'is'} not in the link)` : '';
      toast(ok ? `Copied a link to this view${caveat}` : 'The browser refused to copy the link');
      return url;
    },
  };
}
