// Judges what view_live.mjs saw against the flight's log (its CSV export, an independent path:
// sdlqr-logger export), check by check; each criterion has a negative that shows it can fail.
// usage: node view_judge.mjs WORK_DIR VEHICLE
import { existsSync, readFileSync, statSync } from 'node:fs';
import { Checks, expectFailure } from './lib/checks.mjs';
import { messageKey, readExportCsv, rowDifference } from './lib/csv.mjs';
import { violation } from './lib/json_schema.mjs';
import { describe, poseErrors } from './lib/pose.mjs';
import { readLcmLog } from './lib/lcmlog.mjs';
import foxgloveSchemas from '@foxglove/schemas/jsonschema.js';

const [work, vehicle] = process.argv.slice(2);
const obs = JSON.parse(readFileSync(`${work}/observations.json`, 'utf8'));
const prefix = vehicle ? `${vehicle}/` : '';
const csvOf = (base) => readExportCsv(`${work}/csv/${prefix}${base}.csv`);
const truthCsv = csvOf('SIM_TRUTH');
const estimateCsv = csvOf('STATE_EST');
const checks = new Checks('view_live_flight');

// The page: every criterion of what it draws, from its samples during the flight.
// `drained`: the page after the flight, once it has drawn all that reached it (a loaded page draws
// seconds behind the flight; the overlays are judged on the whole flight it drew).
function judgePage(c, samples, errors, drained) {
  const last = samples[samples.length - 1]?.state;
  c.check('page_connected', samples.length > 0 && samples.every((s) => s.state.connected) && last.messages > 0,
    `${samples.length} samples, ${last?.messages ?? 0} messages, WebGL2 ${last?.webgl2}`);
  c.check('page_no_errors', errors.length === 0, errors.length ? errors.slice(0, 3).join(' | ') : 'no JavaScript error');
  c.check('schema', last && last.schemaErrors.length === 0 && last.dataErrors.length === 0,
    last ? [...last.schemaErrors, ...last.dataErrors].join('; ') || 'every drawn channel fits its schema' : 'no sample');
  c.check('vehicles_shown', last && vehicle in last.vehicles && last.vehicles[vehicle].truth !== null,
    `vehicles drawn: ${last ? Object.keys(last.vehicles).map((v) => v || '(none)').join(', ') : '-'}`);
  const flying = samples.filter((s) => s.state.vehicles[vehicle]?.truth);
  for (const [key, csv, name] of [['truth', truthCsv, 'pose_within_1cm_1deg'], ['estimate', estimateCsv, 'estimate_within_1cm_1deg']]) {
    const e = poseErrors(flying.map((s) => s.state), csv, vehicle, key);
    c.check(name, flying.length >= 10 && e.matched >= 0.8 * flying.length && e.span >= 0.3 && e.maxDistance <= 0.01 && e.maxAngle <= 1,
      `${e.matched} of ${flying.length} sampled instants found in the log (${key}), ${describe(e)}; ` +
      `sampled poses span ${e.span.toFixed(2)} m`);
  }
  const first = flying[0]?.state.charts, end = last?.charts;
  const stalled = first ? Object.entries(end).filter(([n, ch]) => !(ch.points > first[n].points && ch.lastT > first[n].lastT)) : ['all'];
  c.check('charts_update', first && stalled.length === 0,
    first ? Object.entries(end).map(([n, ch]) => `${n} ${first[n].points}->${ch.points} points`).join(', ') : 'no flying sample');
  const overlays = flying.map((s) => s.state.vehicles[vehicle]);
  const lastV = drained?.vehicles[vehicle] ?? overlays[overlays.length - 1];
  c.check('scene_overlays', lastV && lastV.truthTrailPoints > 10 && lastV.estimateTrailPoints > 10 && lastV.reference !== null &&
    lastV.forceDrawn > 0, lastV ? `trails ${lastV.truthTrailPoints}/${lastV.estimateTrailPoints} points, ` +
    `reference ${lastV.reference ? 'shown' : 'absent'}, disturbance drawn with ${lastV.forceDrawn} poses` : 'none');
}

judgePage(checks, obs.pageSamples, obs.pageErrors, obs.afterFlight.state);
expectFailure(checks, 'wrong_schema_page', 'schema', 'sim_truth_t.position',
  (c) => judgePage(c, [{ state: obs.wrongSchemaPage.state }], obs.wrongSchemaPage.errors));
