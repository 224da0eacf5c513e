// SPDX-License-Identifier: Apache-2.0
// Health effects over the deployment: health's own plot (health/plots/EFFECT.png,
// thresholds drawn by health) when there is one, else the effect's series drawn
// here as SVG: value, 95 % band, and the threshold either side of the first value.
'use strict';
const GliderPlots = {
  svg(effect) {
    const NS = 'http://www.w3.org/2000/svg', W = 420, H = 180, P = 36;
    const s = document.createElementNS(NS, 'svg');
    s.setAttribute('width', W); s.setAttribute('height', H); s.setAttribute('class', 'effect-plot');
    const series = (effect.series || []).filter(p => isFinite(p.value));
    const add = (tag, attrs, text) => {
      const e = document.createElementNS(NS, tag);
      for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
      if (text) e.textContent = text;
      s.appendChild(e); return e;
    };
    add('text', {x: P, y: 14, 'font-size': 12}, effect.name + (effect.unit ? ' (' + effect.unit + ')' : '') + ' = ' + effect.value);
    if (series.length < 1) { add('text', {x: P, y: H / 2, 'font-size': 12}, 'no series'); return s; }
    const t = series.map(p => Date.parse(p.t_utc));
    const base = series[0].value, size = effect.threshold && isFinite(effect.threshold.size) ? effect.threshold.size : null;
    let lo = Math.min(...series.map(p => isFinite(p.lo) ? p.lo : p.value)), hi = Math.max(...series.map(p => isFinite(p.hi) ? p.hi : p.value));
    if (size !== null) { lo = Math.min(lo, base - size); hi = Math.max(hi, base + size); }
    if (hi - lo < 1e-12) { hi += 1; lo -= 1; }
    const t0 = Math.min(...t), t1 = Math.max(...t) > t0 ? Math.max(...t) : t0 + 1;
    const X = v => P + (W - 2 * P) * (v - t0) / (t1 - t0), Y = v => H - P + (-(H - 2 * P) * (v - lo) / (hi - lo));
    add('rect', {x: P, y: P, width: W - 2 * P, height: H - 2 * P, fill: 'none', stroke: '#999'});
    const band = series.filter(p => isFinite(p.lo) && isFinite(p.hi));
    if (band.length > 1) {
      const up = band.map(p => X(Date.parse(p.t_utc)) + ',' + Y(p.hi)), down = band.slice().reverse().map(p => X(Date.parse(p.t_utc)) + ',' + Y(p.lo));
      add('polygon', {points: up.concat(down).join(' '), fill: '#9bd', 'fill-opacity': 0.4});
    }
    add('polyline', {points: series.map((p, i) => X(t[i]) + ',' + Y(p.value)).join(' '), fill: 'none', stroke: '#036', 'stroke-width': 2});
    if (size !== null) {
      for (const v of [base - size, base + size]) {
        add('line', {x1: P, x2: W - P, y1: Y(v), y2: Y(v), stroke: '#c00', 'stroke-dasharray': '5 4', class: 'threshold'});
      }
      add('text', {x: W - P - 150, y: P - 4, 'font-size': 10, fill: '#c00'}, 'threshold +-' + size);
    }
    add('text', {x: 2, y: Y(hi) + 4, 'font-size': 10}, hi.toPrecision(3));
    add('text', {x: 2, y: Y(lo), 'font-size': 10}, lo.toPrecision(3));
    return s;
  },

  draw(g) {
    const box = document.getElementById('plots');
    const effects = g.health && g.health.effects ? g.health.effects : [];
    if (!g.health) { box.replaceChildren(Console.el('p', {class: 'muted'}, 'no health report yet')); return; }
    box.replaceChildren(...effects.map(e => {
      const png = e.name + '.png';
      if ((g.plots || []).includes(png)) {
        return Console.el('img', {src: '/api/gliders/' + g.name + '/plots/' + png, alt: e.name, width: 420, class: 'effect-png'});
      }
      return GliderPlots.svg(e);
    }));
  },
};
