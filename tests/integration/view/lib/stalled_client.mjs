// A WebSocket client that stops reading: written on a bare TCP socket (the ws package resumes a
// paused socket by itself). It speaks foxglove.websocket.v1 far enough to subscribe to every
// channel advertised, then, once `stallWhen(advertisedTopics)` holds, pauses its socket for good:
// the server's frames pile up in the kernel's buffers, then in the server's own queue for it.
import { connect } from 'node:net';
import { randomBytes } from 'node:crypto';

function maskedText(text) {  // a client's frame must be masked (RFC 6455 §5.3)
  const payload = Buffer.from(text);
  const mask = randomBytes(4);
  const length = payload.length < 126 ? [0x80 | payload.length] : [0x80 | 126, payload.length >> 8, payload.length & 0xff];
  const frame = Buffer.concat([Buffer.from([0x81, ...length]), mask, payload]);
  for (let i = 0; i < payload.length; i++) frame[2 + length.length - 1 + 4 + i] ^= mask[i % 4];
  return frame;
}

// Complete server frames at the front of `buffer`: [{opcode, payload}], and the bytes left over.
function frames(buffer) {
  const out = [];
  let pos = 0;
  while (buffer.length - pos >= 2) {
    let length = buffer[pos + 1] & 0x7f, header = 2;
    if (length === 126) { if (buffer.length - pos < 4) break; length = buffer.readUInt16BE(pos + 2); header = 4; }
    else if (length === 127) { if (buffer.length - pos < 10) break; length = Number(buffer.readBigUInt64BE(pos + 2)); header = 10; }
    if (buffer.length - pos < header + length) break;
    out.push({ opcode: buffer[pos] & 0x0f, payload: buffer.subarray(pos + header, pos + header + length) });
    pos += header + length;
  }
  return { frames: out, rest: buffer.subarray(pos) };
}

export function stalledClient(port, stallWhen, onStall) {
  const state = { sessionId: null, topics: [], stalledAtMs: null };
  const socket = connect(port, '127.0.0.1');
  let buffer = Buffer.alloc(0), upgraded = false, nextId = 1;
  socket.on('connect', () => socket.write(
    `GET / HTTP/1.1\r\nHost: 127.0.0.1:${port}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n` +
    `Sec-WebSocket-Key: ${randomBytes(16).toString('base64')}\r\nSec-WebSocket-Version: 13\r\n` +
    'Sec-WebSocket-Protocol: foxglove.websocket.v1\r\n\r\n'));
  socket.on('data', (chunk) => {
    buffer = Buffer.concat([buffer, chunk]);
    if (!upgraded) {
      const end = buffer.indexOf('\r\n\r\n');
      if (end < 0) return;
      upgraded = true;
      buffer = buffer.subarray(end + 4);
    }
    const parsed = frames(buffer);
    buffer = Buffer.from(parsed.rest);
    for (const f of parsed.frames) {
      if (f.opcode !== 1) continue;
      const m = JSON.parse(f.payload.toString());
      if (m.op === 'serverInfo') state.sessionId = m.sessionId;
      if (m.op !== 'advertise') continue;
      state.topics.push(...m.channels.map((c) => c.topic));
      socket.write(maskedText(JSON.stringify({ op: 'subscribe', subscriptions: m.channels.map((c) => ({ id: nextId++, channelId: c.id })) })));
    }
    if (state.stalledAtMs === null && stallWhen(state.topics)) {
      socket.pause();  // and never resumed: nothing is read from here on
      state.stalledAtMs = Date.now();
      onStall?.(state);
    }
  });
  state.close = () => socket.destroy();
  return state;
}
