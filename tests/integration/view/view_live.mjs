// During a flight (view_flight.sh flies it), watches sdlqr-view with every kind of client and
// writes what each saw to WORK/observations.json for view_judge.mjs:
//   - the page in headless Chromium: its scene state every 250 ms, a screenshot mid-flight, then
//     after the flight (bus silent) what it drew of the whole flight and when it shows the stream stale;
//   - @foxglove/ws-protocol's client (an implementation nobody here wrote): every channel
//     subscribed, the first messages of each decoded;
//   - a client that subscribes to every channel and stops reading once the vehicle flies, and
//     /api/stats meanwhile; the same client of a second sdlqr-view whose per-client bound is
//     lifted (the negative: there its memory grows);
//   - for two seconds, a second page fed through a proxy that renames a field in SIM_TRUTH's
//     schema (the page must refuse to draw from it).
// usage: node view_live.mjs URL WORK_DIR PROXY_PORT UNBOUNDED_VIEW_PORT
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import foxgloveProtocol from '@foxglove/ws-protocol';
import WebSocket, { WebSocketServer } from 'ws';
import { launchBrowser, openPage, pageState, sleep, treeCpuSeconds } from './lib/browser.mjs';
import { stalledClient } from './lib/stalled_client.mjs';

const { FoxgloveClient } = foxgloveProtocol;  // CommonJS: its named exports are not seen by import
const [url, work, proxyPort, unboundedPort] = process.argv.slice(2);
const unboundedUrl = `http://127.0.0.1:${unboundedPort}/`;
const wsUrl = url.replace(/^http/, 'ws');
const SUBPROTOCOL = 'foxglove.websocket.v1';
const MESSAGES_KEPT = 60;  // per channel, for the value comparison

const observations = {
  pageSamples: [], foxglove: { channels: [], messages: {}, statuses: [] }, stalled: { stats: [] }, unbounded: { stats: [] },
};
const now = () => Date.now();

function foxgloveClient() {
  const client = new FoxgloveClient({ ws: new WebSocket(wsUrl, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]) });
  const topics = new Map();
  const decoder = new TextDecoder();
  client.on('serverInfo', (info) => { observations.foxglove.serverInfo = info; });
  client.on('status', (s) => observations.foxglove.statuses.push(s));
  client.on('advertise', (channels) => {
    for (const c of channels) {
      observations.foxglove.channels.push(c);
      topics.set(client.subscribe(c.id), c.topic);
    }
  });
  client.on('message', ({ subscriptionId, timestamp, data }) => {
    const topic = topics.get(subscriptionId);
    const kept = (observations.foxglove.messages[topic] ??= []);
    if (kept.length < MESSAGES_KEPT) {
      kept.push({ timestampNs: String(timestamp), value: JSON.parse(decoder.decode(data)) });
    }
  });
  return client;
}

// Relays between a page and sdlqr-view, renaming SIM_TRUTH's `position` in every advertised schema.
function wrongSchemaProxy() {
  const server = new WebSocketServer({ host: '127.0.0.1', port: Number(proxyPort), handleProtocols: () => SUBPROTOCOL });
  server.on('connection', (down) => {
    const up = new WebSocket(wsUrl, [SUBPROTOCOL]);
    const pending = [];
    up.on('open', () => { for (const m of pending.splice(0)) up.send(m); });
    down.on('message', (m) => (up.readyState === WebSocket.OPEN ? up.send(m.toString()) : pending.push(m.toString())));
    up.on('message', (data, binary) => {
      if (binary) return down.send(data);
      const m = JSON.parse(data.toString());
      if (m.op === 'advertise') {
        for (const c of m.channels) {
          if (c.schemaName !== 'sdlqr.sim_truth_t') continue;
          const schema = JSON.parse(c.schema);
          schema.properties.position_m = schema.properties.position;
          delete schema.properties.position;
          schema.required = schema.required.map((r) => (r === 'position' ? 'position_m' : r));
          c.schema = JSON.stringify(schema);
        }
      }
      down.send(JSON.stringify(m));
    });
    down.on('close', () => up.close());
    up.on('close', () => down.close());
  });
  return server;
}

