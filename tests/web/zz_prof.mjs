import { launch, open } from './browser.mjs';
import { pathToFileURL } from 'node:url';
import { resolve } from 'node:path';
const browser = await launch();
const { page } = await open(browser, pathToFileURL(resolve(process.argv[2])).href);
await page.click('nav button[data-view="edit"]');
const client = await page.context().newCDPSession(page);
await client.send('Profiler.enable');
await client.send('Profiler.setSamplingInterval', { interval: 100 });
await client.send('Profiler.start');
await page.evaluate(async () => {
  const slider = document.querySelector('#sliders input[data-key="L4"]');
  const base = Number(slider.value);
  for (let k = 0; k < 60; k++) {
    slider.value = String(base * (0.9 + 0.2 * (k % 20) / 19));
    slider.dispatchEvent(new Event('input'));
    await new Promise((done) => requestAnimationFrame(() => done()));
  }
});
const { profile } = await client.send('Profiler.stop');
const self = new Map(), byId = new Map(profile.nodes.map((n) => [n.id, n]));
const dt = profile.timeDeltas; let total = 0;
profile.samples.forEach((id, i) => { const n = byId.get(id); const key = n.callFrame.functionName + ' ' + n.callFrame.url.split('/').pop().slice(0, 20) + ':' + n.callFrame.lineNumber; self.set(key, (self.get(key) || 0) + (dt[i] || 0)); total += dt[i] || 0; });
console.log('total ms', (total / 1000).toFixed(0));
[...self.entries()].sort((a, b) => b[1] - a[1]).slice(0, 25).forEach(([k, v]) => console.log((v / 1000).toFixed(1).padStart(8), k));
await browser.close();
