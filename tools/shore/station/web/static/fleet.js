// SPDX-License-Identifier: Apache-2.0
// The fleet page: one row a glider, in the server's attention order.
'use strict';
(function () {
  const E = Console.el;

  function row(g) {
    const last = g.last_call_start_utc;
    const lastCell = E('td', {}, last ? E('span', {}, last.replace('T', ' ').replace('Z', ' UTC'), E('br'), Console.ago(last)) : 'never',
                       g.in_call ? E('div', {class: 'warn'}, 'in a call now') : null);
    let next = E('td', {class: 'muted'}, 'no forecast yet');
    if (g.next_call) {
      next = E('td', {}, g.next_call.utc.replace('T', ' ').replace('Z', ' UTC'), E('br'), Console.ago(g.next_call.utc, true),
               E('div', {class: 'muted'}, g.next_call.source === 'forecast' ? 'forecast (p90 ' + g.next_call.latest_utc.substr(11, 5) + ')'
                                                                           : 'from the call interval - no forecast yet'));
    }
    const health = g.health_state ? E('td', {class: g.health_state === 'ok' ? 'ok' : (g.health_state === 'alert' ? 'bad' : 'muted')}, g.health_state)
                                  : E('td', {class: 'muted'}, 'no health report yet');
    const open = (g.alerts || []).filter(a => a.active && !a.acked_utc);
    const alerts = E('td', {}, open.length ? E('span', {class: 'bad'}, String(open.length)) : '0',
                     ...open.slice(0, 3).map(a => E('div', {class: 'muted'}, a.message)));
    const ab = g.abort || {};
    const aborts = E('td', {class: ab.aborted ? 'bad' : ''}, ab.total_since_reset === null || ab.total_since_reset === undefined ? '-' : String(ab.total_since_reset),
                     ab.aborted ? E('div', {}, 'ABORTED ' + (ab.cause || '')) : null);
    return E('tr', {id: 'row-' + g.name, class: 'rank-' + g.attention.rank, 'data-rank': g.attention.rank},
             E('td', {}, E('a', {href: '/glider/' + g.name}, g.name)),
             E('td', {class: g.attention.rank <= 3 ? 'bad' : ''}, g.attention.why),
             lastCell, E('td', {}, Console.fix(g.fix)), E('td', {}, (g.reasons || []).join('; ')),
             next, health, alerts, aborts);
  }

  // Overlapping refreshes (event stream, polling): an older answer is dropped.
  let asked = 0, shown = 0;
  async function refresh() {
    const mine = ++asked;
    const fleet = await Console.json('/api/fleet');
    if (mine < shown) return;
    shown = mine;
    const body = document.querySelector('#fleet tbody');
    body.replaceChildren(...fleet.gliders.map(row));
    document.getElementById('empty').hidden = fleet.gliders.length > 0;
    document.body.setAttribute('data-version', fleet.version);
  }

  Console.start(refresh);
})();
