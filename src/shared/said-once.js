// What a shader went without, each thing said once: the page's note (src/studio/ui/notices.js) and
// the command line's warnings and test lines (src/api/io.js, src/runner/case.js) say it in the
// same words.

/** "A", "A and B", "A, B and C". @param {string[]} names */
const listed = (names) => (names.length < 2 ? names.join('') : `${names.slice(0, -1).join(', ')} and ${names[names.length - 1]}`);

/**
 * The lines of a note, each thing said once: lines that say the same of several channels
 * ("Buffer A, iChannel0: the site's video … is not in the media folder; the channel is black",
 * and the same of Buffer B and Image) become one line that names them all ("Buffer A, Buffer B
 * and Image, iChannel0: …; all 3 channels are black"), where the first of them was; a line said
 * twice is said once.
 * @param {string[]} lines
 * @returns {string[]}
 */
export function sayOnce(lines) {
  /** What is said, and of which channels, in the order first said. @type {Map<string, Array<{pass: string, channel: string}>>} */
  const said = new Map();
  for (const line of lines) {
    const of = /^(.+?), (iChannel\d): (.*)$/s.exec(line);
    const what = of ? of[3] : line;
    const channels = said.get(what) ?? [];
    if (of && !channels.some((c) => c.pass === of[1] && c.channel === of[2])) channels.push({ pass: of[1], channel: of[2] });
    said.set(what, channels);
  }
  return [...said].map(([what, channels]) => {
    if (channels.length === 0) return what;
    if (channels.length === 1) return `${channels[0].pass}, ${channels[0].channel}: ${what}`;
    const oneChannel = channels.every((c) => c.channel === channels[0].channel);
    const onePass = channels.every((c) => c.pass === channels[0].pass);
    const where = oneChannel
      ? `${listed(channels.map((c) => c.pass))}, ${channels[0].channel}`
      : onePass
        ? `${channels[0].pass}, ${listed(channels.map((c) => c.channel))}`
        : listed(channels.map((c) => `${c.pass}'s ${c.channel}`));
    const all = channels.length === 2 ? 'both channels are' : `all ${channels.length} channels are`;
    return `${where}: ${what.replace(/; the channel is black/, `; ${all} black`)}`;
  });
}