expectFailure(checks, 'pose_off_by_2cm', 'pose_within_1cm_1deg', 'largest error 2.0', (c) => judgePage(c,
  obs.pageSamples.map((s) => {
    const moved = structuredClone(s);
    const t = moved.state.vehicles[vehicle]?.truth;
    if (t) t.position[2] += 0.02;
    return moved;
  }), obs.pageErrors));

// Process health from HEARTBEAT: every process that beat in the flight has its row.
const heartbeats = csvOf('HEARTBEAT');
const beat = new Set(heartbeats.rows.map((r) => r[heartbeats.column('process')]));
const lastSample = obs.pageSamples[obs.pageSamples.length - 1].state;
const shown = new Set(lastSample.health.filter((h) => h.vehicle === vehicle).map((h) => h.process));
const missing = [...beat].filter((p) => !shown.has(p));
checks.check('health_rows', beat.size >= 6 && missing.length === 0, `${shown.size} processes shown of ${beat.size} that beat` +
  (missing.length ? `; missing ${missing.join(', ')}` : ''));

// And alive: at each sampled instant, every process whose HEARTBEAT the recorder received in the
// 2 s before (log events, zipped with the CSV rows they became) should be shown with a beat under
// 2.5 s old. The page of a loaded machine draws late: the beats expected are those received 200 ms
// before the page's own data horizon at that instant, the recorder's receive time of the SIM_TRUTH
// it shows (measured in this run, so a stalled page is judged on what reached it, a lost beat not).
// A process whose beats the view loses is shown silent at most instants: each at most 10 % of its.
const logEvents = readLcmLog(`${work}/flight.lcmlog`).events;
const truthEvents = logEvents.filter((e) => e.channel === `${prefix}SIM_TRUTH`);
const truthReceivedMs = new Map(truthEvents.map((e, i) => [Number(truthCsv.rows[i][truthCsv.column('utime')]), Number(e.utime / 1000n)]));
function judgeAlive(c, samples) {
  const events = logEvents.filter((e) => e.channel === `${prefix}HEARTBEAT`);
  const beats = events.map((e, i) => ({ atMs: Number(e.utime / 1000n), process: heartbeats.rows[i][heartbeats.column('process')] }));
  const looked = new Map(), silent = new Map();
  let largestLagMs = 0;
  for (const s of samples) {
    const shownAtMs = truthReceivedMs.get(Number(s.state.vehicles[vehicle]?.truth?.utime));
    const horizonMs = shownAtMs === undefined ? s.atMs : Math.min(s.atMs, shownAtMs);
    largestLagMs = Math.max(largestLagMs, s.atMs - horizonMs);
    const recent = new Set(beats.filter((b) => b.atMs > s.atMs - 2000 && b.atMs < horizonMs - 200).map((b) => b.process));
    for (const p of recent) {
      looked.set(p, (looked.get(p) ?? 0) + 1);
      const row = s.state.health.find((h) => h.vehicle === vehicle && h.process === p);
      if (!row || row.ageMs > 2500) silent.set(p, (silent.get(p) ?? 0) + 1);
    }
  }
  const worst = [...looked].map(([p, n]) => [p, (silent.get(p) ?? 0) / n]).sort((a, b) => b[1] - a[1]);
  c.check('health_alive', events.length === heartbeats.rows.length && truthEvents.length === truthCsv.rows.length &&
    looked.size >= 6 && worst[0][1] <= 0.1,
    `${looked.size} processes looked at ${[...looked.values()].reduce((a, b) => a + b, 0)} times after they beat ` +
    `(the page's data up to ${largestLagMs} ms behind); ` +
    `shown silent the most: ${worst.slice(0, 2).map(([p, f]) => `${p} ${(100 * f).toFixed(0)} %`).join(', ')}`);
}
judgeAlive(checks, obs.pageSamples);
expectFailure(checks, 'heartbeats_of_one_process_lost', 'health_alive', 'sdlqr-gains 100 %', (c) => judgeAlive(c,
  obs.pageSamples.map((s) => ({ ...s, state: { ...s.state, health: s.state.health.filter((h) => h.process !== 'sdlqr-gains') } }))));

const png = `${work}/view.png`;
const pngOk = existsSync(png) && readFileSync(png).subarray(0, 8).equals(Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]));
checks.check('screenshot', pngOk && statSync(png).size > 20000, pngOk ? `${png}, ${statSync(png).size} bytes` : 'no PNG written');

