// A minimal client of Foxglove's WebSocket protocol (foxglove.websocket.v1), the one sdlqr-view
// speaks: serverInfo, advertise, unadvertise and status as JSON text; Message Data as binary
// frames (opcode 0x01, uint32 subscription id, uint64 timestamp [ns], little-endian, then the
// message's JSON). Reconnects every second while the server is away.

export const SUBPROTOCOL = 'foxglove.websocket.v1';

export class FoxgloveConnection {
  // handlers: serverInfo(info), advertise(channels), unadvertise(ids), status(message),
  // message(channel, timestampNs, value), connection(connected)
  constructor(url, handlers) {
    this.url = url;
    this.handlers = handlers;
    this.channels = new Map();       // channel id -> advertised channel
    this.subscriptions = new Map();  // subscription id -> channel id
    this.nextSubscription = 1;
    this.decoder = new TextDecoder();
    this.framesReceived = 0;
    this.connect();
  }

  connect() {
    this.ws = new WebSocket(this.url, [SUBPROTOCOL]);
    this.ws.binaryType = 'arraybuffer';
    this.ws.onopen = () => this.handlers.connection(true);
    this.ws.onclose = () => {
      this.channels.clear();
      this.subscriptions.clear();
      this.handlers.connection(false);
      setTimeout(() => this.connect(), 1000);
    };
    this.ws.onmessage = (event) => {
      if (typeof event.data === 'string') this.onText(JSON.parse(event.data));
      else this.onBinary(new DataView(event.data));
    };
  }

  onText(message) {
    if (message.op === 'serverInfo') this.handlers.serverInfo(message);
    else if (message.op === 'advertise') {
      for (const channel of message.channels) this.channels.set(channel.id, channel);
      this.handlers.advertise(message.channels);
    } else if (message.op === 'unadvertise') {
      for (const id of message.channelIds) this.channels.delete(id);
      this.handlers.unadvertise(message.channelIds);
    } else if (message.op === 'status') this.handlers.status(message);
  }

  onBinary(view) {
    if (view.getUint8(0) !== 0x01) return;  // only Message Data is expected
    this.framesReceived += 1;
    const channel = this.channels.get(this.subscriptions.get(view.getUint32(1, true)));
    if (!channel) return;
    const timestamp = view.getBigUint64(5, true);
    const text = this.decoder.decode(new Uint8Array(view.buffer, view.byteOffset + 13, view.byteLength - 13));
    this.handlers.message(channel, timestamp, JSON.parse(text));
  }

  subscribe(channelId) {
    const id = this.nextSubscription++;
    this.subscriptions.set(id, channelId);
    this.ws.send(JSON.stringify({ op: 'subscribe', subscriptions: [{ id, channelId }] }));
  }
}
