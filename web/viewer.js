// The shot viewer: one verified shot (trebuchet-verify's JSON with its "series") drawn as the
// figures, an animation and four charts with values under the pointer. The browser page (app.js)
// and the index.html of `trebuchet-verify shot --plot` both draw with it, so a report and the
// live page are one renderer. Plain SVG, no library: each chart downloads as the SVG it is.
(function (global) {
  'use strict';
  const SVGNS = 'http://www.w3.org/2000/svg';

  // ---- units ------------------------------------------------------------------------------
  // SI base values in, text out; imperial gives feet and pounds (the international foot and
  // avoirdupois pound, exact), forces in pounds-force.
  const FT = 0.3048, LB = 0.45359237, LBF = 4.4482216152605;
  const UNITS = {
    si: {
      length: [[1, 'm']], acceleration: [[1, 'm/s²']], mass: [[1000, 't', 1000], [1, 'kg', 0]], force: [[1e6, 'MN', 1e6], [1000, 'kN', 1000], [1, 'N', 0]],
      energy: [[1e6, 'MJ', 1e6], [1000, 'kJ', 1000], [1, 'J', 0]], speed: [[1, 'm/s']], moment: [[1000, 'kN·m', 1000], [1, 'N·m', 0]],
      stress: [[1e6, 'MPa', 0]],
    },
    imperial: {
      length: [[FT, 'ft', FT], [0.0254, 'in', 0]], acceleration: [[FT, 'ft/s²']], mass: [[LB, 'lb']], force: [[LBF, 'lbf']], energy: [[FT * LBF, 'ft·lbf']], speed: [[FT, 'ft/s']],
      moment: [[FT * LBF, 'lbf·ft']], stress: [[LBF / (0.0254 * 0.0254), 'psi']],
    },
  };
  function significant(x, digits) {
    if (!isFinite(x)) return '—';
    if (x === 0) return '0';
    const text = Number(x.toPrecision(digits));
    return Math.abs(text) >= 1e6 || Math.abs(text) < 1e-3 ? text.toExponential(digits - 1) : String(text);
  }
  // "4.133 m", "3.117 t", "74.75 kN"; `dimension` a key of UNITS.si; others print bare.
  function quantity(value, dimension, system, digits) {
    const table = (UNITS[system] || UNITS.si)[dimension];
    if (!table) return significant(value, digits || 4);
    const [size, name] = table.find(([, , from]) => Math.abs(value) >= (from === undefined ? 0 : from)) || table[table.length - 1];
    return significant(value / size, digits || 4) + ' ' + name;
  }
  function unitOf(dimension, system) { return ((UNITS[system] || UNITS.si)[dimension] || [[1, '']])[0]; }

  // ---- SVG helpers --------------------------------------------------------------------------
  function svg(tag, attributes, parent) {
    const node = document.createElementNS(SVGNS, tag);
    for (const [k, v] of Object.entries(attributes || {})) node.setAttribute(k, v);
    if (parent) parent.appendChild(node);
    return node;
  }
  function text(parent, x, y, content, attributes) {
    const node = svg('text', Object.assign({ x, y, 'font-size': 12, 'font-family': 'sans-serif' }, attributes || {}), parent);
    node.textContent = content;
    return node;
  }
  function niceTicks(lo, hi, count) {
    const span = hi - lo || Math.abs(hi) || 1;
    const raw = span / count, power = Math.pow(10, Math.floor(Math.log10(raw)));
    const step = [1, 2, 2.5, 5, 10].map((f) => f * power).find((s) => s >= raw);
    const ticks = [];
    for (let t = Math.ceil(lo / step) * step; t <= hi + step * 1e-9; t += step) ticks.push(Math.abs(t) < step * 1e-9 ? 0 : t);
    return ticks;
  }

  // The width of a text of `size` units in a sans-serif face, a little generous (0.6 em a character).
  const textWidth = (content, size) => 0.6 * size * String(content).length;
  // `content` broken at spaces into lines no wider than `width` units.
  function wrap(content, size, width) {
    const lines = [];
    for (const word of String(content).split(' ')) {
      const last = lines.length ? lines[lines.length - 1] + ' ' + word : null;
      if (last !== null && textWidth(last, size) <= width) lines[lines.length - 1] = last; else lines.push(word);
    }
    return lines;
  }

  // A chart's width in its own units for a chart drawn `drawn` CSS px wide: its smallest words
  // (10 units) at least 10 px on a screen and 18 on a projector (html.projector).
  function chartUnits(drawn) {
    const projector = typeof document !== 'undefined' && document.documentElement.classList.contains('projector');
    return Math.floor(Math.min(760, Math.max(280, drawn * 10 / (projector ? 18 : 10))));
  }

  // A line chart: `lines` [{name, x, y, colour, dash}], `marks` [{x, name}], with a readout of
  // every line's value at the pointer. Returns the <svg>.
  function chart(spec) {
    const width = spec.width || 760, left = 64, right = 16;
    // The title and subtitle wrap to the chart's width; the key takes as many names a row as fit.
    const titleLines = spec.title ? wrap(spec.title, 13, width - 16) : [], subtitleLines = spec.subtitle ? wrap(spec.subtitle, 11, width - 16) : [];
    const keyWidth = Math.max(...spec.lines.map((line) => 34 + textWidth(line.name, 11)));
    const perRow = Math.max(1, Math.min(3, Math.floor((width - left - right) / keyWidth)));
    const keyRows = Math.ceil(spec.lines.length / perRow);
    const top = 10 + 16 * titleLines.length + 14 * subtitleLines.length + (spec.marks && spec.marks.length ? 24 : 0) + (titleLines.length ? 8 : 0);
    const bottom = 44 + 18 * keyRows;
    const height = Math.max((spec.height || 330) * (width < 600 ? 1.25 : 1), top + bottom + 180);
    const root = svg('svg', { xmlns: SVGNS, viewBox: `0 0 ${width} ${height}`, width: '100%', role: 'img', class: 'chart' });
    svg('rect', { x: 0, y: 0, width, height, fill: 'white' }, root);
    titleLines.forEach((line, k) => text(root, width / 2, 20 + 16 * k, line, { 'text-anchor': 'middle', 'font-weight': 'bold', 'font-size': 13 }));
    subtitleLines.forEach((line, k) => text(root, width / 2, 20 + 16 * titleLines.length + 14 * k, line, { 'text-anchor': 'middle', 'font-size': 11, fill: '#444' }));
    const xs = [], ys = [];
    for (const line of spec.lines)
      line.x.forEach((x, i) => { const y = line.y[i]; if (y !== null && isFinite(y) && isFinite(x)) { xs.push(x); ys.push(y); } });
    if (!xs.length) {  // every value refused or not finite: say so, draw no axes of NaN
      wrap(spec.empty || 'nothing to draw: no point has a value', 13, width - 24).forEach((line, k) =>
        text(root, width / 2, height / 2 + 17 * k, line, { 'text-anchor': 'middle', 'font-size': 13, fill: '#b00020' }));
      return root;
    }
    let [x0, x1] = spec.xRange || [Math.min(...xs), Math.max(...xs)];
    let [y0, y1] = spec.yRange || [Math.min(0, ...ys), Math.max(...ys)];
    if (spec.equalAspect) {
      const w = width - left - right, h = height - top - bottom, scale = Math.max((x1 - x0) / w, (y1 - y0) / h);
      const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
      [x0, x1, y0, y1] = [cx - scale * w / 2, cx + scale * w / 2, cy - scale * h / 2, cy + scale * h / 2];
    } else if (!spec.yRange) {
      const pad = 0.05 * (y1 - y0 || 1);
      y1 += pad; if (y0 < 0) y0 -= pad;
    }
    const X = (x) => left + (x - x0) / (x1 - x0) * (width - left - right);
    const Y = (y) => top + (1 - (y - y0) / (y1 - y0)) * (height - top - bottom);
    const plot = svg('g', {}, root);
    for (const t of niceTicks(x0, x1, 8)) {
      svg('line', { x1: X(t), x2: X(t), y1: top, y2: height - bottom, stroke: '#e4e4e4' }, plot);
      text(plot, X(t), height - bottom + 15, significant(t, 4), { 'text-anchor': 'middle', 'font-size': 11 });
    }
    for (const t of niceTicks(y0, y1, 6)) {
      svg('line', { x1: left, x2: width - right, y1: Y(t), y2: Y(t), stroke: '#e4e4e4' }, plot);
      text(plot, left - 6, Y(t) + 4, significant(t, 4), { 'text-anchor': 'end', 'font-size': 11 });
    }
    svg('rect', { x: left, y: top, width: width - left - right, height: height - top - bottom, fill: 'none', stroke: '#888' }, plot);
    text(root, (left + width - right) / 2, height - bottom + 32, spec.xLabel || '', { 'text-anchor': 'middle' });
    text(root, 14, (top + height - bottom) / 2, spec.yLabel || '', { 'text-anchor': 'middle', transform: `rotate(-90 14 ${(top + height - bottom) / 2})` });
    const clip = 'clip' + Math.random().toString(36).slice(2);
    const defs = svg('defs', {}, root);
    svg('rect', { x: left, y: top, width: width - left - right, height: height - top - bottom }, svg('clipPath', { id: clip }, defs));
    const curves = svg('g', { 'clip-path': `url(#${clip})` }, root);
    // Each mark's name in the first row where it clears the names there: two rows above the plot,
    // then two inside its top, on a white halo.
    const rows = [[], [], [], []];
    (spec.marks || []).filter((mark) => isFinite(mark.x) && mark.x >= x0 && mark.x <= x1).forEach((mark, k) => {
      svg('line', { x1: X(mark.x), x2: X(mark.x), y1: top, y2: height - bottom, stroke: '#999', 'stroke-dasharray': '3 3' }, root);
      const half = textWidth(mark.name, 10) / 2 + 2;
      const free = rows.findIndex((row) => row.every((other) => Math.abs(other.x - X(mark.x)) >= half + other.half));
      const row = free >= 0 ? free : k % 2;
      rows[row].push({ x: X(mark.x), half });
      text(root, X(mark.x), row < 2 ? top - 4 - row * 12 : top + 12 * (row - 1), mark.name,
        { 'text-anchor': 'middle', 'font-size': 10, fill: '#555', stroke: 'white', 'stroke-width': 3, 'paint-order': 'stroke' });
    });
    for (const line of spec.lines) {
      let d = '', pen = false;
      line.x.forEach((x, i) => {
        const y = line.y[i];
        if (y === null || !isFinite(y)) { pen = false; return; }
        d += (pen ? 'L' : 'M') + X(x).toFixed(2) + ' ' + Y(y).toFixed(2);
        pen = true;
      });
      svg('path', { d, fill: 'none', stroke: line.colour, 'stroke-width': line.width || 2, 'stroke-dasharray': line.dash || '' }, curves);
    }
    (spec.labels || []).forEach((label) => text(curves, X(label.x), Y(label.y), label.text, Object.assign({ 'font-size': 11 }, label.attributes || {})));
    // The key, below the plot.
    spec.lines.forEach((line, k) => {
      const kx = left + (k % perRow) * ((width - left - right) / perRow), ky = height - bottom + 50 + 18 * Math.floor(k / perRow);
      svg('line', { x1: kx, x2: kx + 22, y1: ky - 4, y2: ky - 4, stroke: line.colour, 'stroke-width': 2.5, 'stroke-dasharray': line.dash || '' }, root);
      text(root, kx + 28, ky, line.name, { 'font-size': 11 });
    });
    // Values under the pointer.
    const cursor = svg('line', { y1: top, y2: height - bottom, stroke: '#333', visibility: 'hidden' }, root);
    const readout = svg('g', { visibility: 'hidden', 'pointer-events': 'none' }, root);
    const box = svg('rect', { fill: 'rgba(255,255,255,0.93)', stroke: '#999', rx: 3 }, readout);
    const lines = spec.lines.map((line) => text(readout, 0, 0, '', { 'font-size': 11, fill: line.colour }));
    const xText = text(readout, 0, 0, '', { 'font-size': 11, 'font-weight': 'bold' });
    // On the paths (equal aspect) a curve goes back and forth in x: no value is "the" one under the pointer.
    if (!spec.equalAspect) root.addEventListener('pointermove', (event) => {
      const point = root.createSVGPoint ? (() => { const p = root.createSVGPoint(); p.x = event.clientX; p.y = event.clientY; return p.matrixTransform(root.getScreenCTM().inverse()); })() : { x: 0 };
      if (point.x < left || point.x > width - right) return;
      const x = x0 + (point.x - left) / (width - left - right) * (x1 - x0);
      cursor.setAttribute('x1', point.x); cursor.setAttribute('x2', point.x); cursor.setAttribute('visibility', 'visible');
      xText.textContent = (spec.xName || 'x') + ' = ' + significant(x, 4) + (spec.xUnit ? ' ' + spec.xUnit : '');
      const bx = point.x < width / 2 ? point.x + 10 : point.x - 230;
      xText.setAttribute('x', bx + 6); xText.setAttribute('y', top + 16);
      spec.lines.forEach((line, k) => {
        // The curve's sample nearest the pointer; none where the curve has ended (a null there),
        // or beyond its ends. A value below a millionth of the axis is 0 (rounding, not a force).
        let best = -1, distance = Infinity;
        line.x.forEach((lx, i) => { const dd = Math.abs(lx - x); if (dd < distance) { distance = dd; best = i; } });
        const inside = line.x.length > 1 && x >= Math.min(line.x[0], line.x[line.x.length - 1]) && x <= Math.max(line.x[0], line.x[line.x.length - 1]);
        const y = best >= 0 && inside ? line.y[best] : null;
        const shown = y === null || !isFinite(y) ? null : Math.abs(y) < 1e-6 * (y1 - y0) ? 0 : y;
        lines[k].textContent = shown === null ? '' : line.name + ': ' + significant(shown, 4) + (spec.yUnit ? ' ' + spec.yUnit : '');
        lines[k].setAttribute('x', bx + 6); lines[k].setAttribute('y', top + 32 + 15 * k);
      });
      box.setAttribute('x', bx); box.setAttribute('y', top + 4); box.setAttribute('width', 224); box.setAttribute('height', 20 + 15 * spec.lines.length);
      readout.setAttribute('visibility', 'visible');
    });
    root.addEventListener('pointerleave', () => { cursor.setAttribute('visibility', 'hidden'); readout.setAttribute('visibility', 'hidden'); });
    return root;
  }

  // ---- the engine at one moment -------------------------------------------------------------
  const COLOURS = { frame: '#8b5a2b', beam: '#a0522d', sling: '#1f5fbf', stone: '#d62728', weight: '#555', ground: '#6b8e23',
                    theta: '#b22222', psi: '#1f7a1f', phi: '#1f5fbf' };

  // Whether the segment a-b ([x, y] each) meets the box [left, top, right, bottom] (Liang and
  // Barsky's clipping: the part of the segment inside each of the box's four sides).
  function crosses(a, b, box) {
    let t0 = 0, t1 = 1;
    const dx = b[0] - a[0], dy = b[1] - a[1];
    for (const [p, q] of [[-dx, a[0] - box[0]], [dx, box[2] - a[0]], [-dy, a[1] - box[1]], [dy, box[3] - a[1]]]) {
      if (p === 0) { if (q < 0) return false; continue; }
      const t = q / p;
      if (p < 0) { if (t > t1) return false; t0 = Math.max(t0, t); } else { if (t < t0) return false; t1 = Math.min(t1, t); }
    }
    return true;
  }

  // Draws the engine of frame i into `g`, with view transform `to` ([x, y] in metres -> px).
  function drawEngine(g, shot, i, to, scale, options) {
    const f = shot.series.frames, H = shot.series.pivot_height, e = shot.engine;
    const P = (x, y) => to(x, y);
    // The engine's parts as drawn (lines 2 px wide or more, and the round bodies): the angles'
    // labels keep clear of them. Each a segment a-b and its half width; a body, a point and its radius.
    const parts = [];
    const line = (a, b, colour, w, dash) => {
      if (w >= 2) parts.push({ a, b, pad: w / 2 });
      const attributes = { x1: a[0], y1: a[1], x2: b[0], y2: b[1], stroke: colour, 'stroke-width': w, 'stroke-linecap': 'round', 'stroke-dasharray': dash || '' };
      return svg('line', w >= 2 ? Object.assign(attributes, { class: 'tv-part' }) : attributes, g);
    };
    const body = (c, r, colour) => {
      parts.push({ a: c, b: c, pad: r });
      return svg('circle', { cx: c[0], cy: c[1], r, fill: colour, class: 'tv-part' }, g);
    };
    const machine = e.machine || 'hinged';
    const pivot = P(f.pivot_x[i], H), hinge = P(f.hinge_x[i], f.hinge_y[i]), cw = P(f.counterweight_x[i], f.counterweight_y[i]), tip = P(f.tip_x[i], f.tip_y[i]);
    if (machine === 'floating-arm') {
      // The rail the axle rolls on, on two posts, and the guide the counterweight falls in.
      const back = -e.L2 - 0.15 * H, front = 0.15 * H;
      line(P(back, H), P(front, H), COLOURS.frame, 4);
      line(P(back, 0), P(back, H), COLOURS.frame, 4);
      line(P(front, 0), P(front, H), COLOURS.frame, 4);
      line(P(0, 0), P(0, H + e.L2), COLOURS.frame, 2, '3 4');
    } else {
      line(P(-0.3 * H, 0), pivot, COLOURS.frame, 4);
      line(P(0.3 * H, 0), pivot, COLOURS.frame, 4);
    }
    line(hinge, tip, COLOURS.beam, 6);
    if (machine === 'fixed') line(hinge, cw, COLOURS.beam, 6); else line(hinge, cw, '#222', 2);
    body(cw, Math.max(4, (0.12 * e.L2 + 0.04 * H) * scale), COLOURS.weight);
    body(pivot, 3.5, 'black');
    const released = f.phase[i] === 'III';
    if (!released) {
      const stone = P(f.projectile_x[i], f.projectile_y[i]);
      line(tip, stone, COLOURS.sling, 2);
      body(stone, Math.max(3.5, 0.03 * H * scale), COLOURS.stone);
    }
    if (options.angles) {
      // Each label goes beyond its arc's middle, or the nearest place to it (farther out, round
      // the arc, or a line up or down) that is inside the scene above the ground and clear of the
      // engine's parts, of the labels already placed and of the boxes the scene keeps clear (its
      // caption). Where it stood at the frame before, beside its vertex, it stays while that place
      // is clear and nearly as good (options.remember): a label that moves with its vertex, not
      // one that jumps between two places from frame to frame. Distances in the scene's units.
      const placed = (options.keepClear || []).slice();
      const inside = (x, y, w, h) => !options.bounds ||
        (y - h >= 0 && y + 4 <= Math.min(options.bounds.height, options.floor === undefined ? Infinity : options.floor) && x - w / 2 >= 0 && x + w / 2 <= options.bounds.width);  // 4: below the baseline
      const overLabel = (x, y, w, h) => placed.some((b) => x - w / 2 < b.x + b.w / 2 && b.x - b.w / 2 < x + w / 2 && y - h < b.y && b.y - b.h < y);
      const overPart = (x, y, w, h) => parts.some((part) => crosses(part.a, part.b, [x - w / 2 - part.pad, y - h - part.pad, x + w / 2 + part.pad, y + 4 + part.pad]));
      // Returns where the label goes, [x, y] (its middle, its baseline), about `centre` at `radius`, `mid` radians.
      const place = (centre, radius, mid, label) => {
        const w = textWidth(label, 12), h = 14;
        const at = (k, turn, lines) => [centre[0] + k * radius * Math.cos(mid + turn), centre[1] - k * radius * Math.sin(mid + turn) + 4 + lines * h];
        // Round the arc at 1.7 times its radius and farther out (turned by steps of 0.39 rad from
        // its middle), or a line up or down from there; the cheapest first: the distance from the
        // angle's vertex and half that from the arc's middle (a label a little farther out on its
        // arc's side before one as near on the other side).
        const ideal = at(1.7, 0, 0), candidates = [];
        for (const k of [1.7, 2.2, 2.8, 3.6, 4.6]) for (let turn = -8; turn <= 8; turn++) candidates.push(at(k, 0.39 * turn, 0));
        for (let lines = -6; lines <= 6; lines++) if (lines) candidates.push(at(1.7, 0, lines));
        const cost = (p) => Math.hypot(p[0] - centre[0], p[1] - 4 - centre[1]) + 0.5 * Math.hypot(p[0] - ideal[0], p[1] - ideal[1]);
        const kept = ([x0, y]) => [options.bounds ? Math.min(Math.max(x0, w / 2 + 2), options.bounds.width - w / 2 - 2) : x0, y];
        const ranked = candidates.sort((p, q) => cost(p) - cost(q)).map(kept);
        const clear = ([x, y]) => inside(x, y, w, h) && !overLabel(x, y, w, h) && !overPart(x, y, w, h);
        // Where it stood at the frame before stays while clear and within its arc's radius of the
        // cheapest clear place: it moves with its vertex, and comes back to its arc once it can.
        const memory = options.remember || {}, before = memory[label[0]], stay = before && kept([centre[0] + before[0], centre[1] + before[1]]);
        const best = ranked.find(clear);
        const spot = (stay && clear(stay) && (!best || cost(stay) <= cost(best) + radius) ? stay : best) ||
          ranked.find(([x, y]) => inside(x, y, w, h) && !overLabel(x, y, w, h)) || kept(ideal);
        memory[label[0]] = [spot[0] - centre[0], spot[1] - centre[1]];
        placed.push({ x: spot[0], y: spot[1], w, h });
        return spot;
      };
      const arc = (centre, radius, from, to, colour, label) => {
        // Site angles in degrees from +x, counterclockwise; the view flips y.
        const a0 = from * Math.PI / 180, a1 = to * Math.PI / 180;
        const p0 = [centre[0] + radius * Math.cos(a0), centre[1] - radius * Math.sin(a0)], p1 = [centre[0] + radius * Math.cos(a1), centre[1] - radius * Math.sin(a1)];
        const large = Math.abs(to - from) > 180 ? 1 : 0, sweep = to > from ? 0 : 1;
        svg('path', { d: `M${p0[0]} ${p0[1]} A${radius} ${radius} 0 ${large} ${sweep} ${p1[0]} ${p1[1]}`, fill: 'none', stroke: colour, 'stroke-width': 2 }, g);
        // The label beyond the arc's middle; for a small angle, beside its reference line.
        const mid = Math.abs(to - from) < 12 ? Math.min(a0, a1) - 0.35 : (a0 + a1) / 2;
        const [x, y] = place(centre, radius, mid, label);
        text(g, x, y, label, { fill: colour, 'text-anchor': 'middle', 'font-weight': 'bold', 'font-size': 12, stroke: 'white', 'stroke-width': 3, 'paint-order': 'stroke' });
      };
      const theta = f.theta_deg[i], psi = f.psi_deg[i], phi = f.phi_deg[i];
      const r = Math.max(14, 0.22 * Math.min(e.L1, H) * scale);
      line(pivot, [pivot[0], pivot[1] + 1.3 * r], COLOURS.theta, 1, '4 3');
      arc(pivot, r, 270 - theta, 270, COLOURS.theta, 'θ ' + significant(theta, 3) + '°');
      if (machine === 'hinged' || machine === 'whipper') {  // the others' counterweight has no angle of its own
        const rh = Math.max(12, 0.6 * e.L3 * scale);
        line(hinge, [hinge[0], hinge[1] + 0.8 * e.L3 * scale], COLOURS.psi, 1, '4 3');
        arc(hinge, rh, 270 - psi, 270, COLOURS.psi, 'ψ ' + significant(psi, 3) + '°');
      }
      if (!released && phi !== null) {
        const rt = Math.max(12, 0.35 * e.L4 * scale);
        line(tip, [tip[0] + 0.5 * e.L4 * scale, tip[1]], COLOURS.phi, 1, '4 3');
        arc(tip, rt, -phi, 0, COLOURS.phi, 'φ ' + significant(phi, 3) + '°');
      }
    }
  }

  // ---- the viewer ---------------------------------------------------------------------------
  function escapeHtml(s) { return String(s).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]); }

  // How the range changes with the pin bent a degree or two off this optimum's (none for a given release).
  // Reasons that differ only in their numbers (each pin's apex, say), once each: the first, and
  // how many pins it stands for.
  function alike(reasons) {
    const groups = new Map();
    for (const reason of reasons) {
      const key = reason.replace(/-?[0-9][0-9.e+-]*/g, '#');
      if (groups.has(key)) Object.assign(groups.get(key), { count: groups.get(key).count + 1, same: groups.get(key).same && groups.get(key).reason === reason });
      else groups.set(key, { reason, count: 1, same: true });
    }
    return [...groups.values()].map((g) => (g.count > 1 ? `${g.count} pins${g.same ? '' : ', the first'}: ` : '') + g.reason);
  }
  // A pin refused says why, once for all the pins refused for one reason.
  function pinTolerance(shot) {
    if (!shot.pin_tolerance) return '';
    const parts = shot.pin_tolerance.map((p) => {
      const off = p.pin_angle_deg - shot.pin_angle_at_release_deg;
      return (off > 0 ? '+' : '') + significant(off, 2) + '°: ' + (p.R_change === null ? 'refused' : (p.R_change > 0 ? '+' : '') + significant(p.R_change, 3) + ' m');
    });
    const reasons = alike(shot.pin_tolerance.filter((p) => p.R_change === null).map((p) => p.refused || 'a shot given this pin is refused'));
    return ' (R with the pin off by ' + parts.join(', ') + ')' + (reasons.length ? '; refused: ' + reasons.join('; ') : '');
  }

  // What the shot assumed, in words, from its "assumptions".
  function describeAssumptions(shot, system) {
    const a = shot.assumptions;
    const air = a.air === 'vacuum' ? 'in vacuum' : 'in air (Cd ' + (typeof a.air.drag_coefficient === 'number' ? a.air.drag_coefficient : 'of Re') +
      (a.air.wind ? ', wind ' + quantity(a.air.wind, 'speed', system) : '') + ')';
    const given = a.release_at && { time: 'at the time ', velocity_angle: 'at the velocity angle ', pin_angle: 'at the pin angle ' }[a.release_at.by];
    const release = given ? 'released ' + given + significant(a.release_at.value, 6) + (a.release_at.unit === 's' ? ' s' : '°') + ' (given)'
      : a.release === 'Q' ? (a.n === 1 ? 'released where Q peaks (eq:Q)' : 'released where Q_n peaks (eq:Q_n, n = ' + a.n + ')')
        : a.release === 'eps' ? 'released where ε peaks' : 'released where the range peaks';
    const target = a.range_from === 'release' ? "range from the release point back to its height (Denny's)" : 'target level ' + quantity(a.target_level, 'length', system);
    const machine = { fixed: 'built as a fixed counterweight (its centre L3 beyond the short arm), ',
      'floating-arm': "built as a floating arm (the counterweight L3 below its pin, in a guide; ranges from the guide's line), ",
      whipper: 'built as a whipper (started with the long arm forward and up, the counterweight and the projectile resting on it), ' }[shot.engine.machine] || '';
    return machine + air + ', ' + release + ', ' + target + ', g = ' + quantity(a.g, 'acceleration', system);
  }

  const FORCE_LINES = [
    ['FS_perp', 'F_S⊥ (sling, across the beam)', '#1f77b4', ''], ['sling_tension', 'sling tension', '#17becf', '6 3'],
    ['FR', '|F_R| (pivot)', '#d62728', ''], ['FRh', 'F_Rh (pivot, horizontal)', '#ff7f0e', ''], ['FH', '|F_H| (hinge)', '#2ca02c', ''],
    ['normal', 'N (trough on the projectile)', '#9467bd', ''],
  ];

  // The four charts of a shot, each an <svg>: forces, energy, release, paths.
  function charts(shot, system, width) {
    const s = shot.series, f = s.frames, m = s.moments, r = m.release;
    const tMarks = [['lift-off', m.liftoff], ['t_1', m.t1], ['t_m', m.tm], ['t_2', m.t2], ['release', r]].map(([name, i]) => ({ name, x: f.t[i] }));
    const upTo = (column) => f[column].map((v, i) => (i <= r ? v : null));
    const [forceSize, forceUnit] = system === 'si' ? [1000, 'kN'] : [LBF, 'lbf'];
    const forces = chart({ width,
      title: 'Forces up to the release', subtitle: 't_1, t_2: the extremes of F_Rh (eq:F); t_m: the largest pivot force',
      xLabel: 'time [s]', yLabel: `force [${forceUnit}]`, xName: 't', xUnit: 's', yUnit: forceUnit, xRange: [0, f.t[r] * 1.02],
      lines: FORCE_LINES.map(([key, name, colour, dash]) => ({ name, colour, dash, x: f.t, y: upTo(key).map((v, i) => (v === null || (key === 'normal' && f.phase[i] !== 'I') ? null : v / forceSize)) })),
      marks: tMarks,
    });
    const [energySize, energyUnit] = system === 'si' ? [1000, 'kJ'] : [FT * LBF, 'ft·lbf'];
    const rest = (k) => f[k][0];
    const taken = (f.E_projectile_kinetic[r] + f.E_projectile_potential[r]) - rest('E_projectile_potential');
    const projectile = f.t.map((t, i) => (f.phase[i] === 'III' ? taken : f.E_projectile_kinetic[i] + f.E_projectile_potential[i] - rest('E_projectile_potential')));
    const lost = f.W_lost && f.W_lost.some((v) => v !== 0);  // an engine as built: friction and drag take their share
    const energy = chart({ width,
      title: 'Where the energy goes',
      subtitle: shot.energy && shot.energy.flight_drag
        ? `At the release the projectile holds ε = ${significant(100 * shot.eps, 3)} % of ΔU; ${shot.energy.flight_drag > 0 ? 'in flight the air takes' : 'in flight the wind gives'} ${significant(Math.abs(shot.energy.flight_drag) / energySize, 3)} ${energyUnit} more`
        : `ΔU (eq:DU): what beam and counterweight give up, falling to rest. At the release the projectile holds ε = ${significant(100 * shot.eps, 3)} % of it`,
      xLabel: 'time [s]', yLabel: `energy gained since rest [${energyUnit}]`, xName: 't', xUnit: 's', yUnit: energyUnit,
      lines: [
        { name: 'counterweight', colour: '#555', x: f.t, y: f.E_counterweight.map((v) => (v - rest('E_counterweight')) / energySize) },
        { name: 'beam', colour: '#a0522d', x: f.t, y: f.E_beam.map((v) => (v - rest('E_beam')) / energySize) },
        { name: 'projectile', colour: '#d62728', x: f.t, y: projectile.map((v) => v / energySize) },
        { name: 'of which kinetic', colour: '#ff9896', dash: '5 3', x: f.t, y: f.E_projectile_kinetic.map((v, i) => (f.phase[i] === 'III' ? null : v / energySize)) },
        ...(lost ? [{ name: 'taken by friction and drag', colour: '#9467bd', x: f.t, y: f.W_lost.map((v) => v / energySize) }] : []),
        { name: lost ? 'total + losses (conserved)' : 'total (conserved)', colour: 'black', x: f.t,
          y: f.t.map((t, i) => (f.E_counterweight[i] - rest('E_counterweight') + f.E_beam[i] - rest('E_beam') + projectile[i] + (f.W_lost ? f.W_lost[i] : 0)) / energySize) },
        { name: lost ? 'left in beam + counterweight' : '(1 − ε) ΔU: left in beam + counterweight', colour: '#8c564b', dash: '8 3', width: 2.5, x: f.t,
          y: f.t.map((t, i) => (s.energy_drop + f.E_counterweight[i] - rest('E_counterweight') + f.E_beam[i] - rest('E_beam')) / energySize) },
        { name: 'ΔU (eq:DU)', colour: '#888', dash: '2 3', x: [f.t[0], f.t[f.t.length - 1]], y: [s.energy_drop / energySize, s.energy_drop / energySize] },
      ],
      marks: [{ name: 'release', x: f.t[r] }],
    });
    const p = s.phase_two;
    const objective = shot.assumptions.release === 'Q' ? 'Q' : shot.assumptions.release === 'eps' ? 'ε' : 'R';
    const release = chart({ width,
      title: `Phase II, on as if the projectile were kept: ${shot.assumptions.release_at ? 'this shot is released as given' : objective + ' peaks at the release'}`,
      subtitle: 'each over its value at the release; Q, ε and R here at level 0 in vacuum; dashed: the extremes of eq:F so far',
      xLabel: 'time [s]', yLabel: 'value over its value at the release', xName: 't', xUnit: 's', yRange: [0, 1.3],
      lines: [
        { name: 'Q', colour: 'black', width: 3, x: p.t, y: p.Q }, { name: 'ε', colour: '#1f77b4', x: p.t, y: p.eps }, { name: 'R', colour: '#2ca02c', x: p.t, y: p.R },
        { name: 'max F_S⊥ so far', colour: '#9467bd', dash: '5 3', x: p.t, y: p.FS_perp }, { name: 'max |F_R| so far', colour: '#d62728', dash: '5 3', x: p.t, y: p.FR },
        { name: 'max F_Rh so far', colour: '#ff7f0e', dash: '5 3', x: p.t, y: p.FRh_max }, { name: 'max −F_Rh so far', colour: '#8c564b', dash: '5 3', x: p.t, y: p.FRh_min },
      ],
      marks: [{ name: 'release', x: p.t[s.release_row] }],
    });
    const [lengthSize, lengthUnit] = unitOf('length', system);
    const L = (values) => values.map((v) => (v === null ? null : v / lengthSize));
    const fromX = shot.assumptions.range_from === 'release' ? shot.x : 0;
    const end = [s.flight.x[s.flight.x.length - 1], s.flight.y[s.flight.y.length - 1]];
    const paths = chart({ width,
      title: 'The paths, and the flight ' + (shot.assumptions.air === 'vacuum' ? 'in vacuum' : 'through air'),
      subtitle: `R = ${quantity(shot.R, 'length', system)}` + (fromX ? ' from the release point' : ' from the pivot') + '; x toward the target, height above the base',
      xLabel: `x toward the target [${lengthUnit}]`, yLabel: `height [${lengthUnit}]`, xName: 'x', xUnit: lengthUnit, yUnit: lengthUnit, equalAspect: true,
      lines: [
        { name: 'counterweight', colour: '#555', x: L(f.counterweight_x), y: L(f.counterweight_y) },
        { name: 'beam tip', colour: '#a0522d', x: L(f.tip_x), y: L(f.tip_y) },
        { name: 'projectile', colour: '#d62728', x: L(upTo('projectile_x')), y: L(upTo('projectile_y')) },
        { name: 'flight', colour: '#d62728', dash: '5 3', x: L(s.flight.x), y: L(s.flight.y) },
        { name: 'ground', colour: COLOURS.ground, x: [Math.min(...s.flight.x, -shot.engine.L1 - shot.engine.L4) / lengthSize, Math.max(...s.flight.x) / lengthSize], y: [0, 0] },
        { name: shot.assumptions.range_from === 'release' ? 'release height' : 'target level', colour: '#999', dash: '2 3', x: [fromX / lengthSize, end[0] / lengthSize], y: [end[1] / lengthSize, end[1] / lengthSize] },
      ],
    });
    // R and Q against the pin angle: the shot released at each pin 20 degrees either side of its own.
    // Pins without a release leave gaps, or an empty chart, with the reason.
    const pinScan = s.pins;
    const pinRefusals = pinScan ? alike((pinScan.refused || []).filter(Boolean)) : [];
    const pin = pinScan && pinScan.pin_angle_deg.length > 0 && chart({ width,
      title: 'The pin: R and Q of a release at each pin angle',
      subtitle: `this shot's pin angle, ${significant(shot.pin_angle_at_release_deg, 4)}°, marked; each over its value here` +
        (pinRefusals.length ? '; gaps: pins with no release' : ''),
      empty: 'No pin of this span gives a release: ' + (pinRefusals[0] || 'each shot given one is refused'),
      xLabel: 'pin angle between the long arm and the sling at the release [°]', yLabel: 'value over its value in this shot', xName: 'pin', xUnit: '°',
      lines: [
        { name: 'R', colour: '#2ca02c', width: 2.5, x: pinScan.pin_angle_deg, y: pinScan.R.map((v) => (v === null ? null : v / shot.R)) },
        { name: 'Q', colour: 'black', x: pinScan.pin_angle_deg, y: pinScan.Q.map((v) => (v === null ? null : v / shot.Q)) },
      ],
      marks: [{ name: 'this shot', x: shot.pin_angle_at_release_deg }],
    });
    return pin ? { forces, energy, release, paths, pin, pinRefusals } : { forces, energy, release, paths };
  }

  // The viewer into `container`: figures, warnings, the animation and the charts. `options`:
  // units ('si', 'imperial'), downloads (bool), time (where the animation stands, s), playing.
  function render(container, shot, options) {
    options = options || {};
    const system = options.units || 'si';
    const q = (v, dim, digits) => quantity(v, dim, system, digits);
    // options.keepCharts: the charts drawn before stay, greyed, for the caller to draw anew once
    // the hand rests (a slider's move draws the scene and the figures only).
    // They stay in the page, not taken out and put back: laid out and painted again, they would
    // cost a move more than the rest of its drawing.
    const keptCharts = options.keepCharts ? container.querySelector('.tv-charts') : null;
    for (const child of [...container.children]) if (child !== keptCharts) child.remove();
    const put = (node) => container.insertBefore(node, keptCharts);
    const e = shot.engine, s = shot.series;
    const head = document.createElement('div');
    head.className = 'tv-head';
    // The model's warnings, and after them the clearance's, when the counterweight strikes the ground (its record's `clearance`).
    const buildable = !shot.clearance || shot.clearance.buildable !== false;
    const modelWarnings = (shot.warnings || []).slice(0, buildable ? undefined : -1);
    const warnings = (modelWarnings.length
      ? `<div class="tv-warning" role="alert"><b>NOT PHYSICAL.</b> The model stops holding before the release; these are not the figures of a real engine:<ul>${modelWarnings.map((w) => '<li>' + escapeHtml(w) + '</li>').join('')}</ul></div>` : '') +
      (buildable ? '' : `<div class="tv-warning" role="alert"><b>NOT BUILDABLE.</b> ${escapeHtml(shot.warnings[shot.warnings.length - 1])}</div>`);
    const notes = (shot.notes || []).map((n) => `<p class="tv-note">${escapeHtml(n)}</p>`).join('');
    // The beam's strength, pass or break, where the shot knows the beam's diameter (given, or from mb).
    const margin = shot.rupture_margin, stress = Math.max(shot.stress_at_rest || 0, shot.stress_peak || 0);
    const strength = margin === undefined ? ''
      : margin < 1 ? `<div class="tv-strength tv-breaks" role="alert"><b>✗ THE BEAM BREAKS.</b> Its largest stress, ${q(stress, 'stress')}, is ${significant(1 / margin, 3)} times what its wood bears (the modulus of rupture): margin ${significant(margin, 3)}, below 1. Give it a larger diameter D (a box in the edit view), or a lighter counterweight M.</div>`
        : modelWarnings.length ? `<div class="tv-strength tv-unphysical">The beam would hold (margin ${significant(margin, 3)}), but this shot is not physical (above): its stresses are not a real engine's.</div>`
          : `<div class="tv-strength tv-holds"><b>✓ The beam holds:</b> margin ${significant(margin, 3)}. Its largest stress, ${q(stress, 'stress')}, is ${significant(100 / margin, 3)} % of what its wood bears (the modulus of rupture).</div>`;
    const loads = [['sling tension', shot.sling_tension, shot.t_sling_tension], ['hinge pin |F_H|', shot.hinge_force, shot.t_hinge_force],
      ['pivot |F_R|', shot.pivot_force, shot.t_pivot_force]].filter(([, v]) => v !== undefined);
    const row = (name, value, title) => `<tr${title ? ` title="${escapeHtml(title)}"` : ''}><th>${name}</th><td>${value}</td></tr>`;
    // An engine as built: what friction and the air took of ΔU by the release, each named.
    // The parts of an engine as built, as its JSON gives them (docs/verifier.md, "Real engines").
    const pin = (mu, r) => significant(mu, 3) + ' on r = ' + q(r, 'length');
    const built = [
      e.beam_cm !== undefined && ['beam as built', 'centre ' + q(e.beam_cm, 'length') + ' from the pivot, ' +
        (e.beam_gyration !== undefined ? 'radius of gyration ' + q(e.beam_gyration, 'length') : 'I = ' + significant(e.beam_inertia, 4) + ' kg·m²')],
      e.D_tip !== undefined && ['tapered beam', 'D ' + q(e.D_hinge, 'length') + ' at the hinge to ' + q(e.D_tip, 'length') + ' at the tip'],
      e.counterweight_inertia !== undefined && ['counterweight inertia', significant(e.counterweight_inertia, 4) + ' kg·m² about its centre'],
      e.axle_friction > 0 && ['axle friction μ', pin(e.axle_friction, e.axle_radius)],
      e.hinge_friction > 0 && ['hinge pin friction μ', pin(e.hinge_friction, e.hinge_radius)],
      e.trough_friction > 0 && ['trough friction μ', significant(e.trough_friction, 3)],
      e.rope_diameter > 0 && ['sling rope', q(e.rope_diameter, 'length') + ', Cd ' + significant(e.rope_cd, 3)],
      (e.rope_mass > 0 || e.pouch_mass > 0) && ['sling mass', q(e.rope_mass || 0, 'mass') + ' rope, ' + q(e.pouch_mass || 0, 'mass') + ' pouch'],
      e.pin_friction > 0 && ['release pin friction μ', significant(e.pin_friction, 3)],
    ].filter(Boolean);
    const builtRows = built.map(([name, value]) => row(name, value)).join('');
    const lossNames = { axle: 'axle friction', hinge: 'hinge friction', trough: 'trough friction', sling_drag: 'air on the projectile', rope_drag: 'air on the rope' };
    const losses = shot.energy ? Object.entries(shot.energy.losses).filter(([, v]) => v !== 0) : [];
    const lossRows = losses.map(([k, v]) => row(lossNames[k] || k, q(v, 'energy') + ' (' + significant(100 * v / shot.energy.delta_U, 3) + ' % of ΔU)',
      'work taken from the bodies up to the release (docs/verifier.md, "Real engines")')).join('');
    head.innerHTML = `<p class="tv-scene">This shot: <b>${escapeHtml(describeAssumptions(shot, system))}</b>.</p>${warnings}${strength}${notes}`;
    put(head);
    const tables = document.createElement('div');
    tables.className = 'tv-tables';
    tables.innerHTML = `<table class="tv-figures"><caption>the shot</caption>
      ${row('range R' + (shot.assumptions.air === 'vacuum' ? '' : ' (air)'), q(shot.R, 'length'), 'eq:R, to the target level')}
      ${row('energy at the end T', q(shot.T, 'energy'), 'eq:T')}
      ${row('efficiency ε', significant(100 * shot.eps, 4) + ' %', 'eq:Aux: T/ΔU at level 0')}
      ${row('quality Q', significant(100 * shot.Q, 4) + ' %' + (shot.assumptions.n !== 1 ? ' (Q_n, n = ' + shot.assumptions.n + ')' : ' = ρ̃ μ ε / 𝓕 = ' +
        significant(shot.Q * shot.force_factor / (e.m / e.M * shot.eps), 4) + ' × ' + significant(e.m / e.M, 3) + ' × ' + significant(shot.eps, 4) + ' / ' +
        significant(shot.force_factor, 4)), 'eq:Q: ρ̃ = R/L1 (the range at level 0 in vacuum over the long arm), μ = m/M, ε the efficiency, 𝓕 the force factor of eq:F')}
      ${shot.range_efficiency !== undefined ? row('range efficiency', significant(100 * shot.range_efficiency, 4) + ' % (' + significant(100 * shot.range_efficiency_counterweight, 3) + ' % of the counterweight\'s fall)',
        "Siano's: the range in vacuum over a black box's, all of ΔU thrown at 45° from the ground (docs/verifier.md, \"Range efficiency\")") : ''}
      ${row('force factor 𝓕', significant(shot.force_factor, 4), 'eq:F: the largest internal forces, as a multiple of the weights')}
      ${row('release speed v', q(shot.v, 'speed'))}
      ${row('release angle', significant(shot.A_deg, 4) + '°', 'the velocity angle of the projectile above the horizontal at the release')}
      ${row('pin angle', significant(shot.pin_angle_at_release_deg, 4) + '°' + pinTolerance(shot), 'the angle between the long arm and the sling at the release: the pin a builder bends to release there')}
      ${e.pin_friction > 0 ? row('pin to bend', significant(shot.pin_to_bend_deg, 4) + '° for its friction ' + significant(e.pin_friction, 3), 'the loop leaves a pin of friction μ atan μ later: bend it that much more') : ''}
      ${row('release at', significant(shot.t_release, 4) + ' s, ' + q(shot.h, 'length') + ' up, ' + q(Math.abs(shot.x), 'length') + (shot.x < 0 ? ' behind' : ' before') + (shot.engine.machine === 'floating-arm' ? " the guide's line" : ' the pivot'))}
      ${lossRows}
      </table><table class="tv-figures"><caption>the builder's loads (largest up to the release)</caption>
      ${loads.map(([name, v, t]) => row(name, q(v, 'force') + ' at ' + significant(t, 3) + ' s')).join('')}
      ${shot.beam_moment !== undefined ? row('beam moment at the pivot', q(shot.beam_moment, 'moment') + ' at ' + significant(shot.t_beam_moment, 3) + ' s') : ''}
      ${shot.stress_peak > 0 ? row('beam stress, peak', q(shot.stress_peak, 'stress') + (shot.rupture_margin < 1 ? ' (<b class="tv-bad">BREAKS</b>: margin ' + significant(shot.rupture_margin, 3) + ')'
        : ' (margin ' + significant(shot.rupture_margin, 3) + ': holds)'), 'the stress in the beam at the pivot; the margin is the modulus of rupture over the larger of the stress at rest and in the shot') : ''}
      </table><table class="tv-figures"><caption>the engine</caption>
      ${row('L1, L2 (beam)', q(e.L1, 'length') + ', ' + q(e.L2, 'length'))}${row('L3 (counterweight arm)', q(e.L3, 'length'))}
      ${row('L4 (sling)', q(e.L4, 'length'))}${row('H (pivot height)', q(e.H, 'length'))}
      ${row('M, m, mb', q(e.M, 'mass') + ', ' + q(e.m, 'mass') + ', ' + q(e.mb, 'mass'))}${row('θi', significant(e.theta_i_deg, 4) + '°')}
      ${builtRows}
      </table>`;

    // The animation: phases I and II to scale, then the whole flight; over it, the shot's answer
    // in the page's text size (a projector's class reads it beside the throw: issue 67).
    const stage = document.createElement('div');
    stage.className = 'tv-stage';
    const verdict = margin !== undefined && margin < 1 ? ' · <b class="tv-bad">the beam breaks</b>'
      : modelWarnings.length ? ' · <b class="tv-bad">not physical</b>' : margin === undefined ? '' : ' · the beam holds (margin ' + significant(margin, 3) + ')';
    const headline = document.createElement('p');
    headline.className = 'tv-headline';
    headline.innerHTML = `<b>R = ${q(shot.R, 'length')}</b> · ε = ${significant(100 * shot.eps, 3)} % · Q = ${significant(100 * shot.Q, 3)} %${verdict}`;
    stage.appendChild(headline);
    // The scene's units are chosen so that its smallest words (11 units) are drawn at least 11 CSS
    // px on a screen and 18 on a projector (html.projector), at the size it is drawn: the
    // container's width, or less where the stage's height (52 % of the window) bounds it.
    const projector = document.documentElement.classList.contains('projector');
    put(stage);  // to measure the width it is drawn at
    // The scene and the answer over it share the 52 % of the window's height the scene had alone.
    // Its shape is the room's, from 0.35 to 0.6 as high as wide, so that the engine is drawn as
    // large as the room allows: the full width of a projector's stage, taller on a phone.
    const room = 0.52 * (window.innerHeight || 760) - headline.offsetHeight, across = stage.clientWidth || 760;
    const aspect = Math.min(0.6, Math.max(0.35, room / across)), drawn = Math.min(across, room / aspect);
    const width = Math.floor(Math.min(760, Math.max(280, drawn * 11 / (projector ? 18 : 11)))), height = width * aspect, foot = 8;
    const scene = svg('svg', { xmlns: SVGNS, viewBox: `0 0 ${width} ${height}`, width: '100%', class: 'tv-scene-svg', role: 'img' });
    scene.style.maxHeight = Math.max(room, 140) + 'px';
    stage.appendChild(scene);
    const controls = document.createElement('div');
    controls.className = 'tv-controls';
    controls.innerHTML = `<button type="button" class="tv-play" aria-label="play">▶ play</button>
      <input type="range" class="tv-scrub" min="0" max="1000" value="0" aria-label="time: the first half the swing, the second the flight" title="first half: phases I and II; second half: the flight">
      <label>speed <select class="tv-speed"><option value="1">real</option><option value="0.25">¼</option><option value="0.1" selected>1/10</option><option value="0.04">1/25</option></select></label>
      <label><input type="checkbox" class="tv-angles" checked> angles</label><span class="tv-time"></span>`;
    stage.appendChild(controls);
    // The moment in words, under the scene: text of the page's size, which wraps on a phone.
    const phaseLine = document.createElement('p');
    phaseLine.className = 'tv-phase';
    phaseLine.setAttribute('aria-live', 'off');
    stage.insertBefore(phaseLine, controls);
    put(tables);
    const f = s.frames, r = s.moments.release, tRelease = f.t[r], tEnd = tRelease + s.flight.time;
    // The engine's view holds every point of phases I and II; the flight's view the whole path.
    const xs = [-0.3 * e.H, 0.3 * e.H], ys = [0, e.H];
    for (let i = 0; i < f.t.length; i++) {
      for (const k of ['hinge', 'counterweight', 'tip', 'projectile']) if (f[k + '_x'][i] !== null && (f.phase[i] !== 'III' || k !== 'projectile')) { xs.push(f[k + '_x'][i]); ys.push(f[k + '_y'][i]); }
    }
    const view = (x0, x1, y0, y1) => {
      const pad = 0.06 * Math.max(x1 - x0, y1 - y0), scale = Math.min(width / (x1 - x0 + 2 * pad), (height - foot) / (y1 - y0 + 2 * pad));
      const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
      return { scale, to: (x, y) => [width / 2 + (x - cx) * scale, (height - foot) / 2 - (y - cy) * scale] };
    };
    const near = view(Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys));
    const far = view(Math.min(...s.flight.x, ...xs), Math.max(...s.flight.x, ...xs), Math.min(0, ...s.flight.y), Math.max(...s.flight.y, ...ys));
    const stoneAt = (after) => {
      const k = Math.min(Math.max(after / s.flight.time, 0), 1) * (s.flight.x.length - 1), i = Math.min(Math.floor(k), s.flight.x.length - 2), w = k - i;
      return [s.flight.x[i] + w * (s.flight.x[i + 1] - s.flight.x[i]), s.flight.y[i] + w * (s.flight.y[i + 1] - s.flight.y[i])];
    };
    // One animation a container: a viewer drawn over another stops the other's clock.
    const token = {};
    container.trebuchetViewer = token;
    let time = Math.min(options.time || 0, tEnd), playing = false, last = null;
    const scrub = controls.querySelector('.tv-scrub'), timeText = controls.querySelector('.tv-time'), play = controls.querySelector('.tv-play');
    const speed = controls.querySelector('.tv-speed'), angles = controls.querySelector('.tv-angles');
    const labelSpots = {};  // where each angle's label stood beside its vertex at the frame drawn last
    function draw() {
      scene.innerHTML = '';
      svg('rect', { x: 0, y: 0, width, height, fill: '#f7fbff' }, scene);
      // The view widens to the whole flight once the stone leaves the engine's view.
      const stone = time > tRelease ? stoneAt(time - tRelease) : null;
      const seen = stone && near.to(stone[0], stone[1]);
      const flying = Boolean(seen) && (seen[0] < 0 || seen[0] > width || seen[1] < 0 || seen[1] > height - foot);
      const v = flying ? far : near;
      let i = 0;
      while (i + 1 < f.t.length && f.t[i + 1] <= time) i++;
      const g = svg('g', {}, scene);
      const ground = v.to(0, 0);
      svg('rect', { x: 0, y: ground[1], width, height: Math.max(0, height - ground[1]), fill: '#e8f0d8' }, g);
      svg('line', { x1: 0, x2: width, y1: ground[1], y2: ground[1], stroke: COLOURS.ground, 'stroke-width': 2 }, g);
      const level = shot.assumptions.range_from === 'release' ? null : shot.assumptions.target_level;
      if (flying && level) {  // the level the flight ends at, when it is not the ground
        const at = v.to(0, level);
        svg('line', { x1: 0, x2: width, y1: at[1], y2: at[1], stroke: '#888', 'stroke-dasharray': '6 4' }, g);
        text(g, width - 8, at[1] - 4, 'target level ' + quantity(level, 'length', options.units || 'si'), { 'text-anchor': 'end', fill: '#555', 'font-size': 11 });
      }
      if (time > tRelease) {
        const trail = [];
        for (let k = 0; k < s.flight.x.length; k++) trail.push(v.to(s.flight.x[k], s.flight.y[k]).map((n) => n.toFixed(1)).join(' '));
        svg('path', { d: 'M' + trail.join('L'), fill: 'none', stroke: '#bbb', 'stroke-dasharray': '4 4' }, g);
        const at = v.to(stone[0], stone[1]);
        svg('circle', { cx: at[0], cy: at[1], r: flying ? 4 : Math.max(3.5, 0.03 * e.H * v.scale), fill: COLOURS.stone }, g);
      }
      const banner = modelWarnings.length ? [{ x: width / 2, y: 48, w: 0.8 * 30 * 'NOT PHYSICAL'.length, h: 40 }] : [];  // bold capitals: 0.8 em each; the font's ascent and descent
      drawEngine(g, shot, i, v.to, v.scale, { angles: angles.checked && !flying, keepClear: banner, bounds: { width, height }, floor: ground[1], remember: labelSpots });
      const held = shot.t_counterweight_free;  // the whipper's: its counterweight leaves the arm first
      const first = held === undefined ? 'phase I: the projectile slides in the trough'
        : time <= held ? 'phase I: the counterweight and the projectile ride on the arm' : 'phase I: the counterweight swings, the projectile rides on the arm';
      const phase = time <= f.t[s.moments.liftoff] ? first : time <= tRelease ? 'phase II: the sling swings' : 'phase III: the flight';
      phaseLine.textContent = `t = ${time.toFixed(3)} s, ${phase}` + (flying ? ' (zoomed out to the whole flight, real speed)' : '');
      if (modelWarnings.length) text(scene, width / 2, 40, 'NOT PHYSICAL', { 'text-anchor': 'middle', 'font-size': 30, fill: '#cc0000', 'font-weight': 'bold' });
      timeText.textContent = `${time.toFixed(2)} s of ${tEnd.toFixed(2)} s`;
      scrub.value = String(Math.round(time <= tRelease ? 500 * time / tRelease : 500 + 500 * (time - tRelease) / (tEnd - tRelease)));
      container.dataset.frame = String(i);
      container.dataset.time = String(time);
    }
    function tick(now) {
      if (!playing || container.trebuchetViewer !== token) return;
      if (last !== null) {
        // Phases I and II at the chosen speed; the flight at real speed, so that it does not drag.
        const rate = time > tRelease ? 1 : Number(speed.value);
        time = Math.min(tEnd, time + (now - last) / 1000 * rate);
      }
      last = now;
      draw();
      if (time >= tEnd) { playing = false; play.textContent = '▶ play'; return; }
      requestAnimationFrame(tick);
    }
    play.addEventListener('click', () => {
      playing = !playing;
      play.textContent = playing ? '❚❚ pause' : '▶ play';
      if (playing) { if (time >= tEnd) time = 0; last = null; requestAnimationFrame(tick); }
    });
    // The bar's first half is phases I and II, its second the flight: the swing is not crowded
    // into the first tenth of a long flight.
    scrub.addEventListener('input', () => {
      const at = Number(scrub.value);
      time = at <= 500 ? at / 500 * tRelease : tRelease + (at - 500) / 500 * (tEnd - tRelease);
      draw();
    });
    angles.addEventListener('change', draw);
    draw();
    if (options.playing) play.click();  // a change while it played plays on

    const handle = { redraw: draw, setTime: (t) => { time = Math.max(0, Math.min(tEnd, t)); draw(); }, time: () => time, playing: () => playing, duration: tEnd };
    if (keptCharts) {
      keptCharts.classList.add('stale');
      return handle;
    }
    // Each chart's units are chosen as the scene's (chartUnits), at the width a chart's box has in
    // the grid (style.css, .tv-charts: one a row on a projector), measured on an empty box.
    const grid = document.createElement('div');
    grid.className = 'tv-charts';
    container.appendChild(grid);
    // Measured once for a width of the stage and a layout (a projector's is another): a slider
    // redraws at every move, and each measure lays the whole page out again.
    const layout = stage.clientWidth + (projector ? 'p' : '');
    if (!container.chartWidth || container.chartWidth.layout !== layout) {
      const probes = [0, 1, 2, 3, 4].map(() => grid.appendChild(Object.assign(document.createElement('figure'), { className: 'tv-chart' })));
      const padding = parseFloat(getComputedStyle(probes[0]).paddingLeft) + parseFloat(getComputedStyle(probes[0]).paddingRight);
      container.chartWidth = { layout, width: probes[0].clientWidth ? probes[0].clientWidth - padding : 420 };
      probes.forEach((probe) => grid.removeChild(probe));
    }
    const figureWidth = container.chartWidth.width;
    const figures = charts(shot, system, chartUnits(figureWidth));
    const captions = {
      forces: 'F_S⊥ is the sling\'s pull across the beam; |F_R| and F_Rh the pivot\'s force on the beam and its horizontal part; |F_H| the hinge\'s force; N the trough\'s push in phase I. Size ropes, pins and beams from these.',
      energy: 'Each body\'s energy gained since rest. The counterweight falls and gives up its energy; the beam takes a little, the projectile the most. ΔU is what beam and counterweight give up once they have fallen to their final rest; the dashed brown line is what they still hold above that rest, (1 − ε) ΔU at the release, while the projectile holds ε ΔU. The total is constant: with no friction nothing else takes a share; an engine given with friction or drag before the release shows what they took, and the total counts it.',
      release: 'Section 5: the release is where the chosen criterion peaks. An extreme\'s dashed line is flat while its force stays below the largest so far.',
      paths: 'The counterweight, the beam\'s tip and the projectile through phases I and II, then the flight.',
      pin: 'A builder bends the pin to release the sling at one angle between the long arm and the sling. Each point is the shot released at that pin: how far it throws (R) and its quality (Q), over this shot\'s.',
    };
    if (figures.pinRefusals && figures.pinRefusals.length) captions.pin += ' Where a pin has no point: ' + figures.pinRefusals.join('; ') + '.';
    delete figures.pinRefusals;
    for (const [name, figure] of Object.entries(figures)) {
      const box = document.createElement('figure');
      box.className = 'tv-chart tv-chart-' + name;
      box.appendChild(figure);
      const caption = document.createElement('figcaption');
      caption.textContent = captions[name];
      if (options.downloads !== false) {
        const link = document.createElement('a');
        link.textContent = ' Download SVG';
        link.download = name + '.svg';
        // Written when it is about to be followed, not at each drawing: a chart's text is long, and a
        // slider redraws every chart (issue 67: the page follows the hand).
        hrefOnDemand(link, () => 'data:image/svg+xml;charset=utf-8,' + encodeURIComponent(new XMLSerializer().serializeToString(figure)));
        caption.appendChild(link);
      }
      box.appendChild(caption);
      grid.appendChild(box);
    }
    container.appendChild(grid);
    return handle;
  }

  // A link whose address (a data: address, long to write) is written when it is about to be
  // followed: pressed, focused or clicked, before the browser follows it.
  function hrefOnDemand(link, address) {
    link.href = '#';
    for (const event of ['pointerdown', 'focus', 'click']) link.addEventListener(event, () => { link.href = address(); });
  }

  // The series as CSV: one row per frame, SI units.
  function seriesCsv(shot) {
    const f = shot.series.frames, columns = Object.keys(f);
    const unit = { t: 's', pivot_x: 'm', hinge_x: 'm', hinge_y: 'm', counterweight_x: 'm', counterweight_y: 'm', tip_x: 'm', tip_y: 'm', projectile_x: 'm', projectile_y: 'm',
      FS_perp: 'N', sling_tension: 'N', FR: 'N', FRh: 'N', FRv: 'N', FH: 'N', normal: 'N', beam_moment: 'N_m', E_counterweight: 'J', E_beam: 'J',
      E_projectile_kinetic: 'J', E_projectile_potential: 'J' };
    const lines = [columns.map((c) => (unit[c] ? c + '_' + unit[c] : c)).join(',')];
    for (let i = 0; i < f.t.length; i++) lines.push(columns.map((c) => (f[c][i] === null ? '' : f[c][i])).join(','));
    return lines.join('\n') + '\n';
  }

  global.TrebuchetViewer = { render, quantity, unitOf, significant, describeAssumptions, seriesCsv, chart, chartUnits, escapeHtml, hrefOnDemand };
})(typeof window !== 'undefined' ? window : globalThis);