// Bus silent after the flight: the page shows the stream stale within 1 s of its last message.
const after = obs.afterFlight;
checks.check('stale_within_1s', after.staleSeenAtMs !== undefined && after.state.staleShownAfterMs <= 1000 &&
  after.state.statusText.startsWith('STALE'), after.staleSeenAtMs === undefined ? 'never shown stale (its message count still for 3 s)'
  : `shown stale ${after.state.staleShownAfterMs.toFixed(0)} ms after its last message ("${after.state.statusText}" when ` +
    `looked at, ${after.staleSeenAtMs - after.doneAtMs} ms after the launcher exited)`);

// Foxglove's own client: channels, schemas, values.
function judgeFoxglove(c, foxglove) {
  const log = readLcmLog(`${work}/flight.lcmlog`);
  const logged = new Set(log.events.map((e) => e.channel));
  const advertised = new Map(foxglove.channels.map((ch) => [ch.topic, ch]));
  const derived = ['truth_tf', 'estimate_tf', 'estimate_pose', 'scene'].map((n) => `${prefix}foxglove/${n}`);
  const absent = [...logged, ...derived].filter((t) => !advertised.has(t));
  c.check('foxglove_channels', absent.length === 0 && foxglove.serverInfo?.name === 'sdlqr-view',
    `${advertised.size} channels advertised; the log's ${logged.size} and ${derived.length} Foxglove ones` + (absent.length ? `; absent: ${absent.join(', ')}` : ''));
  const npmName = { 'foxglove.FrameTransform': 'FrameTransform', 'foxglove.PoseInFrame': 'PoseInFrame', 'foxglove.SceneUpdate': 'SceneUpdate' };
  const drift = foxglove.channels.filter((ch) => npmName[ch.schemaName] &&
    JSON.stringify(JSON.parse(ch.schema)) !== JSON.stringify(foxgloveSchemas[npmName[ch.schemaName]]));
  c.check('foxglove_schemas_are_foxgloves', drift.length === 0 && foxglove.channels.some((ch) => npmName[ch.schemaName]),
    drift.length ? `differ from @foxglove/schemas: ${drift.map((d) => d.topic).join(', ')}` : 'FrameTransform, PoseInFrame, SceneUpdate equal @foxglove/schemas');
  // Messages the view heard before the recorder started or after it stopped are not in the log.
  const [firstNs, lastNs] = [log.events[0].utime * 1000n, log.events[log.events.length - 1].utime * 1000n];
  let compared = 0, outside = 0, invalid = [], differing = [], channelsCompared = 0;
  for (const [topic, kept] of Object.entries(foxglove.messages)) {
    const ch = advertised.get(topic);
    const schema = JSON.parse(ch.schema);
    for (const m of kept) { const v = violation(m.value, schema); if (v) invalid.push(`${topic} ${v}`); }
    if (!ch.schemaName.startsWith('sdlqr.')) continue;
    const csv = readExportCsv(`${work}/csv/${topic}.csv`);
    channelsCompared += 1;
    for (const m of kept) {
      if (BigInt(m.timestampNs) < firstNs || BigInt(m.timestampNs) > lastNs) { outside += 1; continue; }
      const row = csv.byKey.get(messageKey(m.value));
      const d = row ? rowDifference(csv, row, m.value) : 'not in the log';
      compared += 1;
      if (d) differing.push(`${topic} seq ${m.value.seq}: ${d}`);
    }
  }
  c.check('foxglove_messages_valid', invalid.length === 0 && compared > 0, invalid.length ? invalid.slice(0, 3).join('; ') : 'every kept message valid under its advertised schema');
  c.check('foxglove_values_match_log', differing.length === 0 && channelsCompared === logged.size && compared >= 100,
    `${compared} messages of ${channelsCompared} channels compared field by field with the CSV export ` +
    `(${outside} heard outside the recording)` +
    (differing.length ? `; differ: ${differing.slice(0, 3).join('; ')}` : ''));
  const tf = foxglove.messages[`${prefix}foxglove/truth_tf`] ?? [];
  const truthRows = new Set(truthCsv.rows.map((r) => [0, 1, 2].map((i) => r[truthCsv.column(`position[${i}]`)]).map(Number).join(',')));
  const unmatched = tf.filter((m) => !truthRows.has([m.value.translation.x, m.value.translation.y, m.value.translation.z].join(',')));
  c.check('foxglove_transform_is_truth', tf.length > 0 && unmatched.length === 0, `${tf.length} FrameTransforms, ${unmatched.length} not at a logged SIM_TRUTH position`);
}

judgeFoxglove(checks, obs.foxglove);
expectFailure(checks, 'foxglove_value_changed', 'foxglove_values_match_log', 'csv', (c) => {
  const changed = structuredClone(obs.foxglove);
  changed.messages[`${prefix}STATE_EST`][3].value.velocity[1] += 1e-9;
  judgeFoxglove(c, changed);
});

