// Our MAVLink 2 framing checked byte for byte, both ways, against node-mavlink + mavlink-mappings
// (ArduPilot/node-mavlink, an implementation nobody here wrote; pinned in package-lock.json):
//   ours -> node   every frame the bridge and the emulator can send (mavlink_vectors frames): node's
//                  splitter accepts it (its CRC), its parser decodes every field to our value, a
//                  signed frame's signature matches the key in node's own check, and node encoding
//                  the same fields (and signing them) writes the very same bytes
//   node -> ours   node encodes every message with values of its own choosing, some signed; our
//                  parser (mavlink_vectors decode) accepts them and decodes every field to node's
//                  value; a frame node signs with another key is refused (bad_signature)
// The one documented difference: node trims an all-zero payload to 0 bytes, the C library (and we)
// keep one (mavlink_helpers.h _mav_trim_payload); both decode both.
//   node node_mavlink_check.mjs MAVLINK_VECTORS
import { spawnSync } from 'node:child_process';
import { MavLinkProtocolV2, MavLinkPacketSplitter, MavLinkPacketParser, minimal, common } from 'node-mavlink';

const tool = process.argv[2];
const REGISTRY = { ...minimal.REGISTRY, ...common.REGISTRY };
let failures = 0;
let checks = 0;
const fail = (text) => { failures++; console.log(`FAIL ${text}`); };
const check = (condition, text) => { checks++; if (!condition) fail(text); return condition; };

function runTool(args, input) {
  const r = spawnSync(tool, args, { input, encoding: 'utf8' });
  if (r.status !== 0) throw new Error(`${tool} ${args.join(' ')} exited ${r.status}: ${r.stderr}`);
  return r.stdout.trim().split('\n').filter((l) => l.length > 0).map((l) => JSON.parse(l));
}

// node-mavlink's own splitter (CRC check) and parser.
function parseWithNode(buffer) {
  return new Promise((resolve) => {
    const packets = [];
    let crcErrors = 0;
    const splitter = new MavLinkPacketSplitter({}, { onCrcError: () => { crcErrors++; } });
    const parser = new MavLinkPacketParser();
    splitter.pipe(parser);
    parser.on('data', (p) => packets.push(p));
    parser.on('end', () => resolve({ packets, crcErrors }));
    splitter.end(buffer);
  });
}

const isFloat = (type) => type.startsWith('float') || type.startsWith('double');
const is64 = (type) => type.startsWith('uint64') || type.startsWith('int64');
function same(type, ours, theirs) {
  if (is64(type)) return BigInt(ours) === BigInt(theirs);
  if (isFloat(type)) return Math.fround(Number(ours)) === Math.fround(Number(theirs));
  return Number(ours) === Number(theirs);
}
function fieldsEqual(clazz, ours, theirs, where) {
  let ok = true;
  for (const f of clazz.FIELDS) {
    const a = ours[f.source];
    const b = theirs[f.name];
    const equal = f.length ? a.length === f.length && a.every((v, i) => same(f.type, v, b[i])) : same(f.type, a, b);
    if (!equal) {
      fail(`${where}: field ${f.source}: ours ${JSON.stringify(a)}, node-mavlink ${String(b)}`);
      ok = false;
    }
  }
  return ok;
}
function messageOf(clazz, values) {
  const m = new clazz();
  for (const f of clazz.FIELDS) {
    const v = values[f.source];
    const convert = (x) => (is64(f.type) ? BigInt(x) : Number(x));
    m[f.name] = f.length ? v.map(convert) : convert(v);
  }
  return m;
}
function nodeFrame(clazz, values, { sysid, compid, seq, key, linkId, timestamp }) {
  const flags = key ? MavLinkProtocolV2.IFLAG_SIGNED : 0;
  const protocol = new MavLinkProtocolV2(sysid, compid, flags);
  const frame = protocol.serialize(messageOf(clazz, values), seq);
  if (!key) return frame;
  // node-mavlink signs at millisecond resolution: (ms - 2015-01-01) * 100 in 10 us units.
  return protocol.sign(frame, linkId, key, MavLinkProtocolV2.SIGNATURE_START_TIME + timestamp / 100);
}

