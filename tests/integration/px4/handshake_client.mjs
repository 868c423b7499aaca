// The offboard handshake against the emulated PX4, asked by a MAVLink client nobody here wrote
// (node-mavlink) over real UDP: OFFBOARD asked without the setpoint stream is refused
// (COMMAND_ACK TEMPORARILY_REJECTED, as PX4's Commander answers), and the vehicle stays out of
// OFFBOARD; after SET_ATTITUDE_TARGET streamed at 20 Hz for 1.2 s the same request is accepted and
// PX4's HEARTBEAT reports OFFBOARD (custom_mode 6 << 16). Exit 0 when both hold, 1 otherwise.
//   node handshake_client.mjs AUTOPILOT_PORT
import dgram from 'node:dgram';
import { MavLinkProtocolV2, MavLinkPacketSplitter, MavLinkPacketParser, minimal, common } from 'node-mavlink';

const port = Number(process.argv[2]);
const REGISTRY = { ...minimal.REGISTRY, ...common.REGISTRY };
const protocol = new MavLinkProtocolV2(1, 191);
const socket = dgram.createSocket('udp4');
let seq = 0;
const acks = [];
let heartbeat = null;

const splitter = new MavLinkPacketSplitter();
const parser = new MavLinkPacketParser();
splitter.pipe(parser);
parser.on('data', (p) => {
  const clazz = REGISTRY[p.header.msgid];
  if (!clazz) return;
  const m = p.protocol.data(p.payload, clazz);
  if (p.header.msgid === common.CommandAck.MSG_ID) acks.push(m);
  if (p.header.msgid === minimal.Heartbeat.MSG_ID) heartbeat = m;
});
socket.on('message', (datagram) => splitter.write(datagram));

const send = (message) => new Promise((resolve) => socket.send(protocol.serialize(message, seq++ & 255), port, '127.0.0.1', resolve));
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

function offboardRequest() {
  const c = new common.DoSetModeCommand(1, 1);
  c.mode = 1;        // MAV_MODE_FLAG_CUSTOM_MODE_ENABLED
  c.customMode = 6;  // PX4's OFFBOARD main mode
  return c;
}
function setpoint() {
  const s = new common.SetAttitudeTarget();
  s.targetSystem = 1;
  s.targetComponent = 1;
  s.typeMask = 128;  // attitude ignored: body rates and thrust
  s.q = [1, 0, 0, 0];
  s.thrust = 0;
  return s;
}
// Sends DO_SET_MODE until its COMMAND_ACK (every 250 ms, at most 3 s), returns the result.
async function askOffboard() {
  acks.length = 0;
  for (let i = 0; i < 12; i++) {
    await send(offboardRequest());
    await sleep(250);
    const ack = acks.find((a) => a.command === common.MavCmd.DO_SET_MODE);
    if (ack) return ack.result;
  }
  return null;
}

let ok = true;
const verdict = (good, text) => { console.log(`${good ? 'ok  ' : 'FAIL'} ${text}`); ok = ok && good; };
await new Promise((resolve) => socket.bind(0, '127.0.0.1', resolve));
const refused = await askOffboard();
verdict(refused === common.MavResult.TEMPORARILY_REJECTED,
  `OFFBOARD without a setpoint stream: COMMAND_ACK result ${refused} (TEMPORARILY_REJECTED is ${common.MavResult.TEMPORARILY_REJECTED})`);
await sleep(1100);  // a HEARTBEAT (1 Hz) after the refusal
verdict(heartbeat !== null && ((heartbeat.customMode >>> 16) & 0xff) !== 6,
  `PX4's HEARTBEAT after the refusal: custom_mode ${heartbeat && heartbeat.customMode}, not OFFBOARD`);
for (let i = 0; i < 24; i++) {  // 1.2 s at 20 Hz
  await send(setpoint());
  await sleep(50);
}
const accepted = await askOffboard();
verdict(accepted === common.MavResult.ACCEPTED, `OFFBOARD after 1.2 s of setpoints at 20 Hz: COMMAND_ACK result ${accepted}`);
for (let i = 0; i < 30 && !(heartbeat && ((heartbeat.customMode >>> 16) & 0xff) === 6); i++) {
  await send(setpoint());
  await sleep(50);
}
verdict(heartbeat !== null && heartbeat.customMode === 6 << 16, `PX4's HEARTBEAT then: custom_mode ${heartbeat && heartbeat.customMode} (OFFBOARD)`);
socket.close();
process.exit(ok ? 0 : 1);
