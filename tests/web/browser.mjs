// Headless Debian Chromium for the page's tests, through playwright-core (no browser download).
// The flags keep a closed network quiet (the machine notes: background networking, updates).
import { chromium } from 'playwright-core';

export async function launch() {
  return chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
           '--disable-component-update', '--disable-sync'],
  });
}

// A page of `url` with every console error, page error and network request recorded; for the
// trebuchet page (isPage), once its module is ready.
export async function open(browser, url, viewport, isPage = true) {
  const context = await browser.newContext({ viewport: viewport || { width: 1280, height: 800 } });
  const page = await context.newPage();
  const problems = [], requests = [];
  page.on('console', (m) => { if (m.type() === 'error' || m.type() === 'warning') problems.push(`console ${m.type()}: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push('page error: ' + e.message));
  page.on('request', (r) => { if (!r.url().startsWith('file:') && !r.url().startsWith('data:') && !r.url().startsWith('blob:')) requests.push(r.url()); });
  await page.goto(url);
  if (isPage) await page.evaluate(() => window.trebuchet.ready);
  return { context, page, problems, requests };
}
