// The page: design, edit, reconstruct, over the library compiled to WebAssembly (trebuchet.js,
// createTrebuchet) and drawn by viewer.js. window.trebuchet exposes the library's requests to
// scripts in the programs' JSON schema (docs/web.md). The whole state lives in the URL's hash.
(function () {
  'use strict';
  const $ = (id) => document.getElementById(id);
  const V = window.TrebuchetViewer;
  // The library's table of inputs (api fields, docs/inputs.md), read once the module is ready:
  // the calculator's givens (the capacity first), complete's attested values and the engine's
  // values come from it, each with its label and dimension.
  let INPUTS = [], QUANTITIES = [], ATTESTED = [], ENGINE = [];
  const EXAMPLES = {};
  function readInputs() {
    const tables = JSON.parse(module.fields('{}'));
    INPUTS = tables.fields;
    // The settings' controls say what their rows say (settings.def): the flag's, the key's and the page's one text.
    for (const [id, key] of [['air', 'air'], ['cd', 'cd'], ['wind', 'wind'], ['release', 'quality'], ['target-level', 'target_level'], ['range-from', 'range_from']]) {
      const row = tables.settings.find((s) => s.key === key);
      const control = document.getElementById(id);
      if (row && control) control.title = row.help + (row.default ? ' (default ' + row.default + ')' : '');
    }
    const givens = INPUTS.filter((f) => f.operations.includes('given'));
    QUANTITIES = givens.filter((f) => f.group === 'capacity').concat(givens.filter((f) => f.group !== 'capacity')).map((f) => f.key);
    ATTESTED = INPUTS.filter((f) => f.operations.includes('complete') && (f.group === 'engine' || f.group === 'alternative')).map((f) => [f.key, f.label]);
    ENGINE = INPUTS.filter((f) => f.group === 'engine' && f.operations.includes('shot'));
    // A given's example: its value in the optimal engine of the page's first pair (150 m, 50 kg), so that any two agree.
    const example = JSON.parse(module.design(JSON.stringify({ R: '150m', m: '50kg' })));
    for (const f of givens) EXAMPLES[f.key] = V.significant(example[f.key], 3) + f.unit;
  }

  let module = null;
  const state = {
    view: 'design', units: 'si', pair: 'R,m', first: ['R', '300m'], second: ['m', '50kg'], theta: '30', F: '2/3',
    air: false, cd: '0.47', wind: '0m/s', release: 'Q', target_level: '0m', range_from: 'pivot', release_by: 'optimum', release_value: '',
    machine: 'hinged', edit: null, attested: { Lb: '9.5m', M: '3t', m: '50kg' }, samples: '200',
    projectile: 'stone', projectile_density: '3000kg/m3', projector: false, sweep_key: 'L4', sweep_from: '', sweep_to: '',
    own_table: false, edit_from: 'design',
  };
  const DEFAULTS = JSON.stringify(state);  // a link carries only what differs from these, so that it stays short (and its QR code coarse)
  const LAYOUT = ['projector'];  // how the page is laid out on this screen: no link carries it
  // A whipper that throws, to start from: pytrebuchet's default masses and long arm, its short arm,
  // the counterweight's rope and the sling changed (1.5, 3 and 5 m) on a 6 m frame, where its
  // default (2, 4, 4 m on 5 m) lets the sling go slack and the weight through the ground. Its H as
  // given, its start as the page builds every whipper (asBuilt).
  const WHIPPER = { L1: 4, L2: 1.5, L3: 3, L4: 5, M: 100, m: 3, mb: 10, theta_i_deg: 30, H: 6 };
  let linkEdit = null;   // a link's edited values, put over the engine its edit view opens on
  const MATERIALS = ['stone', 'iron', 'lead', 'clay'];
  const MACHINE_NAMES = { hinged: 'hinged counterweight', fixed: 'fixed counterweight', 'floating-arm': 'floating arm', whipper: 'whipper' };  // the library's names (air.hpp, projectile_materials)
  let designed = null;   // the calculator's design (JSON), or null when refused
  let shown = null;      // the engine the shot is of (engine keys), and its shot
  let editBase = null;   // the engine the edit view opened: the one shown when Edit was chosen
  let editFrom = null;   // the view it was shown in
  let lastSweep = null;  // the what-if sweep drawn: {request, answer}
  let viewer = null;
  const q = (value, dimension) => V.quantity(value, dimension, state.units);  // in the units chosen

  // ---- the library --------------------------------------------------------------------------
  // A number JSON cannot carry (NaN, Infinity) would arrive as null: it is refused here, by name.
  // (Deeper than the module reads, 32 levels, it is refused there; this walk stops at 40.)
  function notFinite(value, path, depth) {
    if (typeof value === 'number') return isFinite(value) ? null : [path, value];
    if (value && typeof value === 'object' && depth < 40) {
      for (const [k, v] of Object.entries(value)) { const found = notFinite(v, path ? path + '.' + k : k, depth + 1); if (found) return found; }
    }
    return null;
  }
  const refused = (error, kind, names) => ({ error, kind, names: names || [] });
  function call(name, request) {
    if (!request || typeof request !== 'object' || Array.isArray(request))
      return refused(`the request must be an object of keys, like {R: "150m", m: "50kg"}; got ${Array.isArray(request) ? 'an array' : String(request)}`, 'usage');
    // Reading the request runs its code, if it has any (a getter, a Proxy, toJSON): whatever that
    // throws is the request's fault, refused by name like a BigInt or an object that holds itself.
    let text;
    try {
      const bad = notFinite(request, '', 0);
      if (bad) return refused(`${bad[0]}: ${bad[1]} is not a finite number; give a number or a value with a unit like "150m"`, 'bad_number', [bad[0]]);
      text = JSON.stringify(request);
      if (typeof text !== 'string') throw new TypeError('it writes as nothing');
    } catch (e) {
      let why = 'it threw';
      try { why = String(e && e.message ? e.message : e); } catch (_) { /* what it threw cannot be read either */ }
      return refused(`the request cannot be written as JSON (${why}); give plain objects of numbers, strings, true or false`, 'usage');
    }
    try {
      return JSON.parse(module[name](text));
    } catch (e) {  // the module itself failed (out of memory, say): an internal error, not the request's
      return { error: `internal error in the module (${e.message}); reload the page, and please report the request`, kind: 'numerical', names: [] };
    }
  }
  function settings() {
    const s = { quality: state.release, target_level: state.target_level, range_from: state.range_from };
    if (state.air) {
      s.air = { drag_coefficient: /^re$/i.test(state.cd.trim()) ? 'Re' : state.cd, wind: state.wind,
        projectile_density: state.projectile === 'density' ? state.projectile_density : state.projectile };
    }
    return s;
  }
  // The settings as trebuchet-verify's flags, so that a downloaded engine is shot again as the page shot it.
  function verifyFlags() {
    const flags = [];
    if (state.release !== 'Q') flags.push('--quality', state.release);
    if (state.target_level.trim()) flags.push('--target-level', state.target_level.trim());
    if (state.range_from !== 'pivot') flags.push('--range-from', state.range_from);
    if (state.air) {
      flags.push('--air', '--cd', /^re$/i.test(state.cd.trim()) ? 'Re' : state.cd.trim(), '--wind', state.wind.trim(),
        '--projectile', state.projectile === 'density' ? state.projectile_density.trim() : state.projectile);
    }
    return flags.map((f) => (/^[-+\w.:/=±]+$/.test(f) ? f : "'" + f.replace(/'/g, "'\\''") + "'"));
  }
  // The engine as the machine chosen (its key "machine", none for the paper's) with the release
  // its builder set, when one is set (release_time, release_angle_deg or pin_angle_deg, keys of
  // the table of inputs' release group).
  function asBuilt(engine) {
    const built = state.machine === 'hinged' ? Object.assign({}, engine) : Object.assign({}, engine, { machine: state.machine });
    // The whipper: pytrebuchet's start, its long arm 60° up, on the engine's frame (its H, as
    // designed: L1 cos θi, or as a link gives it).
    if (state.machine === 'whipper') Object.assign(built, { theta_i_deg: -150, H: engine.H || engine.L1 * Math.cos(engine.theta_i_deg * Math.PI / 180) });
    else delete built.H;  // the other machines' pivot stands at L1 cos θi: a whipper's frame is not theirs
    if (state.release_by === 'optimum' || !state.release_value.trim()) return built;
    return Object.assign(built, { [state.release_by]: state.release_value });
  }
  // The engine keys a design or shot answer carries, as the programs read them back: the
  // engine's values, its diameter and its material (F follows from L3, and H from L1 and θi,
  // which the sliders change; the whipper's H is asBuilt's).
  function engineOf(answer) {
    const engine = {};
    for (const f of INPUTS)
      if (f.operations.includes('shot') && !['F', 'H'].includes(f.key) && ['engine', 'alternative', 'material'].includes(f.group) && answer[f.key] !== undefined) engine[f.key] = answer[f.key];
    if (engine.D === 0) delete engine.D;
    return engine;
  }

  // ---- URL state ----------------------------------------------------------------------------
  // The edited values a link carries: those that differ from the engine the edit view opened on,
  // which the link's other values make again (its givens, its attested values, the whipper).
  // The engine a link's edit view would open on, made from the state as it stands (openEditBase),
  // remembered for the values it is made from: a completion costs many shots.
  let rebuilt = { key: null, engine: null };
  function linkBase() {
    const from = state.edit_from;
    const key = JSON.stringify(from === 'whipper' ? [from] : from === 'reconstruct' ? [from, state.attested, settings()]
      : [from, state.first, state.second, state.theta, state.F, ownTable() && state.machine]);
    if (rebuilt.key !== key) rebuilt = { key, engine: baseFrom(from) };
    return rebuilt.engine;
  }
  function editChanges() {
    if (!state.edit || !editBase) return state.edit;
    // Where the link would open on another engine than this edit's (the machine or its own
    // table changed since Edit was opened), it carries the edited engine whole.
    if (JSON.stringify(linkBase()) !== JSON.stringify(editBase)) return state.edit;
    const changed = {};
    for (const [key, value] of Object.entries(state.edit)) if (value !== editBase[key]) changed[key] = value;
    return Object.keys(changed).length ? changed : null;
  }
  // The settings the shot does not read as the page stands, which a link leaves out: the air's
  // values in vacuum, a typed density beside a named material, a release's value at the optimum.
  function unreadKeys(s) {
    const keys = [];
    if (!s.air) keys.push('cd', 'wind', 'projectile', 'projectile_density');
    else if (s.projectile !== 'density') keys.push('projectile_density');
    if (s.release_by === 'optimum') keys.push('release_value');
    return keys;
  }
  function saveState() {
    const params = new URLSearchParams();
    const defaults = JSON.parse(DEFAULTS);
    const shared = Object.assign({}, state, state.view === 'edit' ? { edit: editChanges() } : { edit: null, edit_from: defaults.edit_from });
    for (const k of unreadKeys(shared)) delete shared[k];
    for (const [k, v] of Object.entries(shared))
      if (v !== null && !LAYOUT.includes(k) && JSON.stringify(v) !== JSON.stringify(defaults[k])) params.set(k, typeof v === 'object' ? JSON.stringify(v) : String(v));
    history.replaceState(null, '', '#' + params.toString());
  }
  // A link's state is anyone's text: each value is checked against what it must be, and one
  // that is not keeps its default (a hand-edited or hostile link can neither break the page nor
  // put markup into it).
  const isText = (v) => typeof v === 'string' && v.length <= 200;
  const CHECKS = {
    view: (v) => ['design', 'edit', 'reconstruct'].includes(v), units: (v) => ['si', 'imperial'].includes(v),
    pair: (v) => ['R,m', 'R,T', 'R,M', 'Lb,l', 'any'].includes(v),
    first: (v) => Array.isArray(v) && v.length === 2 && QUANTITIES.includes(v[0]) && isText(v[1]),
    second: (v) => Array.isArray(v) && v.length === 2 && QUANTITIES.includes(v[0]) && isText(v[1]),
    theta: (v) => ['30', '40'].includes(v), F: (v) => ['1', '2/3'].includes(v), air: (v) => typeof v === 'boolean',
    cd: isText, wind: isText, release: (v) => ['Q', 'eps', 'range'].includes(v), target_level: isText,
    release_by: (v) => ['optimum', 'pin_angle_deg', 'release_angle_deg', 'release_time'].includes(v), release_value: isText,
    machine: (v) => ['hinged', 'fixed', 'floating-arm', 'whipper'].includes(v),
    range_from: (v) => ['pivot', 'release'].includes(v), samples: isText,
    projectile: (v) => MATERIALS.concat(['density']).includes(v), projectile_density: isText,
    own_table: (v) => typeof v === 'boolean', edit_from: (v) => ['design', 'reconstruct', 'whipper'].includes(v),
    sweep_key: (v) => sweepable().some((f) => f.key === v), sweep_from: isText, sweep_to: isText,
    // An edited engine: keys of a shot's design, each a finite number, the engine's own values positive.
    edit: (v) => v === null || (typeof v === 'object' && !Array.isArray(v) && Object.keys(v).length > 0 &&
      Object.entries(v).every(([key, x]) => INPUTS.some((f) => f.key === key && f.operations.includes('shot')) && typeof x === 'number' &&
        isFinite(x) && (x > 0 || (key === 'L3' && x === 0) || !ENGINE.some((f) => f.key === key)))),  // L3 0: the fixed and floating-arm tables' counterweight at the arm's end
    attested: (v) => typeof v === 'object' && v !== null && !Array.isArray(v) &&
      Object.entries(v).every(([key, text]) => ATTESTED.some(([k]) => k === key) && isText(text)),
  };
  // A link's value the page cannot take is left out and named, never dropped without a word.
  function loadState() {
    const params = new URLSearchParams(location.hash.slice(1));
    const refused = [];
    const shown = (text) => (text.length > 40 ? text.slice(0, 40) + '…' : text);
    for (const [k, text] of params) {
      if (!Object.prototype.hasOwnProperty.call(CHECKS, k)) { refused.push(`${shown(k)} (no setting of this page)`); continue; }
      let value = text;
      if (k === 'air' || k === 'own_table') value = text === 'true' ? true : text === 'false' ? false : null;
      else if (['first', 'second', 'edit', 'attested'].includes(k)) {
        try { value = JSON.parse(text); } catch (e) { refused.push(`${k} = ${shown(text)}`); continue; }
      }
      // An edited engine keeps the values it can take; each other one is named.
      if (k === 'edit' && value && typeof value === 'object' && !Array.isArray(value) && !CHECKS.edit(value)) {
        for (const [key, x] of Object.entries(value))
          if (!CHECKS.edit({ [key]: x })) { refused.push(`edit.${shown(key)} = ${shown(JSON.stringify(x))}`); delete value[key]; }
        if (Object.keys(value).length === 0) continue;
      }
      if (CHECKS[k](value)) state[k] = value;
      else refused.push(`${k} = ${shown(text)}`);
    }
    const message = $('link-message');
    message.hidden = refused.length === 0;
    message.textContent = refused.length ? `This link's ${refused.join(', ')} ${refused.length > 1 ? 'are' : 'is'} not a value the page takes, so ` +
      `${refused.length > 1 ? 'they were' : 'it was'} left out; the page shows the rest.` : '';
    linkEdit = state.edit;  // put over the engine the edit view opens on (showView)
    state.edit = null;
    if (state.theta === '40') state.F = '2/3';
  }

  // ---- design ---------------------------------------------------------------------------------
  function fillPairSelects() {
    for (const id of ['first-name', 'second-name']) {
      const select = $(id);
      select.innerHTML = QUANTITIES.map((q) => `<option value="${q}">${q}</option>`).join('');
    }
  }
  // A drag of a given's slider: a factor of 4 either way of its value as typed, on a log scale,
  // in the unit it was typed in ("500ft" drags in feet).
  function givenSlider(slot) {
    const slider = $(slot + '-drag'), text = String(state[slot][1]).trim();
    const number = text.match(/^[+]?([0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?)\s*([A-Za-z]*)$/);
    const value = number ? Number(number[1]) : NaN;
    slider.disabled = !(isFinite(value) && value > 0 && value < 1e300);  // a value the slider cannot read: type it
    slider.dataset.centre = slider.disabled ? '1' : String(value);
    slider.dataset.unit = number ? number[3] : '';
    slider.value = '0';
  }
  function showPair() {
    const any = state.pair === 'any';
    document.querySelectorAll('.any-pair').forEach((s) => { s.hidden = !any; });
    $('first-label').hidden = any; $('second-label').hidden = any;
    $('first-name').value = state.first[0]; $('second-name').value = state.second[0];
    $('first-label').textContent = state.first[0]; $('second-label').textContent = state.second[0];
    $('first').value = state.first[1]; $('second').value = state.second[1];
    givenSlider('first'); givenSlider('second');
  }
  // The machines with a table of their own optimal engines (docs/machines.md).
  const ownTable = () => state.own_table && ['fixed', 'floating-arm'].includes(state.machine);
  function runDesign() {
    const request = ownTable() ? { theta_i_deg: Number(state.theta), machine: state.machine } : { theta_i_deg: Number(state.theta), F: state.F };
    request[state.first[0]] = state.first[1];
    request[state.second[0]] = state.second[1];
    const answer = call('design', request);
    const message = $('design-message');
    if (answer.error) {
      designed = null;
      message.className = 'message refused';
      message.textContent = answer.error;
      $('design-result').innerHTML = '';
      return false;
    }
    designed = answer;
    message.className = 'message';
    message.textContent = (answer.warnings || []).join(' ');
    const block = ownTable() ? `the ${MACHINE_NAMES[state.machine]}'s own optimal engine, θi = ${answer.theta_i_deg}°`
      : `the optimal engine${answer.branch === 'none' ? '' : ' (' + answer.branch + ' branch)'}, θi = ${answer.theta_i_deg}°, F = ${Math.abs(answer.F - 2 / 3) < 1e-12 ? '2/3' : V.significant(answer.F, 4)}`;
    $('design-result').innerHTML = `<table class="tv-figures"><caption>${block}</caption>
      <tr><th>capacity</th><td>R = ${q(answer.R, 'length')}, T = ${q(answer.T, 'energy')} (in vacuum)</td></tr>
      <tr><th>beam</th><td>L1 = ${q(answer.L1, 'length')}, L2 = ${q(answer.L2, 'length')}, Lb = ${q(answer.Lb, 'length')}, diameter D = ${q(answer.D, 'length')}</td></tr>
      <tr><th>arm, sling, pivot</th><td>L3 = ${q(answer.L3, 'length')}, L4 = ${q(answer.L4, 'length')}, H = ${q(answer.H, 'length')}</td></tr>
      <tr><th>masses</th><td>counterweight M = ${q(answer.M, 'mass')}, projectile m = ${q(answer.m, 'mass')}, beam mb = ${q(answer.mb, 'mass')}</td></tr></table>`;
    return true;
  }

  // ---- the machine chosen, in words ---------------------------------------------------------------
  // What the engine shown is for the machine chosen, and what to do for that machine's best: the
  // calculator's optimum is the hinged machine's unless the machine's own table is asked for.
  function showMachineNote() {
    const note = $('machine-note'), machine = state.machine, name = MACHINE_NAMES[machine];
    $('own-table-row').hidden = !['fixed', 'floating-arm'].includes(machine);
    $('own-table').checked = state.own_table;
    $('whipper-example').hidden = machine !== 'whipper';
    if (machine === 'hinged') { note.textContent = 'The paper\'s machine: the counterweight hangs from the short arm on its own arm L3.'; return; }
    if (machine === 'whipper') {
      note.textContent = 'There is no table of optimal whippers: ' + (state.view === 'edit' ? 'this engine is shot as a whipper' : 'the engine shown is the hinged machine\'s, started as a whipper') +
        ' (its long arm 60° up, the counterweight and the ball resting on it). A whipper needs proportions of its own: where the shot says NOT PHYSICAL, the warnings above ' +
        'the animation say where the model stops holding. Edit L3 and L4 in view 2, or start from a whipper that throws:';
      return;
    }
    if (state.view === 'edit') {
      note.textContent = `This engine is shot as a ${name}, its proportions as edited. The box designs the ${name}'s own optimal engine in view 1, Design.`;
      return;
    }
    note.textContent = ownTable()
      ? `The ${name}'s own optimal engine, from its own table (docs/machines.md): the counterweight at the short arm's end.`
      : `The optimal engine of view 1 is the hinged machine's (tab:CPNC), here built as a ${name}: its proportions are not this machine's best, so its efficiency ε and Q fall. Tick the box for the ${name}'s own optimal engine.`;
  }

  // ---- the shot -------------------------------------------------------------------------------
  let downloads = null;  // the shot's record and series as data: addresses, written on demand
  for (const [id, kind] of [['download-json', 'json'], ['download-csv', 'csv']]) V.hrefOnDemand($(id), () => (downloads ? downloads[kind]() : '#'));
  // The shot drawn where the animation stood, so that a drag shows the same moment; with
  // `sliding`, the charts drawn before stay, greyed, until flushFollow draws them anew.
  let drawnView = null;  // the view whose shot the viewer holds
  function drawShot(answer, sliding) {
    drawnView = state.view;
    viewer = V.render($('viewer'), answer, { units: state.units, time: viewer ? viewer.time() : 0, playing: viewer ? viewer.playing() : false, keepCharts: sliding });
  }
  function runShot(engine, title, sliding) {
    // The fixed and floating-arm tables' engines hang the counterweight at the short arm's end (L3 = 0);
    // the hinged machine and the whipper need an arm for it.
    const armless = engine.L3 === 0 && ['hinged', 'whipper'].includes(state.machine);
    const answer = armless ? refused(`This engine has no counterweight arm (L3 = 0): it is the fixed or floating-arm machine's own optimum, whose counterweight sits at the short arm's end. ` +
      `The ${MACHINE_NAMES[state.machine]} needs an arm: choose that machine again, or design the ${MACHINE_NAMES[state.machine]}'s engine in view 1.`, 'usage', ['L3'])
      : call('shot', Object.assign({ design: asBuilt(engine), series: true }, settings()));
    if (answer.error) {
      refuseShot(answer.error);
      return null;
    }
    $('shot-message').hidden = true;
    $('viewer').classList.remove('stale');
    document.querySelector('.downloads').hidden = false;
    shown = { engine, shot: answer };
    $('shot-title').textContent = title;
    drawShot(answer, sliding);
    // The shot's record, as the programs write it (its engine and the settings it was shot with),
    // less its series: trebuchet-verify and trebuchet.shot() read it back as the same shot
    // (docs/schema.md); "command" is that shot, with the page's settings as flags too.
    const name = { design: 'optimal-engine', edit: 'edited-engine', reconstruct: 'completed-engine' }[state.view] || 'engine';
    const command = ['trebuchet-verify', 'shot', name + '.json'].concat(verifyFlags()).join(' ');
    // Written when a link is about to be followed, not at each shot: a slider shoots at every move.
    downloads = {
      json: () => {
        const record = Object.assign({}, answer, { command });
        delete record.series;
        return 'data:application/json;charset=utf-8,' + encodeURIComponent(JSON.stringify(record, null, 2) + '\n');
      },
      csv: () => 'data:text/csv;charset=utf-8,' + encodeURIComponent(V.seriesCsv(answer)),
    };
    $('download-json').download = name + '.json';
    $('download-csv').download = name + '-shot.csv';
    showProjectile(answer);
    return answer;
  }
  // No shot for the input as it stands (a box half typed: "180m" passes "1" and "18"): the refusal
  // goes above the scene, and the last shot stays drawn, greyed, until the input reads again.
  function refuseShot(text) {
    shown = null;
    $('shot-message').textContent = text;
    $('shot-message').hidden = false;
    // Another view's last shot is not this one's: it goes, with its title.
    if (drawnView !== state.view) { $('viewer').innerHTML = ''; viewer = null; $('shot-title').textContent = 'No engine to shoot'; }
    $('viewer').classList.toggle('stale', $('viewer').childElementCount > 0);
    document.querySelector('.downloads').hidden = true;  // no shot: nothing to download, not the last one's
    showProjectile(null);
  }
  const escapeHtml = V.escapeHtml;
  // The ball the shot flew: its material and the diameter that gives it its mass (in air, its drag).
  function showProjectile(answer) {
    if (!answer) { $('projectile-size').textContent = 'No shot: see the message above the animation.'; $('projectile-size').dataset.diameter = ''; return; }
    const a = answer.assumptions.air, words = { stone: 'stone', iron: 'iron', lead: 'lead', clay: 'fired clay', density: 'a ball' }[state.projectile];
    $('projectile-size').textContent = a === 'vacuum'
      ? 'The material sets the ball\'s size for its mass, and so its drag: it matters only in air.'
      : `The ball: ${words} of ${V.significant(a.projectile_density, 5)} kg/m³, m = ${q(answer.engine.m, 'mass')}, diameter d = ${q(a.projectile_diameter, 'length')}.`;
    $('projectile-size').dataset.diameter = a === 'vacuum' ? '' : String(a.projectile_diameter);
  }

  // ---- edit -----------------------------------------------------------------------------------
  // The text a typed box shows for a value: in the units chosen, as the library reads it back ("5.8 m", "19.03 ft", "30 deg").
  const typedText = (value, dimension) => (dimension === 'angle' ? V.significant(value, 4) + ' deg' : q(value, dimension));
  function buildSliders() {
    const box = $('sliders');
    box.innerHTML = '';
    const base = editBase || (designed ? engineOf(designed) : state.edit);
    if (!base) { box.textContent = 'Design an engine first (view 1).'; return; }
    if (!state.edit) state.edit = Object.assign({}, base);
    // A slider and a typed box for each of the engine's values the design has (a propped angle it
    // has not; the whipper's θi, pytrebuchet's -150°, neither), reaching the edited value where a
    // link or a typed value takes it beyond the design's range.
    // D, the beam's diameter, with them: it sets the beam's stress, which the strength box judges.
    for (const { key, dimension, label } of ENGINE.concat(INPUTS.filter((f) => f.key === 'D')).filter((f) => base[f.key] > 0 && !(f.key === 'theta_i_deg' && state.machine === 'whipper'))) {
      if (!(state.edit[key] > 0)) state.edit[key] = base[key];
      const centre = base[key], edited = state.edit[key];
      const [lo, hi] = key === 'theta_i_deg' ? [10, 80] : [Math.min(centre * 0.3, edited * 0.9), Math.max(centre * 2.5, edited * 1.1)];
      const row = document.createElement('div');
      row.className = 'slider';
      row.innerHTML = `<span class="label"><span class="name"></span><span class="words"></span></span><input type="range" step="any"><input class="typed" autocomplete="off">`;
      row.querySelector('.name').textContent = key === 'theta_i_deg' ? 'θi' : key;
      row.querySelector('.words').textContent = key === 'theta_i_deg' ? 'start angle' : label.replace(/ \[deg\]$/, '');
      const input = row.querySelector('input[type="range"]'), typed = row.querySelector('.typed');
      Object.assign(input, { min: String(lo), max: String(hi), value: String(state.edit[key]) });
      input.dataset.key = key;
      typed.dataset.key = key;
      input.setAttribute('aria-label', key + ', ' + label);
      typed.setAttribute('aria-label', key + ' typed, with its unit');
      typed.title = 'type a value with its unit, metric or imperial (' + (INPUTS.find((f) => f.key === key) || { units: [] }).units.join(', ') + '), then Enter';
      const show = () => { typed.value = typedText(state.edit[key], dimension); typed.removeAttribute('aria-invalid'); };
      show();
      // A drag writes the value to the 4 digits the box shows, which a link then carries as they are.
      input.addEventListener('input', () => { state.edit[key] = Number(V.significant(Number(input.value), 4)); show(); update({ sliding: true }); });
      input.addEventListener('change', flushFollow);  // the hand lets go: the comparison and the what-if now
      // A typed value is read by the library, as the programs read it; the slider follows, widened to reach it.
      typed.addEventListener('change', () => {
        const answer = call('value', { key, text: typed.value });
        const message = $('edit-message');
        // A value the library refuses for this key (out of its ordinary range, say) is refused
        // here, in place, with the library's words; the engine and the slider keep theirs.
        let why = answer.error;
        if (!why && !(answer.value > 0 && (key !== 'theta_i_deg' || answer.value < 90)))
          why = `${key}: ${typed.value} must be positive${key === 'theta_i_deg' ? ' and below 90 degrees' : ''}; type it again`;
        if (!why) {
          const trial = call('shot', Object.assign({ design: asBuilt(Object.assign({}, state.edit, { [key]: answer.value })) }, settings()));
          // Refused for this value: the message names it ("design.L1 = 1e+30 m is not of ordinary size ...").
          if (trial.error && (trial.error.startsWith(`design.${key} `) || (trial.names || []).includes(key))) why = trial.error;
        }
        if (why) {
          typed.setAttribute('aria-invalid', 'true');
          message.className = 'message refused';
          message.textContent = why;
          return;
        }
        message.className = 'message'; message.textContent = '';
        state.edit[key] = answer.value;
        input.min = String(Math.min(Number(input.min), answer.value)); input.max = String(Math.max(Number(input.max), answer.value));
        input.value = String(answer.value);
        show();
        update();
      });
      box.appendChild(row);
    }
    buildParts();
    const from = { design: 'the optimal engine of view 1, Design', reconstruct: 'the completed engine of view 3, Reconstruct', whipper: 'a whipper that throws (pytrebuchet\'s masses and long arm; L2 1.5 m, L3 3 m, L4 5 m on a 6 m frame)' }[editFrom];
    $('edit-source').textContent = 'Editing ' + (from || (editBase ? 'the engine of the link' : 'the optimal engine of view 1, Design')) + '.';
    fillSweepKeys();
  }

  // ---- the engine as built: a box for each part row of the table of inputs ------------------------
  // Every part a shot takes has its box, so that a new part row gets one with no new code, but
  // those the page sets another way or does not model (docs/web.md says why).
  const PARTS_LEFT_OUT = {
    projectile_diameter: 'the projectile select sets the ball\'s size from its material',
    rope_diameter: 'the rope\'s drag acts only with the air in the sling, which the page does not model',
    rope_cd: 'the rope\'s drag acts only with the air in the sling, which the page does not model',
    rope_angle_deg: 'the whipper\'s start, which the page sets as pytrebuchet\'s',
  };
  function buildParts() {
    const rows = $('part-rows');
    rows.innerHTML = '';
    for (const f of INPUTS.filter((x) => x.group === 'part' && x.operations.includes('shot') && !PARTS_LEFT_OUT[x.key])) {
      const row = document.createElement('label');
      row.className = 'row';
      row.innerHTML = '<span></span><input autocomplete="off">';
      row.querySelector('span').textContent = f.label;
      const box = row.querySelector('input');
      box.dataset.key = f.key;
      box.placeholder = f.default ? f.default : 'not given';
      box.title = f.help + (f.units.length ? ' (' + f.units.join(', ') + ')' : '');
      box.value = state.edit && state.edit[f.key] !== undefined ? typedText(state.edit[f.key], f.dimension) : '';
      box.addEventListener('change', () => setPart(f, box));
      rows.appendChild(row);
    }
    $('parts-left-out').textContent = 'No box: ' + Object.entries(PARTS_LEFT_OUT).map(([key, why]) => `${key} (${why})`).join('; ') + '.';
    $('parts').open = INPUTS.some((f) => f.group === 'part' && state.edit && state.edit[f.key] !== undefined);
  }
  // A part's typed value, read by the library as the programs read its flag; an empty box takes
  // the part away. A value the library refuses is said in place, the engine keeping its own.
  function setPart(f, box) {
    const message = $('edit-message');
    const text = box.value.trim();
    const answer = text ? call('value', { key: f.key, text }) : { value: undefined };
    if (answer.error) {
      box.setAttribute('aria-invalid', 'true');
      message.className = 'message refused';
      message.textContent = answer.error;
      return;
    }
    box.removeAttribute('aria-invalid');
    message.className = 'message'; message.textContent = '';
    if (answer.value === undefined) delete state.edit[f.key];
    else state.edit[f.key] = answer.value;
    update();
  }

  // ---- what if: one value of the edited engine over a range (api sweep) -------------------------
  // The values a sweep may vary: the engine's, and the builder's pin.
  function sweepable() {
    return INPUTS.filter((f) => (f.group === 'engine' && f.operations.includes('shot') && f.key !== 'psi_i_deg') || f.key === 'D' || f.key === 'pin_angle_deg');
  }
  // A value's name on the page: its symbol and its words ("L4: sling", "θi: start angle", "the pin angle").
  function sweepName(f) {
    if (f.key === 'pin_angle_deg') return 'the pin angle';
    return (f.key === 'theta_i_deg' ? 'θi: start angle' : f.key + ': ' + f.label.replace(/ \[deg\]$/, ''));
  }
  function fillSweepKeys() {
    const select = $('sweep-key');
    // The whipper's θi is its own start (asBuilt's), not a value to vary.
    select.innerHTML = sweepable().filter((f) => f.key === 'pin_angle_deg' || (state.edit && state.edit[f.key] > 0 && !(f.key === 'theta_i_deg' && state.machine === 'whipper')))
      .map((f) => `<option value="${f.key}">${escapeHtml(sweepName(f))}</option>`).join('');
    select.value = state.sweep_key;
    if (select.value !== state.sweep_key) { state.sweep_key = select.value; state.sweep_from = state.sweep_to = ''; }
  }
  // The sweep's range: as typed (with units), else the edited value halved to one and a half
  // times; θi 15° either side; the pin 20° either side of this shot's.
  function sweepRange(shot) {
    const key = state.sweep_key, value = key === 'pin_angle_deg' ? shot.pin_angle_at_release_deg : state.edit[key];
    const [lo, hi] = key === 'pin_angle_deg' ? [value - 20, value + 20] : key === 'theta_i_deg' ? [Math.max(1, value - 15), Math.min(89, value + 15)] : [value / 2, value * 1.5];
    return { value, from: state.sweep_from.trim() || String(lo), to: state.sweep_to.trim() || String(hi) };
  }
  function runSweep(shot) {
    const box = $('sweep-chart'), message = $('sweep-message');
    box.innerHTML = ''; message.textContent = ''; message.className = 'message';
    lastSweep = null;
    if (!state.edit) return null;
    if (!shot) { message.textContent = 'No shot of this engine to vary: see the message above the animation.'; return null; }
    const key = state.sweep_key, field = INPUTS.find((f) => f.key === key);
    if (!field) return null;
    const range = sweepRange(shot);
    $('sweep-from').placeholder = typedText(Number(range.from) || 0, field.dimension);
    $('sweep-to').placeholder = typedText(Number(range.to) || 0, field.dimension);
    // A swept pin angle is the release: a release given another way gives way to it.
    const design = asBuilt(state.edit);
    if (key === 'pin_angle_deg') for (const other of ['release_time', 'release_angle_deg']) delete design[other];
    const request = Object.assign({ design, vary: `${key}=${range.from}..${range.to}`, points: 21 }, settings());
    const answer = call('sweep', request);
    if (answer.error) { message.className = 'message refused'; message.textContent = answer.error; return answer; }
    lastSweep = { request, answer };
    const [size, unit] = field.dimension === 'angle' ? [1, '°'] : V.unitOf(field.dimension, state.units);
    const x = answer.values.map((v) => v / size);
    const over = (name, of) => answer.points.map((p) => (p.error ? null : of(p) / of(shot)));
    const lines = [
      { name: 'range R', colour: '#2ca02c', width: 2.5, x, y: over('R', (p) => p.R) },
      { name: 'efficiency ε', colour: '#1f77b4', x, y: over('eps', (p) => p.eps) },
      { name: 'quality Q', colour: 'black', x, y: over('Q', (p) => p.Q) },
      { name: 'peak axle load', colour: '#9467bd', dash: '5 3', x, y: over('pivot_force', (p) => p.pivot_force) },
    ];
    const breaking = answer.points.map((p, i) => (p.rupture_margin < 1 ? i : -1)).filter((i) => i >= 0);
    const labels = breaking.map((i) => ({ x: x[i], y: answer.points[i].R / shot.R, text: '✗', attributes: { fill: '#b00020', 'font-size': 15, 'text-anchor': 'middle', 'font-weight': 'bold' } }));
    const name = key === 'theta_i_deg' ? 'θi' : key === 'pin_angle_deg' ? 'the pin angle' : key;
    const figure = V.chart({ width: V.chartUnits(box.clientWidth || 420), height: 300, title: `What if ${name} changes? Each point a whole shot`,
      subtitle: 'each value over its value in this engine; ✗: the beam breaks', xLabel: `${sweepName(field)} [${unit}]`,
      yLabel: 'over this engine', xName: name, xUnit: unit, lines, labels, marks: [{ name: 'this engine', x: range.value / size }],
      empty: 'no point of this range makes a shot: see the message above' });
    figure.classList.add('sweep-chart');
    box.appendChild(figure);
    const failed = answer.points.filter((p) => p.error);
    const notes = [];
    if (breaking.length) notes.push(`The beam breaks at ${breaking.length} of the ${answer.points.length} points (✗), from ${name} = ${typedText(answer.values[breaking[0]], field.dimension)} to ${typedText(answer.values[breaking[breaking.length - 1]], field.dimension)}.`);
    if (failed.length) notes.push(`${failed.length} point(s) make no shot: ${failed[0].error}`);
    const [low, high] = [answer.values[0], answer.values[answer.values.length - 1]];
    if (!(range.value >= low && range.value <= high))
      notes.push(`This engine's ${name}, ${typedText(range.value, field.dimension)}, lies outside the range swept (${typedText(low, field.dimension)} to ${typedText(high, field.dimension)}); the curves are still over its values.`);
    if (notes.length) { message.className = breaking.length ? 'message refused' : 'message'; message.textContent = notes.join(' '); }
    return answer;
  }

  function compareWithOptimum(answer) {
    const box = $('compare');
    if (!answer) { box.innerHTML = ''; return; }
    // The paper's optimum for the edited engine's own capacity (vacuum, level 0), same θi and F.
    const request = { R: answer.R_vacuum, T: answer.T_vacuum, theta_i_deg: designed ? designed.theta_i_deg : Number(state.theta) };
    if (ownTable()) request.machine = state.machine; else request.F = designed ? designed.F : state.F;
    let optimum = call('design', request), note = '';
    if (optimum.kind === 'out_of_range') {  // beyond the table: its nearest segment, said so
      const extrapolated = call('design', Object.assign({ extrapolate: true }, request));
      if (!extrapolated.error) { note = ' (extrapolated: this capacity lies beyond tab:CPNC)'; optimum = extrapolated; }
    }
    if (optimum.error) { box.innerHTML = `<details class="message"><summary>No optimum in tab:CPNC for this capacity, to compare with.</summary>${escapeHtml(optimum.error)}</details>`; return; }
    const shot = call('shot', Object.assign({ design: ownTable() ? Object.assign(engineOf(optimum), { machine: state.machine }) : engineOf(optimum) }, settings()));
    const cell = (a, b, f) => `<td>${f(a)}</td><td>${shot.error ? '—' : f(b)}</td>`;
    box.innerHTML = `<table class="tv-figures compare"><caption>the edited engine beside ${ownTable() ? `the ${MACHINE_NAMES[state.machine]}'s own optimum` : "the paper's optimum (the hinged machine's)"} for the same capacity (R and T in vacuum, at the base's level)${note}</caption>
      <tr><th></th><th>edited</th><th>optimal</th></tr>
      <tr><th>quality Q</th>${cell(answer.Q, shot.Q, (v) => V.significant(100 * v, 4) + ' %')}</tr>
      <tr><th>efficiency ε</th>${cell(answer.eps, shot.eps, (v) => V.significant(100 * v, 4) + ' %')}</tr>
      <tr><th>force factor</th>${cell(answer.force_factor, shot.force_factor, (v) => V.significant(v, 4))}</tr>
      <tr><th>range R</th>${cell(answer.R, shot.R, (v) => q(v, 'length'))}</tr>
      <tr><th>M</th><td>${q(answer.engine.M, 'mass')}</td><td>${q(optimum.M, 'mass')}</td></tr>
      <tr><th>L1, L4</th><td>${q(answer.engine.L1, 'length')}, ${q(answer.engine.L4, 'length')}</td><td>${q(optimum.L1, 'length')}, ${q(optimum.L4, 'length')}</td></tr>
      <tr><th>mb (beam)</th><td>${q(answer.engine.mb, 'mass')}</td><td>${q(optimum.mb, 'mass')}</td></tr></table>
      <p class="help">The optimum's beam is as heavy as a beam must be to bear its load (eq:bend_L2, eq:BeamMass); a lighter beam edited in may beat it on Q, and break.${note ? ' Beyond the table the optimum is extrapolated and may not be one: compare with care.' : ''}</p>`;
  }

  // ---- reconstruct ----------------------------------------------------------------------------
  function buildAttested() {
    $('attested').innerHTML = ATTESTED.map(([key, name]) => `<label class="row"><span>${key === 'theta_i_deg' ? 'start angle [deg]' : name} <span class="name">${key === 'theta_i_deg' ? 'θi' : key}</span></span> <input data-key="${key}" value="${escapeHtml(state.attested[key] || '')}" autocomplete="off"></label>`).join('');
    $('attested').querySelectorAll('input').forEach((input) => input.addEventListener('input', () => {
      if (input.value.trim()) state.attested[input.dataset.key] = input.value.trim(); else delete state.attested[input.dataset.key];
      saveState();
    }));
  }
  const uncertain = (text) => /\.\.|±|\+-/.test(text);
  function runComplete() {
    const answer = call('complete', Object.assign({ attested: Object.assign({}, state.attested) }, settings()));
    const message = $('reconstruct-message');
    if (answer.error) {
      message.className = 'message refused'; message.textContent = answer.error; $('reconstruct-result').innerHTML = '';
      refuseShot('No engine to shoot: the attested values are refused (the message under them says why).');
      return null;
    }
    message.className = 'message';
    message.textContent = Object.values(state.attested).some(uncertain) ? 'A range is completed at its middle, a spread at its mean; "Monte Carlo band" samples them.' : '';
    const longest = answer.longest_range;
    $('reconstruct-result').innerHTML = `<table class="tv-figures"><caption>the completed engine (${answer.simulations} shots)</caption>
      <tr><th>attested</th><td>${answer.attested.join(', ')}</td></tr><tr><th>implied</th><td>${answer.implied.join(', ') || '—'}</td></tr>
      <tr><th>chosen</th><td>${answer.chosen.join(', ')}</td></tr>
      <tr><th>engine</th><td>L1 ${q(answer.L1, 'length')}, L2 ${q(answer.L2, 'length')}, L3 ${q(answer.L3, 'length')}, L4 ${q(answer.L4, 'length')}, H ${q(answer.H, 'length')}, M ${q(answer.M, 'mass')}, m ${q(answer.m, 'mass')}, mb ${q(answer.mb, 'mass')}</td></tr>
      <tr><th>shot</th><td>R ${q(answer.R, 'length')}, T ${q(answer.T, 'energy')}, Q ${V.significant(100 * answer.Q, 3)} %, ε ${V.significant(100 * answer.eps, 3)} %</td></tr>
      ${longest ? `<tr><th>longest range</th><td>${q(longest.R, 'length')} with L4 ${q(longest.L4, 'length')} (chosen: ${longest.chosen.join(', ')})</td></tr>` : ''}
      </table><div id="band"></div>`;
    if (lastBand && lastBand.key === JSON.stringify([state.attested, settings(), state.samples])) showBand(lastBand.answer);
    runShot(engineOf(answer), "The completed engine's shot");
    return answer;
  }

  // A Monte Carlo run spread over Web Workers, each with its own module; the parts are put
  // together in sample order, so the result is that of one run. Resolves to the report.
  function monteCarloParallel(request, onProgress) {
    // The module checks the request whole (samples, seed, the values) on no sample at all.
    if (request && typeof request === 'object' && ('first' in request || 'count' in request || 'outcomes' in request))
      return Promise.resolve(call('monteCarlo', request));
    const checked = call('monteCarlo', Object.assign({}, request, { first: 0, count: 0 }));
    if (checked.error) return Promise.resolve(checked);
    const samples = checked.samples;  // as the module reads the request, defaults and units included
    const workers = Math.max(1, Math.min(navigator.hardwareConcurrency || 2, 8, samples));
    const source = $('trebuchet-module').textContent + '\n' + workerMain.toString() + '\nworkerMain();';
    const url = URL.createObjectURL(new Blob([source], { type: 'text/javascript' }));
    const chunk = 25;
    const outcomes = new Array(samples);
    let next = 0, done = 0;
    return new Promise((resolve) => {
      let running = 0;
      const failure = (answer) => { resolve(answer); };
      for (let w = 0; w < workers; w++) {
        let worker;
        try {
          worker = new Worker(url);
        } catch (e) {  // a browser that starts no worker here: the run in this page, at once
          URL.revokeObjectURL(url);
          resolve(call('monteCarlo', request));
          return;
        }
        running++;
        const give = () => {
          if (next >= samples) { worker.terminate(); if (--running === 0) finish(); return; }
          const first = next, count = Math.min(chunk, samples - first);
          next += count;
          worker.postMessage(JSON.stringify(Object.assign({}, request, { first, count })));
          worker.onerror = (event) => {
            worker.terminate(); next = samples;
            failure(refused(`a Web Worker failed (${event.message || 'no message'}); run monteCarlo in the page instead`, 'numerical'));
            if (--running === 0) finish();
          };
          worker.onmessage = (event) => {
            const answer = JSON.parse(event.data);
            if (answer.error) { worker.terminate(); next = samples; failure(answer); if (--running === 0) finish(); return; }
            answer.outcomes.forEach((o, k) => { outcomes[first + k] = o; });
            done += count;
            if (onProgress) onProgress(done, samples);
            give();
          };
        };
        give();
      }
      function finish() {
        URL.revokeObjectURL(url);
        if (done < samples) return;  // a failure has settled the run
        resolve(call('monteCarlo', Object.assign({}, request, { outcomes })));
      }
    });
  }
  // Runs inside each worker, after the module's own text.
  function workerMain() {
    const ready = createTrebuchet();
    self.onmessage = (event) => {
      ready.then((m) => m.monteCarlo(event.data)).then((answer) => self.postMessage(answer), (e) =>
        self.postMessage(JSON.stringify({ error: `internal error in a worker's module (${e && e.message}); reload the page`, kind: 'numerical', names: [] })));
    };
  }
  let lastBand = null;  // the band of the attested values and settings it was run for
  function showBand(answer) {
    const box = $('band') || $('reconstruct-result');
    if (!answer.percentiles) return;
    const p = answer.percentiles;
    const failed = (answer.failures || []).reduce((n, f) => n + f.count, 0);
    box.innerHTML = `<table class="tv-figures"><caption>Monte Carlo band: ${answer.samples} completions, ${failed} failed</caption>
      <tr><th></th><th>5 %</th><th>50 %</th><th>95 %</th></tr>
      <tr><th>R</th><td>${q(p.R.p5, 'length')}</td><td>${q(p.R.p50, 'length')}</td><td>${q(p.R.p95, 'length')}</td></tr>
      <tr><th>T</th><td>${q(p.T.p5, 'energy')}</td><td>${q(p.T.p50, 'energy')}</td><td>${q(p.T.p95, 'energy')}</td></tr></table>
      ${answer.draws_csv ? `<p class="downloads">Download: <a id="download-draws" download="monte-carlo-samples.csv" href="data:text/csv;charset=utf-8,${encodeURIComponent(answer.draws_csv)}">every sample (CSV): its drawn inputs, R, T, ε, v, or why it failed</a></p>` : ''}`;
  }
  async function runBand() {
    if (!Object.values(state.attested).some(uncertain)) {
      $('reconstruct-message').className = 'message refused';
      $('reconstruct-message').textContent = 'Give at least one value as a range (2.5t..3.5t) or a spread (3.5m±0.2m): the band is what the uncertain values make of R and T.';
      return null;
    }
    const request = Object.assign({ attested: Object.assign({}, state.attested), samples: state.samples, seed: 1, draws_csv: true }, settings());
    const key = JSON.stringify([state.attested, settings(), state.samples]);
    const bar = $('progress'), count = $('progress-text');
    bar.hidden = false; bar.value = 0;
    $('monte-carlo').disabled = $('complete').disabled = true;
    const answer = await monteCarloParallel(request, (done, total) => { bar.value = done / total; count.textContent = `${done} of ${total} completions`; });
    bar.hidden = true; count.textContent = '';
    $('monte-carlo').disabled = $('complete').disabled = false;
    if (answer.error) { $('reconstruct-message').className = 'message refused'; $('reconstruct-message').textContent = answer.error; return answer; }
    lastBand = { key, answer };
    showBand(answer);
    ($('band') || $('reconstruct-result')).scrollIntoView({ block: 'nearest' });
    return answer;
  }

  // ---- the share link as a QR code (qrcode-generator, bundled) ---------------------------------
  // A link only this computer opens: a file, or a server on this computer's own name.
  const onlyHere = () => location.protocol === 'file:' || ['localhost', '127.0.0.1', '[::1]'].includes(location.hostname);
  function showQr() {
    saveState();
    const link = location.href;
    let svgText = null;
    // Error correction L (7 %): the fewest modules for the link, so that the code stays coarse
    // enough to scan off a projector's screen; a link too long for a QR code says so.
    for (const level of ['L']) {
      try {
        const code = qrcode(0, level);  // eslint-disable-line no-undef
        code.addData(link);
        code.make();
        svgText = code.createSvgTag({ cellSize: 4, margin: 4, scalable: true, alt: 'QR code of the link to this page' });
        break;
      } catch (e) { /* too long at this level */ }
    }
    $('qr-code').innerHTML = svgText || '<p class="message refused">This link is too long for a QR code; copy it instead.</p>';
    $('qr-file').hidden = !onlyHere();
    $('qr-text').textContent = link.length > 160 ? link.slice(0, 160) + '…' : link;
    $('qr-dialog').showModal();
    $('qr-dialog').scrollTop = 0;  // showModal focuses the Close button at the bottom; the dialog opens at its warning
  }

  // ---- the symbols, in plain words ------------------------------------------------------------
  function buildLegend() {
    const words = [
      ['θ, θi', 'the beam\'s angle from the downward vertical; θi where it starts'],
      ['ψ', 'the counterweight arm\'s angle from the vertical'],
      ['φ', 'the sling\'s angle from the horizontal'],
    ];
    for (const f of INPUTS.filter((g) => ['L1', 'L2', 'L3', 'L4', 'H', 'M', 'm', 'mb', 'D', 'Lb', 'F', 'beta2'].includes(g.key)))
      words.push([f.key === 'beta2' ? 'β2' : f.key, f.help]);
    words.push(
      ['R', 'the range: how far the projectile lands from the pivot, at the target\'s level'],
      ['T', 'the projectile\'s kinetic energy where it lands (eq:T)'],
      ['ΔU', 'the energy the counterweight and the beam give up in falling to their final rest (eq:DU)'],
      ['ε', 'the efficiency: the share of ΔU the projectile carries away (eq:Aux)'],
      ['𝓕', 'the force factor: how hard the engine pulls on its frame, as a multiple of the weights (eq:F)'],
      ['Q', 'the quality: range for the engine\'s size and counterweight, over the force factor, Q = ρ̃ μ ε / 𝓕 (eq:Q)'],
      ['ρ̃, μ', 'R over the long arm L1; the projectile\'s mass over the counterweight\'s, m/M'],
      ['v, A', 'the release speed, and the climb: the velocity\'s angle above the horizontal at the release'],
      ['pin angle', 'the angle between the long arm and the sling at the release: the pin a builder bends'],
      ['margin', 'the wood\'s modulus of rupture over the beam\'s largest stress: below 1 the beam breaks'],
    );
    $('legend').innerHTML = words.map(([symbol, text]) => `<dt>${escapeHtml(symbol)}</dt><dd>${escapeHtml(text)}</dd>`).join('');
  }

  // ---- the whole page -------------------------------------------------------------------------
  // A slider in the hand: each move draws the shot at once, and the comparison with the optimum
  // and the what-if (a design and 22 shots) follow once the hand rests or lets go, greyed until
  // then (issue 67: the page follows the hand). Anything that reads them (whatIf()) has them now.
  let following = null;
  function follow(answer) {
    clearTimeout(following && following.timer);
    following = { answer, timer: setTimeout(flushFollow, 150) };
    $('compare').classList.add('stale');
    $('sweep-chart').classList.add('stale');
  }
  // Nothing waits any more: the timer stopped, the comparison and the what-if no longer greyed.
  function settle() {
    if (following) clearTimeout(following.timer);
    following = null;
    $('compare').classList.remove('stale');
    $('sweep-chart').classList.remove('stale');
  }
  function flushFollow() {
    if (!following) return;
    const { answer } = following;
    settle();
    saveState();  // the link, written once the hand rests (it lays the address bar out again)
    if (shown && shown.shot === answer) drawShot(answer, false);  // its charts
    compareWithOptimum(answer);
    runSweep(answer);
  }
  // The phone's edit view keeps the animation in view while the sliders are (style.css).
  if (window.IntersectionObserver)
    new window.IntersectionObserver(([entry]) => document.documentElement.classList.toggle('sliders-in-view', entry.isIntersecting)).observe($('sliders'));
  function update(how) {
    document.documentElement.dataset.view = state.view;  // the phone's edit view puts the animation first (style.css)
    showMachineNote();
    const sliding = Boolean(how && how.sliding);
    if (!sliding) {
      settle();  // a slide's comparison and what-if, still waiting, belong to the shot this replaces
      saveState();  // a slide's link follows at rest (flushFollow)
    }
    if (state.view === 'design') {
      if (runDesign()) runShot(engineOf(designed), "The optimal engine's shot");
      else refuseShot('No engine to shoot: the givens are refused (the message under them says why).');
    } else if (state.view === 'edit') {
      if (!state.edit && designed) state.edit = engineOf(designed);
      const answer = state.edit ? runShot(state.edit, "The edited engine's shot", sliding) : null;
      if (sliding) {
        follow(answer);
      } else {
        compareWithOptimum(answer);
        runSweep(answer);
      }
    } else if (state.view === 'reconstruct') {
      runComplete();
    }
  }
  // The engine a link's edit view opens on, made again from the link: the design of its givens,
  // the completion of its attested values, or the whipper that throws; the link's changes go over it.
  function baseFrom(from) {
    if (from === 'whipper') return Object.assign({}, WHIPPER);
    if (from === 'reconstruct') {
      const answer = call('complete', Object.assign({ attested: Object.assign({}, state.attested) }, settings()));
      return answer.error ? null : engineOf(answer);
    }
    return runDesign() ? engineOf(designed) : null;
  }
  function openEditBase() {
    const base = baseFrom(state.edit_from);
    editBase = base;
    editFrom = state.edit_from;
    if (base || linkEdit) state.edit = Object.assign({}, base || {}, linkEdit || state.edit || {});
    linkEdit = null;
  }
  function showView(view) {
    // Edit opens the engine shown in the view left (the optimal or the completed one), as it was shot.
    if (view === 'edit' && state.view !== 'edit' && shown) {
      editBase = Object.assign({}, shown.engine);
      editFrom = state.view;
      state.edit = Object.assign({}, shown.engine);
    }
    if (view === 'edit' && editFrom) state.edit_from = editFrom;
    state.view = view;
    if (view === 'edit' && !editBase) openEditBase();
    document.querySelectorAll('nav button').forEach((b) => b.setAttribute('aria-selected', String(b.dataset.view === view)));
    document.querySelectorAll('.view').forEach((v) => { v.hidden = v.dataset.view !== view; });
    if (view === 'edit') buildSliders();
    if (view === 'reconstruct') buildAttested();
    update();
  }
  function wire() {
    fillPairSelects();
    $('pair').addEventListener('change', () => {
      state.pair = $('pair').value;
      if (state.pair !== 'any') {
        const [a, b] = state.pair.split(',');
        state.first = [a, EXAMPLES[a]]; state.second = [b, EXAMPLES[b]];
      }
      state.edit = null; editBase = null;
      showPair(); update();
    });
    for (const [id, slot] of [['first', 'first'], ['second', 'second']]) {
      $(id).addEventListener('input', () => { state[slot][1] = $(id).value; state.edit = null; givenSlider(slot); update(); });
      $(id + '-drag').addEventListener('input', () => {
        const value = Number($(id + '-drag').dataset.centre) * Math.pow(4, Number($(id + '-drag').value));
        state[slot][1] = V.significant(value, 4) + $(id + '-drag').dataset.unit;
        state.edit = null;
        $(id).value = state[slot][1];
        update();
      });
      $(id + '-name').addEventListener('change', () => { state[slot][0] = $(id + '-name').value; state[slot][1] = EXAMPLES[state[slot][0]]; state.edit = null; showPair(); update(); });
    }
    // tab:CPNC's blocks: theta_i 30 deg with F 1 or 2/3, 40 deg with F 2/3 only.
    const blocks = () => {
      const forty = $('theta').value === '40';
      $('F').querySelector('option[value="1"]').disabled = forty;
      if (forty && $('F').value === '1') { $('F').value = '2/3'; state.F = '2/3'; }
    };
    const fields = [['theta', 'theta'], ['F', 'F'], ['cd', 'cd'], ['wind', 'wind'], ['release', 'release'], ['release-by', 'release_by'], ['release-value', 'release_value'], ['machine', 'machine'],
      ['target-level', 'target_level'], ['range-from', 'range_from'], ['samples', 'samples']];
    for (const [id, key] of fields) {
      $(id).value = state[key];
      $(id).addEventListener(id === 'samples' ? 'change' : 'input', () => {
        state[key] = $(id).value;
        if (key === 'theta') blocks();
        if (key === 'theta' || key === 'F') state.edit = null;
        if (key === 'machine' && state.view === 'edit') buildSliders();  // the whipper's θi is its own
        if (key === 'machine' && state.own_table && state.view === 'design') state.edit = null;
        update();
      });
    }
    blocks();
    $('air').checked = state.air;
    $('air').addEventListener('change', () => { state.air = $('air').checked; update(); });
    $('units').value = state.units;
    $('units').addEventListener('change', () => { state.units = $('units').value; if (state.view === 'edit') buildSliders(); update(); });
    $('pair').value = state.pair;
    showPair();
    document.querySelectorAll('nav button').forEach((b) => b.addEventListener('click', () => showView(b.dataset.view)));
    $('reset-edit').addEventListener('click', () => {
      state.edit = editBase ? Object.assign({}, editBase) : null;
      if (!editBase) runDesign();
      buildSliders(); update();
    });
    $('sweep-key').addEventListener('change', () => { state.sweep_key = $('sweep-key').value; state.sweep_from = state.sweep_to = ''; $('sweep-from').value = $('sweep-to').value = ''; update(); });
    for (const [id, key] of [['sweep-from', 'sweep_from'], ['sweep-to', 'sweep_to']]) {
      $(id).value = state[key];
      $(id).addEventListener('change', () => { state[key] = $(id).value; update(); });
    }
    // The projectile's material: a name the library knows, or a density typed.
    $('projectile').value = state.projectile;
    $('projectile-density').value = state.projectile_density;
    $('projectile-density-row').hidden = state.projectile !== 'density';
    $('projectile').addEventListener('change', () => { state.projectile = $('projectile').value; $('projectile-density-row').hidden = state.projectile !== 'density'; update(); });
    $('projectile-density').addEventListener('change', () => { state.projectile_density = $('projectile-density').value; update(); });
    // A projector: large type and high contrast.
    const projector = () => { document.documentElement.classList.toggle('projector', state.projector); $('projector').setAttribute('aria-pressed', String(state.projector)); };
    projector();
    $('projector').addEventListener('click', () => { state.projector = !state.projector; projector(); update(); });
    $('qr').addEventListener('click', showQr);
    let drawnWidth = window.innerWidth, resizing = null;
    window.addEventListener('resize', () => {
      clearTimeout(resizing);
      resizing = setTimeout(() => { if (window.innerWidth !== drawnWidth) { drawnWidth = window.innerWidth; update(); } }, 250);
    });
    $('own-table').addEventListener('change', () => {
      state.own_table = $('own-table').checked;
      if (state.view === 'design') state.edit = null;
      update();
    });
    $('whipper-example').addEventListener('click', () => {
      editBase = Object.assign({}, WHIPPER);
      editFrom = state.edit_from = 'whipper';
      state.edit = Object.assign({}, WHIPPER);
      state.view = 'edit';
      document.querySelectorAll('nav button').forEach((b) => b.setAttribute('aria-selected', String(b.dataset.view === 'edit')));
      document.querySelectorAll('.view').forEach((v) => { v.hidden = v.dataset.view !== 'edit'; });
      buildSliders();
      update();
    });
    $('complete').addEventListener('click', () => runComplete());
    $('monte-carlo').addEventListener('click', () => runBand());
    $('share').addEventListener('click', () => {
      saveState();
      const said = (text) => {  // a toast over the page: the header keeps its height
        const toast = $('toast');
        toast.textContent = text;
        toast.hidden = false;
        clearTimeout(toast.timer);
        toast.timer = setTimeout(() => { toast.hidden = true; }, 4000);
      };
      const local = onlyHere() ? ': it opens only on this computer (see the QR code)' : '';
      if (!navigator.clipboard) { said('Copy the address bar: it holds the link' + local); return; }
      navigator.clipboard.writeText(location.href).then(() => said('Link copied' + local), () => said('Copy the address bar: it holds the link' + local));
    });
  }

  // window.trebuchet: the library for scripts, in the programs' JSON schema (docs/web.md).
  const ready = createTrebuchet().then((m) => {
    module = m;
    readInputs();
    loadState();
    wire();
    buildLegend();
    showView(state.view);
    return api;
  });
  const api = {
    ready,
    design: (request) => call('design', request),
    shot: (request) => call('shot', request),
    sweep: (request) => call('sweep', request),
    value: (request) => call('value', request),
    complete: (request) => call('complete', request),
    monteCarlo: (request) => call('monteCarlo', request),
    fields: () => call('fields', {}),
    monteCarloParallel,
    state: () => { flushFollow(); return JSON.parse(JSON.stringify(state)); },
    current: () => (shown ? shown.shot : null),  // the shot the page shows, as shot() answered it
    viewer: () => viewer,
    whatIf: () => { flushFollow(); return lastSweep; },  // the what-if sweep drawn in the edit view: its request and answer
  };
  window.trebuchet = api;
})();
