// Screenshots of every view of the page, to look at (not a test):
//   node tests/web/screenshots.mjs PAGE.html OUTDIR
// Each view at a projector's 1920x1080, a laptop's 1280x720 (the first screen, and the whole page)
// and a phone's 390x844.
import { mkdirSync } from 'node:fs';
import { resolve, join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { launch, open } from './browser.mjs';

const [pagePath, out] = process.argv.slice(2);
mkdirSync(out, { recursive: true });
const browser = await launch();
const url = pathToFileURL(resolve(pagePath)).href;
const views = {
  design: async () => {},
  // The README's picture (docs/figures/web.png is readme-1280.png): the optimal engine mid-swing.
  readme: async (page) => { await page.evaluate(() => window.trebuchet.viewer().setTime(0.95)); },
  edit: async (page) => {
    await page.click('nav button[data-view="edit"]');
    await page.evaluate(() => { const s = document.querySelector('#sliders input[data-key="L4"]'); s.value = String(Number(s.value) * 1.4); s.dispatchEvent(new Event('input')); });
  },
  reconstruct: async (page) => {
    await page.click('nav button[data-view="reconstruct"]');
    await page.fill('#attested input[data-key="M"]', '2.5t..3.5t');
    await page.click('#complete');
    await page.click('#monte-carlo');
    await page.waitForFunction(() => document.getElementById('progress').hidden, null, { timeout: 60000 });
  },
  air: async (page) => {
    await page.check('#air');
    await page.fill('#target-level', '-20m');
    await page.evaluate(() => window.trebuchet.viewer().setTime(2.2));
  },
  pin: async (page) => {  // a release at a pin of 30 deg: the settings and the shot's pin angle
    await page.selectOption('#release-by', 'pin_angle_deg');
    await page.fill('#release-value', '30deg');
  },
  machine: async (page) => {  // the optimal engine built as a floating arm, mid-swing: its rail, guide and rolling axle
    await page.selectOption('#machine', 'floating-arm');
    await page.evaluate(() => window.trebuchet.viewer().setTime(0.9));
  },
  whipper: async (page) => {  // pytrebuchet's default whipper's parts on its 5 m frame, its weight off the arm, its ball still on it
    const edit = JSON.stringify({ L1: 4, L2: 2, L3: 4, L4: 4, M: 100, m: 3, mb: 10, theta_i_deg: 30, H: 5 });
    await page.goto(url + '#' + new URLSearchParams({ view: 'edit', machine: 'whipper', edit }).toString());
    await page.reload();
    await page.evaluate(async () => { await window.trebuchet.ready; window.trebuchet.viewer().setTime(1.3); });
  },
  refused: async (page) => { await page.fill('#first', '5000m'); },
  // Issue 37: a beam that breaks, the what-if chart, an iron ball in air, the QR code, a projector.
  breaks: async (page) => {
    const edit = JSON.stringify({ L1: 4.13, L2: 0.88, L3: 1.5044566117531541, L4: 3.55, M: 3110, m: 50, mb: 174, D: 0.1 });
    await page.goto(url + '#' + new URLSearchParams({ view: 'edit', edit }).toString());
    await page.reload();
    await page.evaluate(() => window.trebuchet.ready);
  },
  whatif: async (page) => {
    await page.click('nav button[data-view="edit"]');
    await page.locator('.whatif').scrollIntoViewIfNeeded();
  },
  iron: async (page) => { await page.check('#air'); await page.selectOption('#projectile', 'iron'); await page.locator('#projectile-size').scrollIntoViewIfNeeded(); },
  qr: async (page) => { await page.click('#qr'); },
  projector: async (page) => { await page.click('nav button[data-view="edit"]'); await page.click('#projector'); },
  imperial: async (page) => { await page.selectOption('#units', 'imperial'); },
};
for (const [name, act] of Object.entries(views)) {
  for (const [width, height] of [[1920, 1080], [1280, 720], [390, 844]]) {
    const { page, context, problems } = await open(browser, url, { width, height });
    await act(page);
    await page.waitForTimeout(200);
    await page.screenshot({ path: join(out, `${name}-${width}.png`) });
    if (width === 1280) {
      await page.screenshot({ path: join(out, `${name}-${width}-full.png`), fullPage: true });
      await page.locator('#controls').screenshot({ path: join(out, `${name}-${width}-controls.png`) });
    }
    if (problems.length) console.log(name, width, problems);
    await context.close();
  }
}
await browser.close();
console.log(`screenshots in ${out}`);
