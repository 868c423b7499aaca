// Headless Chromium (Debian's) driven by puppeteer-core: WebGL on SwiftShader. Flags from
// /work/shared/NOTES.md: root needs --no-sandbox; --use-gl=swiftshader would break WebGL.
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import puppeteer from 'puppeteer-core';

export const CHROMIUM = process.env.SDLQR_CHROMIUM ?? '/usr/bin/chromium';

export async function launchBrowser() {
  if (!existsSync(CHROMIUM)) throw new Error(`no Chromium at ${CHROMIUM} (Debian package chromium: ./sdlqr setup)`);
  return puppeteer.launch({
    executablePath: CHROMIUM,
    headless: true,
    args: ['--no-sandbox', '--enable-unsafe-swiftshader', '--window-size=1280,720'],
    defaultViewport: { width: 1280, height: 720 },
  });
}

// A page that records its JavaScript errors in page.errors.
export async function openPage(browser, url) {
  const page = await browser.newPage();
  page.errors = [];
  page.on('pageerror', (e) => page.errors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error') page.errors.push(m.text()); });
  await page.goto(url, { waitUntil: 'load' });
  await page.waitForFunction(() => window.sdlqrView && window.sdlqrView.state().connected, { timeout: 10000 });
  return page;
}

export const pageState = (page) => page.evaluate(() => window.sdlqrView.state());

// CPU seconds (user + system) of a process and all its descendants, from /proc.
export function treeCpuSeconds(rootPid) {
  const parent = new Map();
  const ticks = new Map();
  for (const name of readdirSync('/proc')) {
    if (!/^\d+$/.test(name)) continue;
    try {
      const stat = readFileSync(`/proc/${name}/stat`, 'utf8');
      const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
      parent.set(Number(name), Number(fields[1]));
      ticks.set(Number(name), Number(fields[11]) + Number(fields[12]));
    } catch { /* gone meanwhile */ }
  }
  const inTree = (pid) => { for (let p = pid; p > 1; p = parent.get(p)) if (p === rootPid) return true; return false; };
  let total = 0;
  for (const [pid, t] of ticks) if (inTree(pid)) total += t;
  return total / 100;  // USER_HZ
}

export const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
