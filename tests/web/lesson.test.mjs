// The page for a lesson and a workshop (issue 37) in headless Chromium (CTest label web):
//   node tests/web/lesson.test.mjs PAGE.html trebuchet-verify
// 1. a beam that breaks says so, unmissably, with the program's margin; a sound one says it holds;
// 2. an iron ball's diameter is the program's; 3. Edit after Reconstruct opens the completed
// engine; 4. a typed value with a unit is read as the programs read it; 5. the what-if chart's
// points are single shots of the same engines, bit for bit; 6. the Monte Carlo samples download
// as CSV, a row a sample, with the run's own numbers; 7. the QR code decodes to the link;
// 8. the symbols have plain words; 9. a phone's width scrolls nowhere sideways, a projector's type is large.
// Each check prints how close it came. Exit 1 on any failure.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { launch, open } from './browser.mjs';

const [pagePath, verify] = process.argv.slice(2);
let failures = 0;
const check = (ok, what) => { console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`); if (!ok) failures++; };
const native = (args) => JSON.parse(execFileSync(verify, [...args, '--format', 'json'], { encoding: 'utf8' }));
const browser = await launch();
const url = pathToFileURL(resolve(pagePath)).href;
const link = (state) => url + '#' + new URLSearchParams(Object.fromEntries(Object.entries(state).map(([k, v]) => [k, typeof v === 'string' ? v : JSON.stringify(v)]))).toString();
// tab:Alcala_la_Vieja's Ca engine, its beam as thin as the test needs.
const ca = (D) => ({ L1: 4.13, L2: 0.88, L3: 1.5044566117531541, L4: 3.55, M: 3110, m: 50, mb: 174, D });
const caFlags = (D) => ['--L1', '4.13m', '--L2', '0.88m', '--L3', '1.5044566117531541m', '--L4', '3.55m', '--M', '3110kg', '--m', '50kg', '--mb', '174kg', '--D', `${D}m`];

try {
  // ---- 1. the beam's strength, pass or break ---------------------------------------------------
  // A 10 cm beam under 3.11 t breaks (the program: margin 0.27); a 40 cm one holds. The page shows
  // the program's margin to 1e-9 (the shot's own agreement with the program, tests/web/page.test.mjs),
  // in white on red for a break, and the words say which.
  for (const [D, breaks] of [[0.1, true], [0.4, false]]) {
    const { page, context, problems } = await open(browser, link({ view: 'edit', edit: ca(D) }));
    const seen = await page.evaluate(() => {
      const box = document.querySelector('.tv-strength');
      return box && { text: box.innerText, breaks: box.classList.contains('tv-breaks'), background: getComputedStyle(box).backgroundColor,
        visible: box.getBoundingClientRect().top < window.innerHeight, margin: window.trebuchet.current().rupture_margin };
    });
    const program = native(['shot', ...caFlags(D)]).rupture_margin;
    const closeness = seen ? Math.abs(seen.margin - program) / program : Infinity;
    check(seen && seen.breaks === breaks && (breaks ? /THE BEAM BREAKS/.test(seen.text) && seen.background === 'rgb(176, 0, 32)' : /The beam holds/.test(seen.text)) &&
      seen.visible && closeness < 1e-9 && problems.length === 0,
    `D = ${D} m: "${seen && seen.text.slice(0, 60)}…" on ${seen && seen.background}, in the first screen; margin ${seen && seen.margin} against the program's ${program} (relative ${closeness.toExponential(2)})`);
    await context.close();
  }

  const { page, problems, requests } = await open(browser, url);
  // ---- 2. an iron ball's diameter ------------------------------------------------------------------
  // Iron (7870 kg/m3) through air: the diameter the page states is the program's for --projectile
  // iron, and that of a sphere of the ball's mass, d = (6 m/(π ρ))^(1/3), to 1e-12 (cbrt's rounding).
  await page.check('#air');
  await page.selectOption('#projectile', 'iron');
  const iron = await page.evaluate(() => ({ d: Number(document.getElementById('projectile-size').dataset.diameter), text: document.getElementById('projectile-size').textContent,
    densityShown: document.getElementById('projectile-density').getBoundingClientRect().height > 0,
    m: window.trebuchet.current().engine.m, engine: window.trebuchet.current().engine }));
  const sphere = Math.cbrt(6 * iron.m / (Math.PI * 7870));
  const ironProgram = native(['shot', '--L1', `${iron.engine.L1}m`, '--L2', `${iron.engine.L2}m`, '--L3', `${iron.engine.L3}m`, '--L4', `${iron.engine.L4}m`, '--M', `${iron.engine.M}kg`,
    '--m', `${iron.engine.m}kg`, '--mb', `${iron.engine.mb}kg`, '--air', '--projectile', 'iron']).assumptions.air.projectile_diameter;
  check(Math.abs(iron.d - sphere) / sphere < 1e-12 && Math.abs(iron.d - ironProgram) / ironProgram < 1e-12 && /iron of 7870 kg\/m³/.test(iron.text) && !iron.densityShown,
    `an iron ball of ${iron.m} kg: d = ${iron.d} m in the page, ${ironProgram} m in the program, ${sphere} m for the sphere; "${iron.text}"`);
  // A density typed instead: 2800 kg/m3, the box shown, the shot's ball of that density.
  await page.selectOption('#projectile', 'density');
  await page.fill('#projectile-density', '2.8t/m3');
  await page.dispatchEvent('#projectile-density', 'change');
  const typedDensity = await page.evaluate(() => ({ shown: document.getElementById('projectile-density').getBoundingClientRect().height > 0,
    density: window.trebuchet.current().assumptions.air.projectile_density }));
  check(typedDensity.shown && typedDensity.density === 2800, `a density typed, 2.8t/m3, is the shot's ball of ${typedDensity.density} kg/m3, its box shown`);
  await page.selectOption('#projectile', 'stone');
  await page.uncheck('#air');

  // ---- 3. Edit after Reconstruct opens the completed engine -------------------------------------
  await page.click('nav button[data-view="reconstruct"]');
  await page.click('#complete');
  const completed = await page.evaluate(() => window.trebuchet.current());
  await page.click('nav button[data-view="edit"]');
  const opened = await page.evaluate(() => ({ shot: window.trebuchet.current(), L1: document.querySelector('#sliders .typed[data-key="L1"]').value,
    source: document.getElementById('edit-source').textContent }));
  const sameEngine = ['L1', 'L2', 'L3', 'L4', 'M', 'm', 'mb'].every((k) => opened.shot.engine[k] === completed.engine[k]);
  check(sameEngine && opened.shot.R === completed.R && /completed engine/.test(opened.source),
    `Edit after Reconstruct opens the completed engine: L1 ${opened.L1}, R ${opened.shot.R} m against the completion's ${completed.R} m; "${opened.source}"`);

  // ---- 4. a typed value with a unit ----------------------------------------------------------------
  // 19 ft is 5.7912 m exactly (1 ft = 0.3048 m): the library reads it as the programs do.
  await page.fill('#sliders .typed[data-key="L4"]', '19ft');
  await page.press('#sliders .typed[data-key="L4"]', 'Enter');
  const typed = await page.evaluate(() => ({ edit: window.trebuchet.state().edit.L4, shot: window.trebuchet.current().engine.L4,
    slider: Number(document.querySelector('#sliders input[data-key="L4"]').value), box: document.querySelector('#sliders .typed[data-key="L4"]').value }));
  check(typed.edit === 19 * 0.3048 && typed.shot === typed.edit && typed.slider === typed.edit,
    `a typed 19ft is L4 = ${typed.edit} m in the engine shot, the slider at ${typed.slider}, the box showing "${typed.box}"`);
  await page.fill('#sliders .typed[data-key="L4"]', '19kg');
  await page.press('#sliders .typed[data-key="L4"]', 'Enter');
  const wrong = await page.evaluate(() => ({ invalid: document.querySelector('#sliders .typed[data-key="L4"]').getAttribute('aria-invalid'),
    message: document.getElementById('edit-message').textContent, L4: window.trebuchet.state().edit.L4 }));
  check(wrong.invalid === 'true' && /mass/.test(wrong.message) && wrong.L4 === typed.edit, `a typed 19kg is refused in place: "${wrong.message}", L4 kept at ${wrong.L4} m`);

  // A value of the right kind that the library refuses for the engine (1e30 m, beyond the ordinary
  // 1e-6 to 1e6 m) is refused in place too; the engine and the slider keep theirs.
  const before30 = await page.evaluate(() => ({ L1: window.trebuchet.state().edit.L1, max: document.querySelector('#sliders input[data-key="L1"]').max }));
  await page.fill('#sliders .typed[data-key="L1"]', '1e30m');
  await page.press('#sliders .typed[data-key="L1"]', 'Enter');
  const huge = await page.evaluate(() => ({ invalid: document.querySelector('#sliders .typed[data-key="L1"]').getAttribute('aria-invalid'),
    message: document.getElementById('edit-message').textContent, L1: window.trebuchet.state().edit.L1, max: document.querySelector('#sliders input[data-key="L1"]').max,
    shot: window.trebuchet.current() !== null }));
  check(huge.invalid === 'true' && /ordinary size/.test(huge.message) && huge.L1 === before30.L1 && huge.max === before30.max && huge.shot,
    `a typed 1e30m is refused in place: "${huge.message.slice(0, 90)}…", L1 kept at ${huge.L1} m, the slider's end at ${huge.max}`);
  // An engine that makes no shot (19 kg cannot turn this beam): no stale downloads, and the what-if says why it is empty.
  const M = await page.evaluate(() => window.trebuchet.state().edit.M);
  await page.fill('#sliders .typed[data-key="M"]', '19kg');
  await page.press('#sliders .typed[data-key="M"]', 'Enter');
  const noShot = await page.evaluate(() => ({ downloads: document.querySelector('.downloads').hidden, sweep: document.getElementById('sweep-message').textContent,
    shot: window.trebuchet.current() }));
  check(noShot.shot === null && noShot.downloads && /No shot of this engine/.test(noShot.sweep), `an engine that makes no shot hides the downloads and says so under What if: "${noShot.sweep}"`);
  await page.fill('#sliders .typed[data-key="M"]', `${M}kg`);
  await page.press('#sliders .typed[data-key="M"]', 'Enter');

  // ---- 5. the what-if chart's points are single shots, bit for bit ------------------------------------
  // Each point of the chart, shot alone with the same settings, gives the same record: every number equal.
  for (const key of ['L4', 'M', 'pin_angle_deg']) {
    await page.selectOption('#sweep-key', key);
    const result = await page.evaluate(() => {
      const { request, answer } = window.trebuchet.whatIf();
      const settings = Object.assign({}, request);
      delete settings.design; delete settings.vary; delete settings.points;
      let equal = 0;
      answer.points.forEach((point, i) => {
        const single = window.trebuchet.shot(Object.assign({ design: Object.assign({}, request.design, { [answer.vary]: answer.values[i] }) }, settings));
        if (JSON.stringify(single) === JSON.stringify(point)) equal++;
      });
      return { equal, points: answer.points.length, vary: request.vary, drawn: document.querySelectorAll('#sweep-chart svg.sweep-chart').length,
        edited: request.design.L4, L4: window.trebuchet.state().edit.L4 };
    });
    check(result.equal === result.points && result.points === 21 && result.drawn === 1 && result.edited === result.L4,
      `what if ${result.vary}: ${result.equal} of ${result.points} points equal the single shot of their engine, bit for bit; the chart drawn for the edited L4 ${result.edited} m`);
  }
  // The chart follows the edited engine: a drag of M sweeps the new engine.
  await page.evaluate(() => { const s = document.querySelector('#sliders input[data-key="M"]'); s.value = String(Number(s.value) * 1.2); s.dispatchEvent(new Event('input')); });
  const follows = await page.evaluate(() => ({ design: window.trebuchet.whatIf().request.design.M, edit: window.trebuchet.state().edit.M }));
  check(follows.design === follows.edit, `the chart follows a drag of M: swept with M = ${follows.design} kg, the edited ${follows.edit} kg`);

  // ---- 6. the Monte Carlo samples as CSV -------------------------------------------------------------
  // 40 completions with M uniform in 2.5..3.5 t: the file has a row a sample, the drawn M and R, T,
  // eps, v, each the run's own number (17 digits read back to the same double).
  await page.click('nav button[data-view="reconstruct"]');
  await page.fill('#attested input[data-key="M"]', '2.5t..3.5t');
  await page.fill('#samples', '40');
  await page.dispatchEvent('#samples', 'change');
  await page.click('#monte-carlo');
  await page.waitForFunction(() => document.getElementById('progress').hidden && document.getElementById('download-draws'), null, { timeout: 120000 });
  const folder = mkdtempSync(join(tmpdir(), 'trebuchet-lesson-'));
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download-draws')]);
  await download.saveAs(join(folder, 'samples.csv'));
  const rows = readFileSync(join(folder, 'samples.csv'), 'utf8').trim().split('\n').map((line) => line.split(','));
  const header = rows.shift();
  const run = await page.evaluate(() => window.trebuchet.monteCarlo({ attested: window.trebuchet.state().attested, samples: 40, seed: 1 }));
  const column = (name) => rows.map((r) => (r[header.indexOf(name)] === '' ? null : Number(r[header.indexOf(name)])));
  const sameAs = (a, b) => a.length === b.length && a.every((x, i) => x === b[i]);
  const drawnM = header.find((h) => /^M/.test(h));
  check(rows.length === 40 && drawnM && sameAs(column(drawnM), run.draws.M) && sameAs(column('R_m'), run.draws.R) && sameAs(column('T_J'), run.draws.T) &&
    sameAs(column('eps'), run.draws.eps) && sameAs(column('v_m_s'), run.draws.v),
  `the samples' CSV: ${rows.length} rows, columns ${header.join(' ')}; the drawn M and R, T, eps, v equal the run's (first R ${column('R_m')[0]} m)`);

  // ---- 7. the QR code of the share link ------------------------------------------------------------
  // jsQR (npm) reads the code the page drew, from its pixels; the text must be the page's address.
  await page.click('#qr');
  await page.addScriptTag({ content: readFileSync(new URL('./node_modules/jsqr/dist/jsQR.js', import.meta.url), 'utf8') });
  const qr = await page.evaluate(async () => {
    const svgNode = document.querySelector('#qr-code svg');
    const image = new window.Image();
    image.src = 'data:image/svg+xml;charset=utf-8,' + encodeURIComponent(new XMLSerializer().serializeToString(svgNode));
    await image.decode();
    // Drawn at 6 pixels a module, as a phone's camera sees a code on a screen.
    const size = 6 * svgNode.viewBox.baseVal.width / 4;  // the library's cells are 4 units
    const canvas = document.createElement('canvas');
    canvas.width = canvas.height = size;
    const g = canvas.getContext('2d');
    g.fillStyle = 'white'; g.fillRect(0, 0, size, size);
    g.drawImage(image, 0, 0, size, size);
    const pixels = g.getImageData(0, 0, size, size);
    const code = window.jsQR(pixels.data, size, size);
    return { text: code && code.data, href: location.href, open: document.getElementById('qr-dialog').open };
  });
  check(qr.open && qr.text === qr.href, `the QR code decodes to the link (${qr.href.length} characters): "${(qr.text || 'nothing').slice(0, 70)}…"`);
  await page.click('#qr-dialog button');

  // ---- 8. plain words beside every symbol ----------------------------------------------------------
  const legend = await page.evaluate(() => Object.fromEntries([...document.querySelectorAll('#legend dt')].map((dt) => [dt.textContent, dt.nextElementSibling.textContent])));
  const symbols = ['θ, θi', 'ψ', 'φ', 'β2', 'ε', '𝓕', 'Q', 'ΔU', 'R', 'T', 'L1', 'L2', 'L3', 'L4', 'M', 'm', 'mb', 'D', 'H'];
  const missing = symbols.filter((s) => !(legend[s] && legend[s].split(' ').length >= 2));  // words, not a symbol again
  check(missing.length === 0, `the legend gives each symbol in words (${symbols.length}; missing: ${missing.join(', ') || 'none'}): ε "${legend['ε']}"`);

  check(problems.length === 0 && requests.length === 0, `no console error and no network request through it all (${problems.join('; ')} ${requests.join(' ')})`);

  // ---- 9. a phone and a projector -------------------------------------------------------------------
  for (const view of ['design', 'edit', 'reconstruct']) {
    for (const projector of [false, true]) {
      const phone = await open(browser, link({ view }), { width: 390, height: 844 });
      if (projector) await phone.page.click('#projector');
      const wide = await phone.page.evaluate(() => document.documentElement.scrollWidth);
      check(wide <= 390, `on a 390 px phone${projector ? ' with the projector\'s type' : ''} the ${view} view is ${wide} px wide: nothing scrolls sideways`);
      await phone.context.close();
    }
  }
  const projector = await open(browser, link({ view: 'edit' }), { width: 1920, height: 1080 });
  await projector.page.click('#projector');  // the layout of this screen: no link carries it
  const type = await projector.page.evaluate(() => ({ body: parseFloat(getComputedStyle(document.body).fontSize), table: parseFloat(getComputedStyle(document.querySelector('.tv-figures')).fontSize),
    wide: document.documentElement.scrollWidth }));
  check(type.body >= 20 && type.table >= 20 && type.wide <= 1920, `on a projector the type is ${type.body} px (tables ${type.table} px), the page ${type.wide} px wide`);
  await projector.context.close();
} finally {
  await browser.close();
}
check(failures === 0, `${failures} failure(s)`);
process.exit(failures ? 1 : 0);
