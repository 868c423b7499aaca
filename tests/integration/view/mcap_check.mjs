// Reads an MCAP file written by `sdlqr-logger export --mcap` with @mcap/core (an independent
// reader) and checks it against the LCM log it came from (read here without LCM: lib/lcmlog.mjs):
// every channel, the count and the timestamps of each channel's messages equal to the log's events,
// every CRC valid (chunks and summary by @mcap/core, the data section recomputed with
// @foxglove/crc), every message valid under its channel's schema. A negative corrupts one byte of a
// chunk and expects the CRC check to fail for that reason.
// usage: node mcap_check.mjs LOG MCAP [EXPORT_STDERR]   (with EXPORT_STDERR: the log has a torn tail)
import { readFileSync } from 'node:fs';
import { McapIndexedReader, McapStreamReader } from '@mcap/core';
import { crc32 } from '@foxglove/crc';
import { Checks, expectFailure } from './lib/checks.mjs';
import { violation } from './lib/json_schema.mjs';
import { countByChannel, readLcmLog } from './lib/lcmlog.mjs';

const [logPath, mcapPath, stderrPath] = process.argv.slice(2);
const torn = stderrPath !== undefined;
const checks = new Checks(torn ? 'view_mcap_torn_tail' : 'view_mcap_export');
const log = readLcmLog(logPath);
const bytes = new Uint8Array(readFileSync(mcapPath));
const DERIVED = /(^|\/)foxglove\/(truth_tf|estimate_tf|estimate_pose|scene)$/;

// Every record in file order, chunks opened and their CRCs checked.
function streamRecords(file) {
  const reader = new McapStreamReader({ validateCrcs: true });
  reader.append(file);
  const records = [];
  for (let r; (r = reader.nextRecord());) records.push(r);
  if (!reader.done()) throw new Error(`${reader.bytesRemaining()} bytes left unread`);
  return records;
}

function judgeCrcs(c, file) {
  let records, dataCrcOk = false, detail = '';
  try {
    records = streamRecords(file);
    const view = new DataView(file.buffer, file.byteOffset, file.byteLength);
    const footerAt = file.length - 8 - 29;
    const summaryStart = Number(view.getBigUint64(footerAt + 9, true));
    const dataEnd = summaryStart - 13;
    const stored = view.getUint32(dataEnd + 9, true);
    dataCrcOk = stored === crc32(file.subarray(0, dataEnd));
    detail = `chunk CRCs valid (${records.filter((r) => r.type === 'Message').length} messages), data section CRC ` +
      `${dataCrcOk ? 'equal' : 'DIFFERS'} (recomputed over ${dataEnd} bytes)`;
  } catch (e) {
    detail = String(e.message);
  }
  c.check('crcs_valid', records !== undefined && dataCrcOk, detail);
  return records;
}

const records = judgeCrcs(checks, bytes);
expectFailure(checks, 'chunk_byte_flipped', 'crcs_valid', 'chunk CRC', (c) => {
  const broken = bytes.slice();
  const header = Number(new DataView(broken.buffer).getBigUint64(9, true));
  const chunkAt = 8 + 9 + header;  // the record after the header: the first chunk
  broken[chunkAt + 200] ^= 0xff;    // inside its records
  judgeCrcs(c, broken);
});

const reader = await McapIndexedReader.Initialize({
  readable: {
    size: async () => BigInt(bytes.length),
    read: async (offset, length) => bytes.subarray(Number(offset), Number(offset + length)),
  },
});
checks.check('indexed', reader.chunkIndexes.length >= 2 && reader.statistics !== undefined,
  `${reader.chunkIndexes.length} chunks indexed, summary CRC valid, statistics: ${reader.statistics?.messageCount} messages`);

