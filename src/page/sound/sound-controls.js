// The Sound tab's widgets in the toolbar, beside the frame-time graph: a mute button and a level
// meter (the RMS of what plays, drawn each frame), shown only for a shader with a Sound tab; and
// the note that says the sound waits for a first click or key (the browsers' autoplay rule).

import { element } from '../ui/dom.js';
import { soundNote } from '../ui/notices.js';
import { SoundPlayer } from './player.js';

/** The meter's size in pixels. */
const METER = { width: 40, height: 24 };

/**
 * Makes the player and its widgets, after `graph` (the toolbar's frame-time graph).
 * @param {import('../app/app.js').RaytracerApp} app
 * @param {{graph: HTMLElement, stage: HTMLElement}} where
 */
export function installSound(app, { graph, stage }) {
  const player = new SoundPlayer(app);
  const mute = element('button', { type: 'button', class: 'sound-mute', 'aria-pressed': 'false', title: 'Mute the Sound tab' }, '🔊');
  const meter = /** @type {HTMLCanvasElement} */ (
    element('canvas', { class: 'sound-meter', width: METER.width, height: METER.height, role: 'meter', 'aria-label': 'Sound level' })
  );
  const bar = element('span', { class: 'sound' }, mute, meter);
  bar.hidden = true;
  graph.after(bar);
  mute.addEventListener('click', () => player.setMuted(!player.muted));

  const show = () => {
    bar.hidden = !player.available;
    mute.textContent = player.muted ? '🔇' : '🔊';
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
