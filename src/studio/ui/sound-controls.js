// The Sound tab's widgets in the toolbar, a group of their own before the frame-time graph: a
// mute button (a drawn speaker icon, named "Mute sound", pressed while muted) and a level meter
// (the RMS of what plays, drawn each frame), shown only for a shader with a Sound tab; and the
// note that says the sound waits for a first click or key (the browsers' autoplay rule). The
// toolbar is fitted again when they come or go (toolbar-fit.js): on a phone they go to the
// second row (toolbar.css), so that the frame-time line keeps its room on the first.

import { element } from './dom.js';
import { soundNote } from './notices.js';
import { icon } from './toolbar/toolbar.js';
import { SoundPlayer } from '../../player/sound/player.js';

/** The meter's size in pixels. */
const METER = { width: 40, height: 24 };

/**
 * Makes the player and its widgets, in a group of the toolbar before its frame-time graph.
 * @param {import('../../player/app/app.js').ShaderApp} app
 * @param {{toolbar: import('./toolbar/toolbar.js').Toolbar, stage: HTMLElement}} where
 */
export function installSound(app, { toolbar, stage }) {
  const player = new SoundPlayer(app);
  const mute = element('button', {
    type: 'button',
    class: 'sound-mute',
    'aria-label': 'Mute sound',
    'aria-pressed': 'false',
    title: 'Mute the Sound tab',
  });
  const meter = /** @type {HTMLCanvasElement} */ (
    element('canvas', { class: 'sound-meter', width: METER.width, height: METER.height, role: 'meter', 'aria-label': 'Sound level' })
  );
  const bar = element('div', { class: 'group sound' }, mute, meter);
  bar.hidden = true;
  toolbar.meterGroup.before(bar);
  mute.addEventListener('click', () => player.setMuted(!player.muted));

  /** @type {boolean | null} whether the icon shows muted (null: none yet) */
  let drawnMuted = null;
  const show = () => {
    const hidden = !player.available;
    if (bar.hidden !== hidden) {
      bar.hidden = hidden;
      toolbar.fit(); // the group takes room of its own, or gives it back
    }
    if (drawnMuted !== player.muted) {
      drawnMuted = player.muted;
      mute.replaceChildren(icon(player.muted ? 'muted' : 'sound'));
    }
    mute.setAttribute('aria-pressed', String(player.muted));
    mute.title = player.muted ? 'Unmute the Sound tab' : 'Mute the Sound tab';
    soundNote(stage, player.waiting);
  };
  player.onChange = show;
  app.on('source', show);
  app.on('compile', show);
  app.on('drawn', () => {
    if (bar.hidden) return;
    const level = player.level();
    meter.setAttribute('aria-valuenow', level.toFixed(3));
    const g = /** @type {CanvasRenderingContext2D} */ (meter.getContext('2d'));
    g.clearRect(0, 0, METER.width, METER.height);
    g.fillStyle = level > 0.9 ? '#e55' : '#5c5';
    g.fillRect(0, METER.height * (1 - Math.min(1, level * 1.4)), METER.width, METER.height);
  });
  // the autoplay rule: sound may start with the first click or key on the page
  const unlock = () => {
    player.unlock();
    show();
  };
  window.addEventListener('pointerdown', unlock, { capture: true, once: true });
  window.addEventListener('keydown', unlock, { capture: true, once: true });
  return player;
}
