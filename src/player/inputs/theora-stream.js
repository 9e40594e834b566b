// An Ogg file's Theora video, frame by frame: its packets read once, by ogv.js's WebAssembly
// builds of liboggz (the demuxer) and libtheora (the decoder), and any frame decoded on demand,
// from the keyframe before it (or on from the frame decoded last, when no keyframe lies between).
//
// Why: Chromium no longer decodes Theora, and the site's videos are Theora (`.ogv`, with Vorbis
// sound). Nothing here needs a page: the two modules come in as factories, so that the page
// (theora-video.js) gives them their WebAssembly from the build and a test from node_modules.
//
// Times. A frame's time is its frame number (from its granule position, which the demuxer turns
// into seconds, rounded to the millisecond) less the first frame's, over the frame rate the
// stream's identification header declares; the video lasts until the end of its last frame. A
// frame the encoder sent as a duplicate (an empty packet) has no packet: the frame before it is
// shown in its time, as a player shows it.

/** ogv.js's Ogg demuxer (ogv-demuxer-ogg-wasm.js), the part used here. @typedef {{init: (done: () => void) => void, receiveInput: (data: ArrayBuffer, done: () => void) => void, process: (done: (more: boolean) => void) => void, videoPackets: Array<{data: ArrayBuffer, timestamp: number, isKeyframe: boolean}>, audioPackets: unknown[]}} OgvDemuxer */
/** ogv.js's Theora decoder (ogv-decoder-video-theora-wasm.js), the part used here. @typedef {{init: (done: () => void) => void, processHeader: (data: ArrayBuffer, done: (ok: number) => void) => void, processFrame: (data: ArrayBuffer, done: (ok: number) => void) => void, loadedMetadata: boolean, frameBuffer: import('./theora-colour.js').YuvFrame | null}} OgvDecoder */
/** @typedef {{data: ArrayBuffer, offset: number, key: number}} TheoraPacket offset: frames after the first; key: the index of the keyframe it decodes from */

/** A packet that is one of Theora's three headers has its high bit set (identification 0x80, comment 0x81, setup 0x82). */
const isHeader = (/** @type {ArrayBuffer} */ data) => data.byteLength > 0 && (new Uint8Array(data)[0] & 0x80) !== 0;

/**
 * The frame rate the identification header declares, frames a second as a fraction.
 * @param {ArrayBuffer} packet
 */
function frameRate(packet) {
  const view = new DataView(packet);
  const magic = packet.byteLength >= 42 ? String.fromCharCode(...new Uint8Array(packet, 1, 6)) : '';
  if (view.getUint8(0) !== 0x80 || magic !== 'theora') throw new Error('its Theora identification header is damaged');
  // after the magic: version (3 bytes), frame size in macroblocks (2 × 2), picture size (2 × 3), offset (2 × 1)
  const numerator = view.getUint32(22);
  const denominator = view.getUint32(26);
  if (!numerator || !denominator) throw new Error('its Theora header declares no frame rate');
  return numerator / denominator;
}

export class TheoraStream {
  /**
   * @param {OgvDecoder} decoder with the headers read, its frame buffer the first frame's
   * @param {TheoraPacket[]} packets
   * @param {number} rate frames a second
   * @param {number} frames frames from the first to the end of the last (duplicates included)
   */
  constructor(decoder, packets, rate, frames) {
    this.decoder = decoder;
    this.packets = packets;
    this.rate = rate;
    /** Seconds, from the first frame's start to the last one's end. */
    this.duration = frames / rate;
    /** The index of the packet in the decoder's frame buffer. */
    this._decoded = 0;
  }

  /**
   * Reads an Ogg file's Theora stream and its headers; the decoder is then at the first frame.
   * @param {ArrayBuffer} bytes the whole file
   * @param {{demuxer: () => Promise<OgvDemuxer>, decoder: () => Promise<OgvDecoder>}} make
   *   new instances of ogv.js's modules
   */
  static async open(bytes, make) {
    const demuxer = await make.demuxer();
    demuxer.init(() => {});
    demuxer.receiveInput(bytes, () => {});
    /** @type {Array<{data: ArrayBuffer, timestamp: number, isKeyframe: boolean}>} */
    const all = [];
    for (let more = true; more;) {
      demuxer.process((going) => (more = going));
      all.push(...demuxer.videoPackets.splice(0));
      demuxer.audioPackets.length = 0; // the sound is not read (video-file.js says why)
    }
    // the demuxer gives a Theora stream's packets alone (its first, the identification header, at once)
    if (!all.length) throw new Error('it has no Theora video track');
    const headers = all.filter((packet) => isHeader(packet.data));
    const data = all.filter((packet) => !isHeader(packet.data) && packet.data.byteLength > 0);
    if (headers.length !== 3)
      throw new Error(`its Theora stream has ${headers.length} of its 3 headers (the file is cut short or damaged)`);
    if (!data.length) throw new Error('its Theora stream has no frame');
    const rate = frameRate(headers[0].data);
    const number = (/** @type {number} */ seconds) => Math.round(seconds * rate);
    const first = number(data[0].timestamp);
    let key = 0;
    const packets = data.map((packet, i) => {
      if (packet.isKeyframe) key = i;
      return { data: packet.data, offset: number(packet.timestamp) - first, key };
    });
    if (!data[0].isKeyframe) throw new Error('its Theora stream does not start with a keyframe');

    const decoder = await make.decoder();
    decoder.init(() => {});
    // the decoder takes its headers, then the first frame, which completes them and is decoded
    for (const packet of [...headers, data[0]]) {
      let ok = 0;
      decoder.processHeader(packet.data, (result) => (ok = result));
      if (!ok) throw new Error('its Theora headers cannot be read');
    }
    if (!decoder.loadedMetadata || !decoder.frameBuffer) throw new Error('its first Theora frame cannot be decoded');
    return new TheoraStream(decoder, packets, rate, packets[packets.length - 1].offset + 1);
  }

  /**
   * The index of the frame shown at `seconds` after the first frame's start: the last one
   * starting at or before it.
   * @param {number} seconds from 0 to the duration
   */
  indexAt(seconds) {
    // a frame starting at exactly `seconds` is shown, whatever the float rounding of seconds · rate
    const frame = seconds * this.rate + 1e-6;
    let low = 0;
    let high = this.packets.length - 1;
    while (low < high) {
      const middle = (low + high + 1) >> 1;
      if (this.packets[middle].offset <= frame) low = middle;
      else high = middle - 1;
    }
    return low;
  }

  /** The start of frame `index`, in seconds after the first frame's. @param {number} index */
  timeOf(index) {
    return this.packets[index].offset / this.rate;
  }

  /**
   * Frame `index`, decoded (the decoder's frame buffer: valid until the next decode).
   * @param {number} index
   * @returns {import('./theora-colour.js').YuvFrame}
   */
  decode(index) {
    const { key } = this.packets[index];
    // on from the frame decoded last when it lies between the keyframe and this one
    const from = this._decoded <= index && this._decoded >= key ? this._decoded + 1 : key;
    for (let i = from; i <= index; i++) {
      let ok = 0;
      this.decoder.processFrame(this.packets[i].data, (result) => (ok = result));
      if (!ok) {
        this._decoded = -1; // the decoder's state is unknown: the next frame starts from its keyframe
        throw new Error(`frame ${i} of the Theora stream cannot be decoded`);
      }
      this._decoded = i;
    }
    return /** @type {import('./theora-colour.js').YuvFrame} */ (this.decoder.frameBuffer);
  }
}