// Per channel: the log's events against the MCAP's messages, read through the indexes.
const logCounts = countByChannel(log.events);
const logTimes = new Map();
for (const e of log.events) (logTimes.get(e.channel) ?? logTimes.set(e.channel, []).get(e.channel)).push(e.utime * 1000n);
const mcapTimes = new Map();
const invalid = [];
const schemas = new Map();
for (const [id, ch] of reader.channelsById) {
  const schema = reader.schemasById.get(ch.schemaId);
  schemas.set(id, schema ? JSON.parse(new TextDecoder().decode(schema.data)) : null);
}
const decoder = new TextDecoder();
const validated = new Map();  // per channel: its first 50 messages and every 20th after them
for await (const m of reader.readMessages({ validateCrcs: true })) {
  const topic = reader.channelsById.get(m.channelId).topic;
  const times = mcapTimes.get(topic) ?? mcapTimes.set(topic, []).get(topic);
  times.push(m.logTime);
  const schema = schemas.get(m.channelId);
  if (schema && invalid.length < 5 && (times.length <= 50 || times.length % 20 === 0)) {
    validated.set(topic, (validated.get(topic) ?? 0) + 1);
    const v = violation(JSON.parse(decoder.decode(m.data)), schema);
    if (v) invalid.push(`${topic}: ${v}`);
  }
}
const lcmTopics = [...mcapTimes.keys()].filter((t) => !DERIVED.test(t));
const vehicles = new Set([...logCounts.keys()].filter((c) => c.endsWith('SIM_TRUTH')).map((c) => c.replace(/\/?SIM_TRUTH$/, '')));
const derivedMissing = [...vehicles].flatMap((v) => ['truth_tf', 'estimate_tf', 'estimate_pose', 'scene']
  .map((n) => `${v ? `${v}/` : ''}foxglove/${n}`)).filter((t) => !mcapTimes.has(t));
const absent = [...logCounts.keys()].filter((c) => !mcapTimes.has(c));
checks.check('every_channel', absent.length === 0 && lcmTopics.length === logCounts.size && derivedMissing.length === 0,
  `${logCounts.size} channels of the log, ${lcmTopics.length} in the MCAP file, Foxglove poses of ${vehicles.size} vehicle(s)` +
  (absent.length || derivedMissing.length ? `; absent: ${[...absent, ...derivedMissing].join(', ')}` : ''));
const countDiffs = [...logCounts].filter(([c, n]) => (mcapTimes.get(c)?.length ?? 0) !== n ||
  Number(reader.statistics.channelMessageCounts.get([...reader.channelsById].find(([, ch]) => ch.topic === c)?.[0]) ?? -1) !== n);
checks.check('counts_equal_log', countDiffs.length === 0, countDiffs.length
  ? countDiffs.slice(0, 3).map(([c, n]) => `${c}: log ${n}, mcap ${mcapTimes.get(c)?.length ?? 0}`).join('; ')
  : `${log.events.length} events, message for message (statistics agree)`);
const sorted = (a) => [...a].sort((x, y) => (x < y ? -1 : x > y ? 1 : 0));
const timeDiffs = [...logTimes].filter(([c, t]) => JSON.stringify(sorted(t).map(String)) !== JSON.stringify(sorted(mcapTimes.get(c) ?? []).map(String)));
checks.check('timestamps_equal_log', timeDiffs.length === 0, timeDiffs.length ? `differ: ${timeDiffs.map(([c]) => c).join(', ')}`
  : 'every message\'s log time is its event\'s receive time');
// In file order the messages follow the log's events one for one.
const fileOrder = records.filter((r) => r.type === 'Message').map((r) => r.channelId)
  .map((id) => reader.channelsById.get(id).topic).filter((t) => !DERIVED.test(t));
const orderOk = fileOrder.length === log.events.length && fileOrder.every((t, i) => t === log.events[i].channel);
checks.check('log_order', orderOk, orderOk ? 'the file holds the events in the log\'s order' : 'the order differs from the log');
const sampled = [...validated.values()].reduce((a, b) => a + b, 0);
checks.check('messages_valid', invalid.length === 0 && validated.size === [...schemas.values()].filter(Boolean).length,
  invalid.length ? invalid.join('; ') : `${sampled} messages of ${validated.size} channels (the first 50 of each, then every 20th) ` +
  'valid under their channel\'s JSON Schema');

if (torn) {
  const stderr = readFileSync(stderrPath, 'utf8');
  const said = stderr.match(/ends in a truncated event: (\d+) bytes after byte (\d+)/);
  checks.check('says_what_it_dropped', log.tornBytes > 0 && said !== null && Number(said[1]) === log.tornBytes &&
    Number(said[2]) === log.wholeBytes, said ? `export said: ${said[0]}; the log's torn tail is ${log.tornBytes} bytes after byte ${log.wholeBytes}`
    : `no warning naming the torn tail in: ${stderr.trim().split('\n').pop()}`);
}
process.exit(checks.exitCode());