async function stats(server = url) {
  const reply = await fetch(new URL('/api/stats', server));
  return reply.json();
}

const flying = (topics) => topics.some((t) => t.endsWith('foxglove/scene'));
const stalled = stalledClient(new URL(url).port, flying);
const unbounded = stalledClient(unboundedPort, flying);
const browser = await launchBrowser();
const page = await openPage(browser, url);
const foxglove = foxgloveClient();
const proxy = wrongSchemaProxy();
let wrong = await openPage(browser, `${url}?ws=ws://127.0.0.1:${proxyPort}/`);
const cpuStart = { browser: treeCpuSeconds(browser.process().pid), atMs: now() };
writeFileSync(`${work}/browser.ready`, '');

// During the flight. The page samples its own state every 250 ms (a sampler injected by this
// test, so a slow round trip to the browser never skips an instant); /api/stats is read on its
// own loop; this loop takes the screenshot and watches the wrong-schema page.
await page.evaluate(() => {
  window.testSamples = [];
  window.testSampler = setInterval(() => window.testSamples.push({ atMs: Date.now(), state: window.sdlqrView.state() }), 250);
});
const flightOver = () => existsSync(`${work}/flight.done`);
const statsLoop = (async () => {
  while (!flightOver()) {
    observations.stalled.stats.push({ atMs: now(), stats: await stats() });
    observations.unbounded.stats.push({ atMs: now(), stats: await stats(unboundedUrl) });
    await sleep(300);
  }
})();
let screenshotTaken = false;
while (!flightOver()) {
  const state = await pageState(page);
  const vehicle = state.vehicles[Object.keys(state.vehicles)[0]];
  if (!screenshotTaken && vehicle?.forceDrawn > 0) {  // the pull: the vehicle in the air with its trails
    await page.screenshot({ path: `${work}/view.png` });
    screenshotTaken = true;
  }
  if (wrong) {  // closed once it has seen SIM_TRUTH advertised and a while of the flight
    observations.wrongSchemaPage = { state: await pageState(wrong), errors: wrong.errors };
    if (observations.wrongSchemaPage.state.schemaErrors.length > 0 && observations.wrongSchemaPage.state.messages > 300) {
      await wrong.close();
      wrong = null;
    }
  }
  await sleep(250);
}
await statsLoop;
observations.pageSamples = await page.evaluate(() => { clearInterval(window.testSampler); return window.testSamples; });
observations.cpu = {
  browserSeconds: treeCpuSeconds(browser.process().pid) - cpuStart.browser, wallSeconds: (now() - cpuStart.atMs) / 1000,
};
if (!screenshotTaken) await page.screenshot({ path: `${work}/view.png` });

// After the flight: the bus is silent. A page on a loaded machine draws seconds behind (10 s seen
// beside a sanitizer build): it first draws what reached it, then shows the stream stale. Watched
// until it shows STALE, or its message count has not moved for 3 s (never stale: a failure).
const doneAtMs = Number(readFileSync(`${work}/flight.done`, 'utf8'));
observations.afterFlight = { doneAtMs };
for (let count = -1, quietSinceMs = now(), deadline = now() + 60000; now() < deadline;) {
  const state = await pageState(page);
  observations.afterFlight.state = state;  // the drained page: what it drew of the whole flight
  if (state.statusText.startsWith('STALE')) {  // what the page shows, not only what it computes
    observations.afterFlight.staleSeenAtMs = now();
    break;
  }
  if (state.messages !== count) [count, quietSinceMs] = [state.messages, now()];
  if (now() - quietSinceMs > 3000) break;
  await sleep(50);
}
observations.pageErrors = page.errors;
for (const [key, client] of [['stalled', stalled], ['unbounded', unbounded]]) {
  Object.assign(observations[key], { sessionId: client.sessionId, stalledAtMs: client.stalledAtMs, topics: client.topics.length });
}
writeFileSync(`${work}/observations.json`, JSON.stringify(observations));
stalled.close();
unbounded.close();
foxglove.close();
proxy.close();
await browser.close();
