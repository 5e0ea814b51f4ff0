// The browser page's speed (a benchmark, never a test):
//   node tests/web/bench.mjs PAGE.html BENCH_API
// 1. One request inside the page (window.trebuchet, the module in WebAssembly) against the same
//    request natively (bench-api: trebuchet::api in C++): medians over 301 runs (in the page, of
//    batches of 50, 10 and 1 calls, the clock of a file:// page being 0.1 ms), and the ratio.
// 2. A slider change in view 2 until the page has drawn it (the shot, its series, the viewer's
//    charts and the comparison with the optimum), over 200 drags of L4: median and 95th percentile.
import { execFileSync } from 'node:child_process';
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { launch, open } from './browser.mjs';

const [pagePath, benchApi] = process.argv.slice(2);
const [nativeDesign, nativeShot, nativeSeries] = execFileSync(benchApi, ['301'], { encoding: 'utf8' }).trim().split(' ').map(Number);
const browser = await launch();
const { page } = await open(browser, pathToFileURL(resolve(pagePath)).href);
const inPage = await page.evaluate(() => {
  // A page from file:// reads the clock to 0.1 ms: each sample times a batch of `batch` calls.
  const t = window.trebuchet, times = (work, batch) => {
    const list = [];
    for (let k = 0; k < 301; k++) {
      const start = performance.now();
      for (let j = 0; j < batch; j++) work();
      list.push(1000 * (performance.now() - start) / batch);
    }
    list.sort((a, b) => a - b);
    return list[150];
  };
  const request = { R: '150m', m: '50kg', theta_i_deg: 30, F: '2/3' };
  const design = t.design(request);
  return [times(() => t.design(request), 50), times(() => t.shot({ design }), 10), times(() => t.shot({ design, series: true }), 1)];
});
const row = (name, web, native) => console.log(`${name.padEnd(28)} page ${web.toFixed(1).padStart(8)} us   native ${native.toFixed(1).padStart(8)} us   ratio ${(web / native).toFixed(2)}`);
row('design (calculator)', inPage[0], nativeDesign);
row('shot (verified, no series)', inPage[1], nativeShot);
row('shot with its series', inPage[2], nativeSeries);

await page.click('nav button[data-view="edit"]');
const latency = await page.evaluate(async () => {
  const slider = document.querySelector('#sliders input[data-key="L4"]');
  const base = Number(slider.value), list = [];
  for (let k = 0; k < 200; k++) {
    const start = performance.now();
    slider.value = String(base * (0.9 + 0.2 * (k % 20) / 19));
    slider.dispatchEvent(new Event('input'));
    await new Promise((done) => requestAnimationFrame(() => done()));  // until the frame that shows it
    list.push(performance.now() - start);
  }
  list.sort((a, b) => a - b);
  return { median: list[100], p95: list[190], max: list[199] };
});
console.log(`slider change to drawn frame    median ${latency.median.toFixed(1)} ms, 95th percentile ${latency.p95.toFixed(1)} ms, largest ${latency.max.toFixed(1)} ms (200 drags)`);
await browser.close();
