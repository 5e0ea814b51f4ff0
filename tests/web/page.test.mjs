// The browser page in headless Chromium (CTest label web):
//   node tests/web/page.test.mjs PAGE.html trebuchet-calc trebuchet-verify
// 1. It loads from file:// with no console error and no network request.
// 2. Through window.trebuchet, the Alcalá la Vieja Ca design, Denny's engine and 20 random
//    designs give the native programs' JSON numbers (design: to 1e-12 relative; shot: see below).
// 3. The animation advances; 4. a shared URL restores the state; 5. the downloaded design is
//    accepted by trebuchet-verify and gives the page's shot; 6. a Monte Carlo run spread over
//    Web Workers is the run of one module; 7. a refusal shows the calculator's message;
// 8. the index.html of trebuchet-verify shot --plot draws its shot with the same viewer;
// 9. hostile links and requests are refused as bad input, the page working on.
// Each check prints how close it came. Exit 1 on any failure.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { launch, open } from './browser.mjs';

const [pagePath, calc, verify] = process.argv.slice(2);
let failures = 0;
const check = (ok, what) => { console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`); if (!ok) failures++; };
const native = (program, args, input) => JSON.parse(execFileSync(program, args, { input, encoding: 'utf8' }));
const nativeMaybe = (program, args, input) => {
  try { return JSON.parse(execFileSync(program, args, { input, encoding: 'utf8', stdio: ['pipe', 'pipe', 'pipe'] })); } catch (e) { return { error: (e.stderr || '').toString().trim(), status: e.status }; }
};

// One ulp up (x > 0).
function nextUp(x) {
  const view = new DataView(new ArrayBuffer(8));
  view.setFloat64(0, x);
  view.setBigUint64(0, view.getBigUint64(0) + 1n);
  return view.getFloat64(0);
}
// Deterministic random numbers (mulberry32), so that the 20 designs are the same on every run.
function random(seed) {
  return () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
// Every number of a JSON answer with its path ("engine.L1").
function numbers(value, path = '', out = {}) {
  if (typeof value === 'number') out[path] = value;
  else if (value && typeof value === 'object' && !Array.isArray(value))
    for (const [k, v] of Object.entries(value)) numbers(v, path ? path + '.' + k : k, out);
  return out;
}

const NUDGED = ['L1', 'L2', 'L3', 'L4', 'M', 'm', 'mb'];
const browser = await launch();
const url = pathToFileURL(resolve(pagePath)).href;
const { page, problems, requests } = await open(browser, url);
try {
  // ---- 1. loads clean ------------------------------------------------------------------------
  check(problems.length === 0, `the page loads from file:// with no console error (${problems.length}: ${problems.join('; ')})`);
  check(requests.length === 0, `and makes no network request (${requests.length}: ${requests.join(' ')})`);
  const api = (name, request) => page.evaluate(([n, r]) => window.trebuchet[n](r), [name, request]);

  // ---- 2. the same numbers as the native programs -----------------------------------------------
  // The calculator is arithmetic and the same libm calls on both sides: its numbers agree to 1e-12.
  // The shot integrates appendix A's equations with sin, cos and exp at every step; the browser's
  // C library (musl, in Emscripten) and the native one (glibc) may round those a last bit apart,
  // and the adaptive integrator and the release search carry such a bit into the result at the
  // size of the method's own rounding noise. That noise is measured on the native program itself:
  // the same design with each of its seven lengths and masses in turn one ulp larger. A figure
  // passes within 1e-12 relative, or within ten times the largest change those one-ulp nudges
  // make natively (the page and the program differ in many such last bits, not one). The energy drift, itself a measure of the
  // integrator's error near 1e-13, passes within 1e-12 absolute.
  const rand = random(20261124);
  const designs = [
    { name: 'Alcalá la Vieja Ca (150 m, 50 kg, θi 30°, F 2/3)', request: { R: '150m', m: '50kg', theta_i_deg: 30, F: '2/3' },
      args: ['--R', '150m', '--m', '50kg', '--theta', '30', '--F', '2/3'] },
  ];
  // Random requests until 20 are designs; one the table does not cover must be refused alike,
  // with the same message (the program's words for options aside).
  let refusals = 0;
  while (designs.length < 21) {
    // The blocks of tab:CPNC: theta_i 30 deg with F 1 or 2/3, 40 deg with F 2/3.
    const R = Math.round(60 + 440 * rand()), m = Math.round(5 + 145 * rand()), [theta, F] = [[30, '1'], [30, '2/3'], [40, '2/3']][Math.floor(3 * rand())];
    const d = { name: `random ${designs.length}: R ${R} m, m ${m} kg, θi ${theta}°, F ${F}`, request: { R: `${R}m`, m: `${m}kg`, theta_i_deg: theta, F },
      args: ['--R', `${R}m`, '--m', `${m}kg`, '--theta', String(theta), '--F', F], L4: 0.8 + 0.4 * rand(), M: 0.8 + 0.4 * rand() };
    const theirs = nativeMaybe(calc, [...d.args, '--format', 'json']);
    if (!theirs.error) { designs.push(d); continue; }
    const mine = await api('design', d.request);
    // Up to the first ';': the programs name options (--extrapolate), the page keys.
    const words = (text) => text.replace(/^trebuchet-calc: /, '').split(';')[0];
    check(mine.error && words(mine.error) === words(theirs.error), `${d.name}: refused alike, "${(mine.error || '').slice(0, 90)}..."`);
    refusals++;
  }
  let worstDesign = 0;
  const engines = [];
  for (const d of designs) {
    const mine = await api('design', d.request), theirs = native(calc, [...d.args, '--format', 'json']);
    const mineNumbers = numbers(mine);
    for (const [key, value] of Object.entries(numbers(theirs))) {
      const difference = Math.abs(mineNumbers[key] - value) / Math.max(Math.abs(value), 1e-300);
      worstDesign = Math.max(worstDesign, difference);
      if (!(difference <= 1e-12)) check(false, `${d.name}: design ${key} ${mineNumbers[key]} against ${value}`);
    }
    // The random engines are taken off the optimum (L4 and M by up to 20 %), so that the shots
    // are not all of one family.
    const engine = { theta_i_deg: theirs.theta_i_deg, L1: theirs.L1, L2: theirs.L2, L3: theirs.L3, L4: theirs.L4 * (d.L4 || 1), M: theirs.M * (d.M || 1), m: theirs.m, mb: theirs.mb };
    engines.push({ name: d.name, engine });
  }
  check(worstDesign <= 1e-12, `the calculator: ${designs.length} designs (and ${refusals} refusals alike), worst relative difference ${worstDesign.toExponential(2)} (within 1e-12)`);
  const denny = JSON.parse(readFileSync(new URL('../cli/denny_standard.json', import.meta.url)));
  delete denny.comment;
  const dennyEngine = (await api('shot', { design: denny })).engine;
  engines.splice(1, 0, { name: "Denny's standard engine", engine: { theta_i_deg: dennyEngine.theta_i_deg, L1: dennyEngine.L1, L2: dennyEngine.L2, L3: dennyEngine.L3, L4: dennyEngine.L4, M: dennyEngine.M, m: dennyEngine.m, mb: dennyEngine.mb } });

  const settingsList = [
    { name: 'vacuum', request: {}, args: [] },
    { name: 'air, release for the range', request: { air: true, release: 'range' }, args: ['--air', '--quality', 'range'] },
    { name: 'air with wind 5 m/s, target 10 m below', request: { air: { wind: 5 }, target_level: -10 }, args: ['--air', '--wind', '5', '--target-level', '-10'] },
  ];
  for (const settings of settingsList) {
    let worstRelative = 0, worstOverBound = 0, compared = 0, refusedAlike = 0;
    let worstKey = '';
    const headline = { R: 0, T: 0, eps: 0, Q: 0, force_factor: 0 };
    const nudged = [];
    const keys = [null, ...NUDGED];
    for (const { engine } of engines) for (const key of keys) nudged.push(key ? Object.assign({}, engine, { [key]: nextUp(engine[key]) }) : engine);
    const all = nativeMaybe(verify, ['-', '--format', 'json', ...settings.args], JSON.stringify(nudged));
    const theirsAll = Array.isArray(all) ? all : [];
    for (let k = 0; k < engines.length; k++) {
      const [theirs, ...nudges] = theirsAll.slice(keys.length * k, keys.length * (k + 1));
      const mine = await api('shot', Object.assign({ design: engines[k].engine }, settings.request));
      if (!theirs || theirs.error || mine.error) {
        const alike = Boolean(theirs && theirs.error) && Boolean(mine.error);
        check(alike, `${engines[k].name}, ${settings.name}: refused alike (native: ${theirs && theirs.error}; page: ${mine.error})`);
        refusedAlike += alike;
        continue;
      }
      const mineNumbers = numbers(mine), nudgeNumbers = nudges.map((n) => numbers(n));
      for (const [key, value] of Object.entries(numbers(theirs))) {
        const difference = Math.abs(mineNumbers[key] - value);
        const floor = Math.max(...nudgeNumbers.map((n) => Math.abs(n[key] - value)));
        const bound = key === 'energy_drift' ? 1e-12 : Math.max(1e-12 * Math.abs(value), 10 * floor);
        compared++;
        if (!(difference <= bound)) check(false, `${engines[k].name}, ${settings.name}: ${key} ${mineNumbers[key]} against ${value} (bound ${bound.toExponential(2)})`);
        if (key !== 'energy_drift') {
          const relative = difference / Math.max(Math.abs(value), 1e-300);
          if (key in headline) headline[key] = Math.max(headline[key], relative);
          if (relative > worstRelative) { worstRelative = relative; worstKey = key; }
        }
        if (difference > 0) worstOverBound = Math.max(worstOverBound, difference / bound);
      }
    }
    check(compared > 0, `the shot, ${settings.name}: ${engines.length} engines, ${compared} numbers, ${refusedAlike} refused by both; worst relative difference ` +
      `${worstRelative.toExponential(2)} (${worstKey}), worst difference over its bound ${worstOverBound.toFixed(3)}; worst of ` +
      Object.entries(headline).map(([k, v]) => `${k} ${v.toExponential(1)}`).join(', '));
  }

  // ---- 3. the animation advances ----------------------------------------------------------------
  const before = await page.evaluate(() => Number(document.getElementById('viewer').dataset.time));
  await page.click('.tv-play');
  await page.waitForTimeout(600);
  const after = await page.evaluate(() => ({ time: Number(document.getElementById('viewer').dataset.time), frame: Number(document.getElementById('viewer').dataset.frame) }));
  check(after.time > before && after.frame > 0, `the animation advances: t ${before} s -> ${after.time.toFixed(3)} s, frame ${after.frame}`);
  await page.click('.tv-play');

  // ---- 4. a shared URL restores the state ------------------------------------------------------
  await page.selectOption('#pair', 'R,T');
  await page.fill('#first', '300m');
  await page.fill('#second', '60kJ');
  await page.check('#air');
  await page.selectOption('#units', 'imperial');
  await page.click('nav button[data-view="edit"]');
  await page.evaluate(() => {  // a drag of the L4 slider
    const slider = document.querySelector('#sliders input[data-key="L4"]');
    slider.value = String(Number(slider.value) * 0.9);
    slider.dispatchEvent(new Event('input'));
    slider.dispatchEvent(new Event('change'));  // let go
  });
  // A drag of L1 and θi, which set the pivot's height: the edited engine still shoots (a stale H
  // in the edited engine would be refused by the program).
  const dragged = await page.evaluate(() => {
    for (const key of ['L1', 'theta_i_deg']) {
      const slider = document.querySelector(`#sliders input[data-key="${key}"]`);
      slider.value = String(Number(slider.value) * 1.05);
      slider.dispatchEvent(new Event('input'));
      slider.dispatchEvent(new Event('change'));
    }
    return { shot: window.trebuchet.current(), text: document.getElementById('shot-message').textContent.slice(0, 160) };
  });
  check(dragged.shot !== null && dragged.shot.R > 0, `a drag of L1 and θi shoots the edited engine: R ${dragged.shot && dragged.shot.R} m ${dragged.shot ? '' : dragged.text}`);
  const shared = await page.evaluate(() => ({ url: location.href, state: window.trebuchet.state(), R: document.querySelector('#viewer .tv-figures td').textContent }));
  const second = await open(browser, shared.url);
  const restored = await second.page.evaluate(() => ({ state: window.trebuchet.state(), R: document.querySelector('#viewer .tv-figures td').textContent }));
  check(JSON.stringify(restored.state) === JSON.stringify(shared.state) && restored.R === shared.R,
    `a shared URL restores the state (view ${restored.state.view}, units ${restored.state.units}, edited L4 ${restored.state.edit && restored.state.edit.L4}, R shown ${restored.R})`);
  await second.context.close();

  // ---- 5. the downloaded design is accepted by trebuchet-verify ----------------------------------
  const folder = mkdtempSync(join(tmpdir(), 'trebuchet-web-'));
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download-json')]);
  const file = join(folder, 'design.json');
  await download.saveAs(file);
  // The file's engine, shot natively under the page's settings (air, the standard Cd, no wind),
  // is the shot the page shows: R within 1e-9 relative, where section 2 found the page and the
  // program 3.1e-10 apart at most.
  const shown = await page.evaluate(() => window.trebuchet.current());
  const verified = native(verify, [file, '--format', 'json', '--air']);
  const closeness = Math.abs(verified.R - shown.R) / verified.R;
  check(shown.assumptions.air !== 'vacuum' && closeness < 1e-9 && verified.engine.L4 === shown.engine.L4,
    `the downloaded design reads in trebuchet-verify and is the shot shown: R ${verified.R} m natively, ${shown.R} m in the page, relative ${closeness.toExponential(2)}`);

  // ---- 5b. a release set by its pin angle is the program's ---------------------------------------
  // The same engine released where the sling's angle to the long arm closes to 30 deg: the page's
  // shot is the program's (--pin-angle 30) within 1e-9 in R, and releases at that pin to 1e-9 deg.
  await page.selectOption('#release-by', 'pin_angle_deg');
  await page.fill('#release-value', '30deg');
  const pinned = await page.evaluate(() => window.trebuchet.current());
  const pinnedNative = native(verify, [file, '--format', 'json', '--air', '--pin-angle', '30']);
  const pinCloseness = Math.abs(pinnedNative.R - pinned.R) / pinnedNative.R;
  check(pinned.assumptions.release_at && pinned.assumptions.release_at.by === 'pin_angle' && Math.abs(pinned.pin_angle_at_release_deg - 30) < 1e-9 &&
    pinCloseness < 1e-9, `a release at a pin of 30 deg is the program's: R ${pinnedNative.R} m natively, ${pinned.R} m in the page, relative ${pinCloseness.toExponential(2)}`);
  // A pin the sling passes in the trough is refused in the page with the program's words.
  await page.fill('#release-value', '175deg');
  const trough = await page.textContent('#shot-message');
  check(/before lift-off/.test(trough), `a pin passed in the trough is refused: "${trough.slice(0, 120)}"`);
  await page.selectOption('#release-by', 'optimum');

  // ---- 5c. the machine chosen is the program's --machine -----------------------------------------
  // The same engine built as a floating arm: the page's shot is the program's within 1e-9 in R, its
  // record names the machine, and the picture's pivot rolls (its x changes through the shot).
  await page.selectOption('#machine', 'floating-arm');
  const floating = await page.evaluate(() => window.trebuchet.current());
  const floatingNative = native(verify, [file, '--format', 'json', '--air', '--machine', 'floating-arm']);
  const floatingCloseness = Math.abs(floatingNative.R - floating.R) / floatingNative.R;
  const pivots = floating.series.frames.pivot_x;
  check(floating.engine.machine === 'floating-arm' && floatingCloseness < 1e-9 && Math.max(...pivots) - Math.min(...pivots) > 0.5 * floating.engine.L2,
    `a floating arm is the program's: R ${floatingNative.R} m natively, ${floating.R} m in the page, relative ${floatingCloseness.toExponential(2)}; the pivot rolls over ${Math.max(...pivots) - Math.min(...pivots)} m`);
  await page.selectOption('#machine', 'hinged');

  // ---- 5d. a whipper is the program's --machine whipper -------------------------------------------
  // pytrebuchet's default whipper's parts, from a link to the edit view on its 5 m frame: the page's
  // shot is the program's within 1e-9 in R, and the counterweight leaves the arm before the ball.
  const whipperParts = { L1: 4, L2: 2, L3: 4, L4: 4, M: 100, m: 3, mb: 10, theta_i_deg: 30, H: 5 };
  const link = new URLSearchParams({ view: 'edit', machine: 'whipper', edit: JSON.stringify(whipperParts) });
  await page.goto(url + '#' + link.toString());
  await page.reload();  // a new fragment alone does not load the page again
  const whipper = await page.evaluate(async () => { await window.trebuchet.ready; return window.trebuchet.current(); });
  const whipperNative = native(verify, ['shot', '--machine', 'whipper', '--L1', '4m', '--L2', '2m', '--L3', '4m', '--L4', '4m', '--M', '100kg', '--m', '3kg',
    '--mb', '10kg', '--H', '5m', '--format', 'json']);
  const whipperCloseness = whipper && whipper.R ? Math.abs(whipperNative.R - whipper.R) / whipperNative.R : Infinity;
  check(whipper && whipper.engine.machine === 'whipper' && whipperCloseness < 1e-9 && whipper.t_counterweight_free < whipper.t_liftoff,
    `a whipper is the program's: R ${whipperNative.R} m natively, ${whipper && whipper.R} m in the page, relative ${whipperCloseness.toExponential(2)}; ` +
    `the counterweight leaves the arm at ${whipper && whipper.t_counterweight_free} s, the ball at ${whipper && whipper.t_liftoff} s`);
  const phaseText = await page.evaluate(() => { window.trebuchet.viewer().setTime(0.5); return document.getElementById('viewer').textContent; });
  check(/ride on the arm/.test(phaseText), `the viewer says the bodies ride on the arm: "${(phaseText.match(/phase I[^)]*?arm/) || [''])[0]}"`);
  await page.goto(url);
  await page.reload();
  await page.evaluate(() => window.trebuchet.ready);

  // ---- 6. Monte Carlo over Web Workers is the run of one module ---------------------------------
  const request = { attested: { Lb: '9.5m', M: '2.5t..3.5t', m: '50kg' }, samples: 40, seed: 7 };
  const [whole, parts] = await page.evaluate(async (r) => [window.trebuchet.monteCarlo(r), await window.trebuchet.monteCarloParallel(r)], request);
  check(!whole.error && JSON.stringify(whole) === JSON.stringify(parts),
    `a Monte Carlo run over Web Workers equals one run: R p50 ${whole.percentiles && whole.percentiles.R.p50} m, ${whole.error || ''}`);

  // ---- 7. a refusal shows the calculator's own message ------------------------------------------
  await page.click('nav button[data-view="design"]');
  await page.selectOption('#pair', 'R,m');
  await page.fill('#first', '90000m');
  const refusal = await page.textContent('#design-message');
  const nativeRefusal = nativeMaybe(calc, ['--R', '90000m', '--m', '50kg', '--F', '2/3']);
  const sentence = (text) => text.replace(/^trebuchet-calc: /, '').split(';')[0];
  check(nativeRefusal.error && sentence(refusal) === sentence(nativeRefusal.error), `a refusal shows the calculator's own message: "${refusal.slice(0, 150)}"`);

  // ---- 8. the report of trebuchet-verify shot --plot is the same viewer ------------------------
  // Its index.html, opened from the folder, draws the shot inside it: through air when the shot
  // flew through air, NOT PHYSICAL when the model stopped holding.
  const engineFlags = ['--L1', '4.13m', '--L2', '0.88m', '--L4', '3.55m', '--M', '3.11t', '--m', '50kg', '--mb', '174kg'];
  for (const [name, flags, expect] of [['air', ['--F', '2/3', '--air', '--target-level', '-15m'], /in air \(Cd 0\.47\).*target level -15 m/],
                                       ['below', ['--F', '2'], /NOT PHYSICAL/]]) {
    execFileSync(verify, ['shot', ...engineFlags, ...flags, '--plot', join(folder, name)], { stdio: 'ignore' });
    const report = await open(browser, pathToFileURL(join(folder, name, 'index.html')).href, undefined, false);
    const shown = await report.page.evaluate(() => ({ text: document.querySelector('.tv-head').innerText, charts: document.querySelectorAll('.tv-chart svg').length }));
    check(expect.test(shown.text) && !(name === 'air' && /in vacuum/.test(shown.text)) && shown.charts === 5 && report.problems.length === 0,
      `trebuchet-verify shot --plot (${name}): index.html draws the shot with the page's viewer, 4 charts, "${(shown.text.match(expect) || ['nothing'])[0].slice(0, 80)}"`);
    await report.context.close();
  }

  // ---- 9. hostile links and requests (cases a probe of the page found) ------------------------
  // A link's state is anyone's text: markup in it must stay text, and a value of the wrong kind
  // must fall back to its default, with the page working and no error.
  for (const hash of ['#view=edit&edit={"L1":"\\"><img src=x onerror=\\"document.title=\'XSS\'\\">"}', '#first=null&second=null',
                      '#attested=null&view=reconstruct', '#view=edit&edit=true', '#view=nowhere&units=zz', '#attested="abc"&view=reconstruct']) {
    const hostile = await open(browser, url + hash);
    const seen = await hostile.page.evaluate(() => ({ title: document.title, views: [...document.querySelectorAll('.view')].filter((v) => !v.hidden).length,
                                                     R: (document.querySelector('#viewer .tv-figures td') || {}).textContent }));
    check(seen.title.startsWith('trebuchet') && seen.views === 1 && seen.R && hostile.problems.length === 0,
      `the link ${hash.slice(0, 40)}... opens one view with a shot (R ${seen.R}), no script, no error ${hostile.problems.join('; ')}`);
    await hostile.context.close();
  }
  const answers = await page.evaluate(() => {
    const t = window.trebuchet, loop = { R: '150m' }, nested = {};
    loop.self = loop;
    let at = nested;
    for (let k = 0; k < 100000; k++) { at.a = {}; at = at.a; }
    // Objects that run code when read (issue 34): a getter that throws, a Proxy whose traps throw,
    // a toJSON that throws something that is no Error.
    const getter = { R: '150m' };
    Object.defineProperty(getter, 'm', { enumerable: true, get() { throw new Error('no m here'); } });
    const proxy = new Proxy({ R: '150m', m: '50kg' }, { ownKeys() { throw new TypeError('no keys'); }, get() { throw new RangeError('no values'); } });
    const odd = { R: '150m', m: '50kg', toJSON() { throw { toString() { throw new Error('not even this'); } }; } };
    return [t.design(getter), t.design(proxy), t.design(odd), t.shot({ design: getter }),
            t.design(undefined), t.design(nested), t.design(loop), t.design({ R: '150m', m: '50kg', scale: -1 }),
            t.shot({ design: t.design({ R: '150m', m: '50kg' }), n: -1 }), t.shot({ design: t.design({ R: '150m', m: '50kg' }), tolerance: 0 }),
            t.monteCarlo({ design: { L1: 4, L2: 1, L3: 2, L4: 4, M: '2t..3t', m: 50, mb: 200 }, samples: 2, outcomes: [['1', 2, 3, 4], [1, 2, 3, 4]] })];
  });
  const kinds = answers.map((a) => a.kind);
  check(answers.every((a) => a.error && a.kind !== 'numerical'),
    `hostile requests are refused as bad input, not failures: ${kinds.join(', ')}; e.g. "${answers[0].error}", "${answers[8].error}"`);
  // Issue 62 at the page's door: a number under a key that is no input is refused by name, a
  // text passes through by name, and a value beside a record's engine is refused, not dropped.
  const unread = await page.evaluate(() => {
    const t = window.trebuchet, e = { L1: 4.13, L2: 0.88, F: 2 / 3, L4: 3.55, M: 3110, m: 50, mb: 174 };
    const record = t.shot({ design: e });
    return { number: t.shot({ design: Object.assign({ year: 1304 }, e) }), text: t.shot({ design: Object.assign({ site: 'Alcalá' }, e) }),
             beside: t.shot({ design: Object.assign({}, record, { L4: 2 }) }) };
  });
  check(unread.number.kind === 'usage' && unread.number.names.includes('year') && /"notes"/.test(unread.number.error),
    `a number under no input's key is refused by name: "${unread.number.error}"`);
  check(unread.text.passed && unread.text.passed.site === 'Alcalá', `a text passes through, named under passed: ${JSON.stringify(unread.text.passed)}`);
  check(unread.beside.kind === 'usage' && unread.beside.names.includes('L4'), `a value beside a record's engine is refused by name: "${unread.beside.error}"`);
  const parallel = await page.evaluate(() => window.trebuchet.monteCarloParallel({ attested: { Lb: '9.5m', M: '2.5t..3.5t', m: '50kg' }, samples: -1 }));
  check(Boolean(parallel.error), `monteCarloParallel refuses samples -1 before any work: "${parallel.error}"`);
} finally {
  await browser.close();
}
check(failures === 0, `${failures} failure(s)`);
process.exit(failures ? 1 : 0);