async function oursToNode() {
  const frames = runTool(['frames']);
  check(frames.length >= 10, `mavlink_vectors wrote ${frames.length} frames`);
  for (const f of frames) {
    const where = `${f.name}${f.signed ? ' (signed)' : ''}`;
    const clazz = REGISTRY[f.msgid];
    if (!check(clazz !== undefined, `${where}: node-mavlink knows message ${f.msgid}`)) continue;
    const bytes = Buffer.from(f.hex, 'hex');
    const { packets, crcErrors } = await parseWithNode(bytes);
    if (!check(packets.length === 1 && crcErrors === 0, `${where}: node-mavlink's splitter takes our frame (CRC)`)) continue;
    const p = packets[0];
    check(p.header.msgid === f.msgid && p.header.seq === f.seq && p.header.sysid === f.sysid &&
          p.header.compid === f.compid, `${where}: header as ours`);
    if (f.signed) {
      const key = Buffer.from(f.key, 'hex');
      check(p.signature !== null && p.signature.matches(key), `${where}: node-mavlink verifies our signature`);
      check(p.signature.linkId === f.link_id && p.signature.timestamp === f.timestamp, `${where}: link id, timestamp`);
    }
    checks++;
    fieldsEqual(clazz, f.fields, p.protocol.data(p.payload, clazz), `${where} decoded by node-mavlink`);
    const again = nodeFrame(clazz, f.fields, {
      sysid: f.sysid, compid: f.compid, seq: f.seq,
      key: f.signed ? Buffer.from(f.key, 'hex') : null, linkId: f.link_id, timestamp: f.timestamp,
    });
    check(again.toString('hex') === f.hex, `${where}: node-mavlink encodes the same fields to our bytes\n  ours ${f.hex}\n  node ${again.toString('hex')}`);
  }
  console.log(`ours -> node: ${frames.length} frames`);
  return frames;
}

// Values of node's choosing, per field type.
function nodeValues(clazz, salt) {
  const values = {};
  let k = salt;
  const next = (type) => {
    k += 1;
    if (is64(type)) return String(9000000000000000n + BigInt(k));
    if (isFloat(type)) return Math.fround(k * 1.125 - 11.5);
    if (type.startsWith('int')) return -((k * 3) % 100);
    return (k * 5) % 250 + 1;
  };
  for (const f of clazz.FIELDS) values[f.source] = f.length ? Array.from({ length: f.length }, () => next(f.type)) : next(f.type);
  return values;
}

function nodeToOurs(ourFrames) {
  const ids = [...new Set(ourFrames.map((f) => f.msgid))];
  const key = Buffer.from(ourFrames.find((f) => f.signed).key, 'hex');
  const timestamp = ourFrames.find((f) => f.signed).timestamp;
  const cases = [];
  ids.forEach((id, i) => {
    const clazz = REGISTRY[id];
    cases.push({ clazz, values: nodeValues(clazz, 40 + 13 * i), seq: i, signed: false });
    cases.push({ clazz, values: nodeValues(clazz, 90 + 17 * i), seq: 100 + i, signed: true });
  });
  for (const signed of [false, true]) {
    const chosen = cases.filter((c) => c.signed === signed);
    const hexes = chosen.map((c) => nodeFrame(c.clazz, c.values, {
      sysid: 1, compid: 1, seq: c.seq, key: signed ? key : null, linkId: 5, timestamp,
    }).toString('hex'));
    const decoded = runTool(signed ? ['decode', key.toString('hex')] : ['decode'], `${hexes.join('\n')}\n`);
    chosen.forEach((c, i) => {
      const where = `${c.clazz.MSG_NAME}${signed ? ' (signed)' : ''} from node-mavlink`;
      const d = decoded[i];
      if (!check(d && !d.error, `${where}: our parser takes it (${d && d.error})`)) return;
      check(d.msgid === c.clazz.MSG_ID && d.seq === c.seq && d.signed === signed, `${where}: header`);
      checks++;
      fieldsEqual(c.clazz, d.fields, messageOf(c.clazz, c.values), `${where} decoded by ours`);
    });
  }
  // Signed with another key: our parser refuses it.
  const wrong = Buffer.alloc(32, 7);
  const forged = nodeFrame(common.Odometry, nodeValues(common.Odometry, 3), { sysid: 1, compid: 1, seq: 9, key: wrong, linkId: 5, timestamp });
  const refused = runTool(['decode', key.toString('hex')], `${forged.toString('hex')}\n`)[0];
  check(refused.error && refused.error.includes('bad_signature'), `a frame node-mavlink signed with another key is refused: ${JSON.stringify(refused)}`);
  console.log(`node -> ours: ${cases.length} frames, and one signed with the wrong key`);
}

const frames = await oursToNode();
nodeToOurs(frames);
console.log(`${checks} checks, ${failures} failed`);
process.exit(failures === 0 && checks > 0 ? 0 : 1);
