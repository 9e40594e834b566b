// What a channel's file is, by its type or, without one, its name: an image, a video or music.
// The command line's --channel0..3 and the page's channel sources go through here, so one file
// is the same kind everywhere.

const VIDEO = /\.(webm|mp4|m4v|mov|mkv|ogv)$/i;
const MUSIC = /\.(wav|mp3|ogg|oga|opus|flac|m4a|aac)$/i;

/**
 * @param {{name?: string, type?: string}} file a File or Blob, or a URL as {name}
 * @returns {'image' | 'video' | 'music'}
 */
export function channelKind({ name = '', type = '' }) {
  if (type.startsWith('video/')) return 'video';
  if (type.startsWith('audio/')) return 'music';
  if (type.startsWith('image/')) return 'image';
  const path = name.split(/[?#]/)[0];
  if (VIDEO.test(path)) return 'video';
  if (MUSIC.test(path)) return 'music';
  return 'image';
}