// A client that stopped reading: once its connection is backlogged it gets no frame, the server
// holds at most its bound (plus a frame) for it, and the server's memory stays flat; the same
// client of a view without the bound (--max-client-buffer of a GiB) shows the opposite.
function judgeSlowClient(c, observed, bound) {
  const windowed = observed.stats.filter((s) => observed.stalledAtMs !== null && s.atMs >= observed.stalledAtMs);
  const [first, last] = [windowed[0], windowed[windowed.length - 1]];
  if (!first || last.atMs - first.atMs < 3000) {
    c.check('slow_client_costs_frames', false, `${windowed.length} /api/stats samples after the stall: too few`);
    return;
  }
  const id = observed.sessionId;
  const tail = windowed.filter((s) => s.atMs >= last.atMs - 3000);
  const tailSeconds = (last.atMs - tail[0].atMs) / 1000;
  const delta = (key) => last.stats.hub.clients[id][key] - tail[0].stats.hub.clients[id][key];
  const [skipped, sent] = [delta('frames_skipped'), delta('frames_sent')];
  const held = last.stats.hub.clients[id].max_buffered_bytes;
  c.check('slow_client_costs_frames', skipped > 0 && sent === 0 && held <= bound + FRAME_ALLOWANCE,
    `in its last ${tailSeconds.toFixed(1)} s stalled ${skipped} frames skipped, ${sent} sent; the most held unsent for it: ` +
    `${(held / 1024).toFixed(0)} KiB (bound ${(bound / 1024).toFixed(0)} KiB)`);
  const growth = last.stats.resident_bytes - first.stats.resident_bytes;
  c.check('slow_client_costs_no_memory', growth <= 2 * (1 << 20),
    `resident memory ${(first.stats.resident_bytes / 1048576).toFixed(1)} -> ${(last.stats.resident_bytes / 1048576).toFixed(1)} MiB ` +
    `over ${((last.atMs - first.atMs) / 1000).toFixed(1)} s stalled`);
  const rates = Object.entries(last.stats.hub.clients).filter(([k]) => first.stats.hub.clients[k] && k !== id)
    .map(([k, cl]) => (cl.frames_sent - first.stats.hub.clients[k].frames_sent) / ((last.atMs - first.atMs) / 1000));
  c.check('rate_cap_60', rates.length >= 2 && Math.max(...rates) <= 60.5,
    `frames a second of each reading client meanwhile: ${rates.map((r) => r.toFixed(1)).join(', ')}`);
}

const BOUND = 128 * 1024;  // view_flight.sh: sdlqr-view --max-client-buffer 128 (KiB)
const FRAME_ALLOWANCE = 256 * 1024;  // the bound is checked before a frame, which may then exceed it
judgeSlowClient(checks, obs.stalled, BOUND);
expectFailure(checks, 'unbounded_view', 'slow_client_costs_frames', 'held unsent', (c) => judgeSlowClient(c, obs.unbounded, BOUND));
const unboundedLast = obs.unbounded.stats[obs.unbounded.stats.length - 1].stats;
checks.report(`without the bound the stalled client held ${(unboundedLast.hub.clients[obs.unbounded.sessionId].max_buffered_bytes / 1048576).toFixed(1)} MiB ` +
  `unsent; that view's resident memory ${(obs.unbounded.stats[0].stats.resident_bytes / 1048576).toFixed(1)} -> ${(unboundedLast.resident_bytes / 1048576).toFixed(1)} MiB`);

// Reported, not judged: the view's CPU and the flight's deadline misses.
const cpu = existsSync(`${work}/view_cpu.txt`) ? readFileSync(`${work}/view_cpu.txt`, 'utf8').trim() : 'not measured';
const misses = new Map();
for (const r of heartbeats.rows) misses.set(r[heartbeats.column('process')], Number(r[heartbeats.column('deadline_misses')]));
checks.report(`sdlqr-view CPU over the flight: ${cpu}; Chromium (page rendering) ${obs.cpu.browserSeconds.toFixed(2)} CPU-s ` +
  `in ${obs.cpu.wallSeconds.toFixed(1)} s (${(100 * obs.cpu.browserSeconds / obs.cpu.wallSeconds).toFixed(0)} % of a core)`);
checks.report(`deadline misses with a browser connected (last HEARTBEAT): ${[...misses].map(([p, n]) => `${p} ${n}`).join(', ')}`);
process.exit(checks.exitCode());
