// sdlqr-view's page: connects to the server's WebSocket (Foxglove's protocol), subscribes to what
// it draws for every vehicle (channel prefix), checks each channel's schema first, and shows the
// 3D scene, the strip charts and each process's health. The same page plays a log (the server
// says so in serverInfo): then it shows play, pause, speed and seek. window.sdlqrView.state()
// tells a test what is drawn (tests/integration/view).
import { FoxgloveConnection } from './foxglove_client.js';
import { checkMessage, checkSchema } from './schema_check.js';
import { SceneView } from './scene.js';
import { StripChart } from './charts.js';

const STALE_MS = 500;              // no message for this long: the stream is shown stale
const HEARTBEAT_SILENT_MS = 2500;  // a process without a HEARTBEAT this long: SILENT (as sdlqr-top)
const DRAWN = ['SIM_TRUTH', 'STATE_EST', 'REFERENCE', 'TRAJECTORY', 'RATE_CMD', 'GAINS', 'HEARTBEAT'];
const STATES = ['STARTING', 'RUNNING', 'DEGRADED', 'FAILSAFE', 'STOPPING'];

const $ = (id) => document.getElementById(id);
const scene = new SceneView($('scene'));
const axes = [['x', '#d62728'], ['y', '#2ca02c'], ['z', '#1f77b4']];
const charts = {
  position_error: new StripChart($('chart-error'), 'position error, reference - truth', 'm',
    axes.map(([n, c]) => ({ name: n, color: c }))),
  body_rates: new StripChart($('chart-rates'), 'body rates, commanded and measured (dashed)', 'rad/s', [
    ...axes.map(([n, c]) => ({ name: n, color: c })),
    ...axes.map(([, c]) => ({ name: '', color: c, dash: true }))]),
  thrust: new StripChart($('chart-thrust'), 'collective thrust', 'm/s²', [
    { name: 'commanded', color: '#ff7f0e' }, { name: 'demanded', color: '#7f7f7f', dash: true }]),
  solve_time: new StripChart($('chart-solve'), 'gain solve time', 'µs', [{ name: 'solve', color: '#9467bd' }]),
};

const page = {
  connected: false, source: null, serverInfo: null, messages: 0, lastMessageMs: null, staleSinceMs: null,
  staleShownAfterMs: null, schemaErrors: [], dataErrors: [], status: [], vehicles: new Set(), chartVehicle: null,
  health: new Map(),
  reference: new Map(), playback: null, rejected: new Set(),
};

// "QUAD1/SIM_TRUTH" -> ["QUAD1", "SIM_TRUTH"]; "SIM_TRUTH" -> ["", "SIM_TRUTH"]
function splitTopic(topic) {
  const slash = topic.lastIndexOf('/');
  return slash < 0 ? ['', topic] : [topic.slice(0, slash), topic.slice(slash + 1)];
}
const typeName = (channel) => channel.schemaName.replace(/^sdlqr\./, '');

function onAdvertise(channels) {
  for (const channel of channels) {
    if (channel.topic === 'sdlqr/playback') { connection.subscribe(channel.id); continue; }
    const [vehicle, base] = splitTopic(channel.topic);
    if (!DRAWN.includes(base)) continue;
    const errors = checkSchema(typeName(channel), channel.schema);
    if (errors.length) {  // drawn from nothing rather than from the wrong numbers
      page.schemaErrors.push(...errors.map((e) => `${channel.topic}: ${e}`));
      page.rejected.add(channel.topic);
      showErrors();
      continue;
    }
    if (base === 'SIM_TRUTH' && !page.vehicles.has(vehicle)) addVehicle(vehicle);
    connection.subscribe(channel.id);
  }
}

function addVehicle(name) {
  page.vehicles.add(name);
  const option = document.createElement('option');
  option.value = name;
  option.textContent = name || '(no prefix)';
  $('vehicle').appendChild(option);
  if (page.chartVehicle === null) selectVehicle(name);
}

function selectVehicle(name) {
  page.chartVehicle = name;
  $('vehicle').value = name;
  scene.follow(name);
  for (const chart of Object.values(charts)) chart.clear();
}

function onMessage(channel, timestampNs, m) {
  page.messages += 1;
  page.lastMessageMs = performance.now();
  if (channel.topic === 'sdlqr/playback') { page.playback = m; showPlayback(); return; }
  const [vehicle, base] = splitTopic(channel.topic);
  const bad = checkMessage(typeName(channel), m);
  if (bad) {
    if (page.dataErrors.length < 20) page.dataErrors.push(`${channel.topic}: ${bad} has the wrong shape`);
    showErrors();
    return;
  }
  const t = m.utime / 1e6;
  const charted = vehicle === page.chartVehicle;
  if (base === 'HEARTBEAT') {
    page.health.set(`${vehicle}|${m.process}`, { vehicle, m, at: performance.now() });
    return;
  }
  if (!page.vehicles.has(vehicle)) return;
  const v = scene.vehicle(vehicle);
  if (base === 'SIM_TRUTH') {
    v.onTruth(m);
    const ref = page.reference.get(vehicle);
    if (charted && ref) for (let i = 0; i < 3; i++) charts.position_error.add(i, t, ref[i] - m.position[i]);
  } else if (base === 'STATE_EST') {
    v.onEstimate(m);
    if (charted) for (let i = 0; i < 3; i++) charts.body_rates.add(3 + i, t, m.body_rate[i]);
  } else if (base === 'REFERENCE') {
    v.onReference(m);
    page.reference.set(vehicle, m.x.slice(0, 3));
  } else if (base === 'TRAJECTORY') {
    v.onTrajectory(m);
  } else if (base === 'RATE_CMD') {
    v.onRateCommand(m);
    if (charted) {
      for (let i = 0; i < 3; i++) charts.body_rates.add(i, t, m.body_rate[i]);
      charts.thrust.add(0, t, m.thrust);
      charts.thrust.add(1, t, m.thrust_demand);
    }
  } else if (base === 'GAINS' && charted) {
    charts.solve_time.add(0, t, m.solve_us);
  }
}

