// Reads an LCM event log (lcm-logger's format) without LCM: each event is the sync word
// 0xEDA1DA01, int64 event number, int64 timestamp [us], int32 channel length, int32 data length,
// the channel, the data; all big-endian. A last event cut short is reported, not read.
import { readFileSync } from 'node:fs';

const SYNC = 0xeda1da01;

export function readLcmLog(path) {
  const bytes = readFileSync(path);
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const events = [];
  let pos = 0;
  while (pos + 28 <= bytes.length) {
    if (view.getUint32(pos) !== SYNC) throw new Error(`${path}: no sync word at byte ${pos}`);
    const channelLength = view.getInt32(pos + 20);
    const dataLength = view.getInt32(pos + 24);
    const end = pos + 28 + channelLength + dataLength;
    if (end > bytes.length) break;
    events.push({
      offset: pos,
      eventNumber: view.getBigInt64(pos + 4),
      utime: view.getBigInt64(pos + 12),
      channel: bytes.toString('latin1', pos + 28, pos + 28 + channelLength),
      size: dataLength,
    });
    pos = end;
  }
  return { events, wholeBytes: pos, tornBytes: bytes.length - pos, fileBytes: bytes.length };
}

export function countByChannel(events) {
  const counts = new Map();
  for (const e of events) counts.set(e.channel, (counts.get(e.channel) ?? 0) + 1);
  return counts;
}
