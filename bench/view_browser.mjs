// bench/view_cost's browser: opens sdlqr-view's page in headless Chromium, says when it is ready,
// keeps it open until DIR/flight.done exists, then writes Chromium's CPU seconds to DIR/browser_cpu.
// usage: node bench/view_browser.mjs URL DIR
import { existsSync, writeFileSync } from 'node:fs';
import { launchBrowser, openPage, sleep, treeCpuSeconds } from '../tests/integration/view/lib/browser.mjs';

const [url, dir] = process.argv.slice(2);
const browser = await launchBrowser();
await openPage(browser, url);
const start = treeCpuSeconds(browser.process().pid);
writeFileSync(`${dir}/browser.ready`, '');
while (!existsSync(`${dir}/flight.done`)) await sleep(100);
writeFileSync(`${dir}/browser_cpu`, (treeCpuSeconds(browser.process().pid) - start).toFixed(2));
await browser.close();