function showErrors() {
  const all = [...page.schemaErrors.map((e) => `schema mismatch: ${e}`), ...page.dataErrors];
  $('errors').textContent = all.join('\n');
  $('errors').hidden = all.length === 0;
}

function showHealth() {
  const now = performance.now();
  // Processes that beat first, by name; those silent (or gone, such as the launcher's helpers) after.
  const silent = (h) => now - h.at > HEARTBEAT_SILENT_MS;
  const rows = [...page.health.values()].sort((a, b) => (silent(a) - silent(b)) ||
    `${a.vehicle}${a.m.process}`.localeCompare(`${b.vehicle}${b.m.process}`));
  $('health').innerHTML = rows.map(({ vehicle, m, at }) => {
    const quiet = now - at > HEARTBEAT_SILENT_MS;
    const state = quiet ? 'SILENT' : (STATES[m.state] ?? String(m.state));
    const cls = quiet || m.state >= 3 ? 'bad' : m.state === 2 ? 'warn' : 'ok';
    const name = m.process.replace(/^sdlqr-/, '');  // every process of the stack is sdlqr-*
    return `<tr class="${cls}"><td>${vehicle ? `${vehicle}/` : ''}${name}</td><td>${state}</td>` +
      `<td>${(m.cpu_percent ?? 0).toFixed(1)}</td><td>${m.deadline_misses}</td><td>${m.dropped}</td>` +
      `<td>${m.rejected}</td><td>${m.errors}</td><td>${((now - at) / 1000).toFixed(1)}</td></tr>`;
  }).join('');
}

function showPlayback() {
  const p = page.playback;
  $('playback').hidden = false;
  $('play').textContent = p.playing ? 'pause' : 'play';
  if (document.activeElement !== $('seek')) {
    $('seek').max = p.duration_s;
    $('seek').value = p.position_s;
  }
  $('position').textContent = `${p.position_s.toFixed(1)} / ${p.duration_s.toFixed(1)} s`;
  $('speed').value = String(p.speed);
}

async function control(op, value) {
  await fetch(`/api/playback?op=${op}${value === undefined ? '' : `&value=${value}`}`, { method: 'POST' });
}
$('play').onclick = () => control(page.playback && page.playback.playing ? 'pause' : 'play');
$('speed').onchange = () => control('speed', $('speed').value);
$('seek').onchange = () => control('seek', $('seek').value);
$('vehicle').onchange = () => selectVehicle($('vehicle').value);

function isStale(now) {
  return page.connected && (page.lastMessageMs === null || now - page.lastMessageMs > STALE_MS);
}

// Ten times a second: staleness, the status line, the health table, the charts.
setInterval(() => {
  const now = performance.now();
  const stale = isStale(now);
  if (stale && page.staleSinceMs === null) {
    page.staleSinceMs = now;
    // How long after its last message the page showed the stream stale (its own clock).
    page.staleShownAfterMs = page.lastMessageMs === null ? null : now - page.lastMessageMs;
  }
  if (!stale) page.staleSinceMs = null;
  const paused = page.playback && !page.playback.playing;
  const status = $('status');
  status.className = !page.connected ? 'bad' : stale && !paused ? 'bad' : 'ok';
  status.textContent = !page.connected ? 'disconnected'
    : paused ? 'paused'
      : stale ? (page.lastMessageMs === null ? 'STALE: no data yet'
        : `STALE: no data for ${((now - page.lastMessageMs) / 1000).toFixed(1)} s`)
        : `live: ${page.vehicles.size} vehicle(s)`;
  showHealth();
  for (const chart of Object.values(charts)) chart.draw(now);
}, 100);

const wsUrl = new URLSearchParams(location.search).get('ws') ?? `ws://${location.host}/`;
const connection = new FoxgloveConnection(wsUrl, {
  serverInfo: (info) => { page.serverInfo = info; page.source = info.metadata?.source ?? null; },
  advertise: onAdvertise,
  unadvertise: () => {},
  status: (s) => { if (page.status.length < 20) page.status.push(s.message); },
  message: (channel, timestampNs, value) => { onMessage(channel, timestampNs, value); scene.dirty = true; },
  connection: (up) => { page.connected = up; if (!up) page.lastMessageMs = null; },
});

window.sdlqrView = {
  state() {
    const now = performance.now();
    const chartStates = {};
    for (const [name, chart] of Object.entries(charts)) chartStates[name] = chart.state();
    return {
      connected: page.connected, source: page.source, messages: page.messages, frames: connection.framesReceived,
      stale: isStale(now), staleForMs: page.staleSinceMs === null ? 0 : now - page.staleSinceMs,
      staleShownAfterMs: page.staleShownAfterMs,
      lastMessageAgeMs: page.lastMessageMs === null ? null : now - page.lastMessageMs,
      statusText: $('status').textContent, schemaErrors: [...page.schemaErrors], dataErrors: [...page.dataErrors],
      serverStatus: [...page.status], chartVehicle: page.chartVehicle, charts: chartStates,
      health: [...page.health.values()].map(({ vehicle, m, at }) => ({
        vehicle, process: m.process, state: m.state, ageMs: now - at })),
      playback: page.playback, ...scene.state(),
    };
  },
};
