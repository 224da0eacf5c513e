// SPDX-License-Identifier: Apache-2.0
// The glider page: alerts, map, forecast, health, the queue and its actions,
// the surfacings, the last dialog and the actions journal.
'use strict';
(function () {
  const E = Console.el;
  const name = decodeURIComponent(location.pathname.split('/').pop());
  const utc = t => t ? t.replace('T', ' ').replace('Z', '') : '';
  let current = null;

  function result(body) {
    const box = document.getElementById('queue-result');
    const r = body.rehearsal;
    const lines = [];
    if (r) {
      lines.push(E('div', {class: r.verdict === 'ok' ? 'ok' : (r.verdict === 'not rehearsed' ? 'note' : 'bad'), id: 'rehearsal-verdict'},
                   'rehearsal: ' + r.verdict + (r.message ? ' - ' + r.message : '') +
                   (isFinite(r.abort_risk) && !(r.message || '').includes('abort risk') ? ' (abort risk ' + Math.round(100 * r.abort_risk) + ' %)' : '')));
    }
    lines.push(E('div', {class: body.ok ? 'ok' : 'bad', id: 'action-result'},
                 body.ok ? (body.action ? body.action.result : 'done') : (body.error || (body.action && body.action.result) || 'refused')));
    box.replaceChildren(...lines);
    document.getElementById('force-label').hidden = body.status !== 409;
  }

  async function act(url, fields) {
    const form = new FormData();
    for (const [k, v] of Object.entries(fields)) form.append(k, v);
    const body = await Console.post(url, form);
    if (!url.endsWith('/ack') || !body.ok) result(body);  // an acknowledgement shows in its alert
    await refresh();
    return body;
  }

  function alertsSection(g) {
    const pilot = Console.session && Console.session.role === 'pilot';
    const items = (g.alerts || []).filter(a => a.active || !a.acked_utc).slice(0, 20).map(a => {
      const state = a.acked_utc ? 'acked' : (a.active ? 'open' : 'cleared');
      const ack = !a.acked_utc && pilot ? E('button', {class: 'ack', 'data-id': a.id,
        onclick: () => act('/api/alerts/ack', {id: a.id, glider: g.name})}, 'acknowledge') : null;
      return E('div', {class: 'alert ' + state, 'data-kind': a.kind},
               E('b', {}, a.kind.replace('_', ' ') + ': '), a.message, ' ', E('span', {class: 'muted'},
               '(' + state + (a.acked_by ? ' by ' + a.acked_by : '') + ', since ' + utc(a.first_utc) + ', notified ' + a.notifications +
               'x' + (a.escalated ? ', ESCALATED' : '') + ')'), a.check ? E('div', {class: 'muted'}, 'check: ' + a.check) : null, ack);
    });
    document.getElementById('alerts').replaceChildren(...(items.length ? [E('h2', {}, 'Alerts'), ...items] : []));
  }

  function forecastBox(g) {
    const f = g.forecast, box = document.getElementById('forecast');
    if (!f) { box.replaceChildren(E('h3', {}, 'Forecast'), E('p', {class: 'muted', id: 'no-forecast'}, 'no forecast yet')); return; }
    // The shore's forecast after a surfacing failed (no mission copy, no fix...): its file says why.
    if (!f.next_surfacing) {
      box.replaceChildren(E('h3', {}, 'Forecast'), E('p', {class: 'muted', id: 'no-forecast'}, 'no forecast: ' + (f.error ? f.error.replace(/^forecast: failed: /, '') : 'no surfacing in the runs')));
      return;
    }
    const n = f.next_surfacing || {};
    const causes = Object.entries(f.abort_causes || {}).map(([k, v]) => k + ' ' + Math.round(100 * v) + ' %').join(', ');
    box.replaceChildren(E('h3', {}, 'Forecast'),
      E('p', {id: 'forecast-next'}, 'next surfacing ', utc(n.time_utc), ' (', Console.ago(n.time_utc, true), ')', E('br'),
        'p10-p90 ', utc(n.time_p10_utc), ' - ', utc(n.time_p90_utc), E('br'),
        'at ', isFinite(n.lat_deg) ? n.lat_deg.toFixed(5) + ', ' + n.lon_deg.toFixed(5) : '?',
        n.ellipse ? ' +- ' + Math.round(n.ellipse.semi_major_m) + ' x ' + Math.round(n.ellipse.semi_minor_m) + ' m' : ''),
      E('p', {class: f.abort_risk >= 0.2 ? 'bad' : ''}, 'abort risk ' + Math.round(100 * (f.abort_risk || 0)) + ' %' + (causes ? ': ' + causes : '')),
      E('p', {class: 'muted'}, 'made ' + utc(f.made_utc) + ' from ' + (f.runs || '?') + ' runs, mission ' + (f.mission || '?')));
  }

  function healthBox(g) {
    const h = g.health, box = document.getElementById('health-box');
    if (!h) { box.replaceChildren(E('h3', {}, 'Health'), E('p', {class: 'muted', id: 'no-health'}, 'no health report yet')); return; }
    box.replaceChildren(E('h3', {}, 'Health'),
      E('p', {id: 'health-state', class: h.state === 'ok' ? 'ok' : (h.state === 'alert' ? 'bad' : 'muted')}, h.state + ' (updated ' + utc(h.updated_utc) + ')'),
      ...(h.alerts || []).map(a => E('div', {class: 'alert health-alert'}, a.message, a.check ? E('div', {class: 'muted'}, 'check: ' + a.check) : null)),
      E('ul', {}, ...(h.effects || []).map(e => E('li', {}, e.name + ' ' + num(e.value) + (e.unit ? ' ' + e.unit : '') +
        (e.ci95 ? ' [' + e.ci95.map(num).join(', ') + ']' : '') + (e.since_utc ? ' since ' + utc(e.since_utc) : '')))));
  }

  // Four significant digits: health writes full doubles; "?" where it gives no number (an interval it cannot give).
  function num(v) {
    return typeof v === 'number' && isFinite(v) ? String(Number(v.toPrecision(4))) : '?';
  }

  function queueSection(g) {
    const pilot = Console.session && Console.session.role === 'pilot';
    const files = (g.queued_files || []).map(f => E('li', {class: 'queued-file'}, f.name + ' (' + f.bytes + ' B) ',
      pilot ? E('button', {id: 'cancel-file-' + f.name, onclick: () => act('/api/gliders/' + name + '/cancel', {kind: 'file', name: f.name})}, 'cancel') : null));
    const commands = (g.queued_commands || []).map((c, i) => E('li', {class: 'queued-command'}, 'command: ' + c + ' ',
      pilot ? E('button', {id: 'cancel-command-' + i, onclick: () => act('/api/gliders/' + name + '/cancel', {kind: 'command', index: i, command: c})}, 'cancel') : null));
    document.getElementById('queued').replaceChildren(...(files.length + commands.length ? files.concat(commands) : [E('li', {class: 'muted'}, 'nothing queued')]));
    document.getElementById('sent').replaceChildren(...(g.sent_files || []).slice(-20).map(f => E('li', {class: 'sent-file'}, f.name + ' (' + f.bytes + ' B)')));
    document.getElementById('rehearsals').replaceChildren(...(g.rehearsals || []).filter(r => r).map(r =>
      E('li', {}, (r.file || '?') + ': ' + r.verdict + (r.message ? ' - ' + r.message : ''))));
    document.getElementById('actions-box').hidden = false;
    document.getElementById('queue-form').hidden = !pilot;
    document.getElementById('command-form').hidden = !pilot;
  }

  function surfacings(g) {
    const rows = (g.surfacings || []).slice().reverse().slice(0, 200).map(s => E('tr', {class: 'surfacing'},
      E('td', {}, utc(s.call_start_utc)), E('td', {}, (s.reasons || []).join('; ')),
      E('td', {}, Console.fix(s.gps)), E('td', {}, s.dr_error_m === null ? '-' : Math.round(s.dr_error_m) + ' m'),
      E('td', {}, (s.files_received || []).join(', ')), E('td', {}, E('pre', {}, (s.excerpt || []).join('\n'))),
      E('td', {}, s.end_reason + (s.prompt ? ' / ' + s.prompt : ''))));
    document.querySelector('#surfacings tbody').replaceChildren(...rows);
  }

  function actions(g) {
    document.querySelector('#actions tbody').replaceChildren(...(g.actions || []).slice().reverse().map(a => {
      const what = a.action + ' ' + (a.file || a.command || a.alert || '') +
        (a.rehearsal ? ' [rehearsal ' + a.rehearsal.verdict + (a.forced ? ', OVERRIDDEN' : '') + ']' : '');
      return E('tr', {class: 'action'}, E('td', {}, utc(a.utc)), E('td', {}, a.user), E('td', {}, what), E('td', {}, a.result || ''));
    }));
  }

  // Refreshes overlap (an action's own, the event stream's): an answer older
  // than the one on the page is dropped, or a cancelled item could come back
  // and stay until the next event.
  let asked = 0, shown = 0;
  async function refresh() {
    const mine = ++asked;
    const r = await fetch('/api/gliders/' + encodeURIComponent(name), {credentials: 'same-origin', cache: 'no-store'});
    if (r.status === 401) { location.href = '/login'; return; }
    if (!r.ok) { document.getElementById('attention').textContent = 'no glider ' + name + ' has called this shore'; return; }
    const g = await r.json();
    if (mine < shown) return;
    shown = mine;
    current = g;
    document.getElementById('name').textContent = g.name;
    document.title = g.name + ' - glider console';
    document.getElementById('last-call').replaceChildren(g.last_call_start_utc ? Console.ago(g.last_call_start_utc) : 'never',
                                                         g.in_call ? ' (in a call now)' : '');
    document.getElementById('attention').replaceChildren(E('p', {class: g.attention.rank <= 3 ? 'bad' : 'muted', id: 'attention-why'},
      'needs: ' + g.attention.why + (g.abort && g.abort.aborted ? ' - ' + (g.abort.cause || '') : '')));
    alertsSection(g); forecastBox(g); healthBox(g); GliderPlots.draw(g); queueSection(g); surfacings(g); actions(g);
    GliderMap.draw(g);
    document.getElementById('journal-name').textContent = g.transcript.journal || '';
    document.getElementById('transcript').textContent = g.transcript.text || 'no call yet';
    document.body.setAttribute('data-surfacings', (g.surfacings || []).length);
  }

  document.getElementById('queue-form').onsubmit = async (event) => {
    event.preventDefault();
    const input = document.getElementById('queue-file');
    if (!input.files.length) { result({ok: false, error: 'choose a .ma or .mi file'}); return; }
    const form = new FormData();
    form.append('file', input.files[0]);
    form.append('force', document.getElementById('force').checked ? '1' : '0');
    const body = await Console.post('/api/gliders/' + encodeURIComponent(name) + '/queue', form);
    result(body);
    if (body.ok) { input.value = ''; document.getElementById('force').checked = false; }
    await refresh();
  };
  document.getElementById('command-form').onsubmit = async (event) => {
    event.preventDefault();
    const command = document.getElementById('command');
    const body = await act('/api/gliders/' + encodeURIComponent(name) + '/command', {command: command.value});
    if (body.ok) command.value = '';
  };

  GliderMap.init();
  Console.start(refresh);
})();
