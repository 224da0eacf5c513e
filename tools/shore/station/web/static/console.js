// SPDX-License-Identifier: Apache-2.0
// What every page shares: the session (user, role, CSRF token), JSON and form
// requests, "time since" text that ticks every second, and live updates
// (server-sent events, polling every 5 s when a stream cannot be had).
'use strict';
const Console = {
  session: null,

  async start(onChange) {
    const r = await fetch('/api/session', {credentials: 'same-origin'});
    if (r.status === 401) { location.href = '/login'; return; }
    Console.session = await r.json();
    const who = document.getElementById('who');
    if (who) {
      who.textContent = Console.session.user + ' (' + Console.session.role + ')';
      if (Console.session.login_required) {
        const out = document.createElement('button');
        out.textContent = 'log out';
        out.onclick = async () => { const f = new FormData(); f.append('bye', '1'); await Console.post('/api/logout', f); location.href = '/login'; };
        who.appendChild(document.createTextNode(' ')); who.appendChild(out);
      }
    }
    await onChange();
    Console.live(onChange);
    setInterval(Console.tickAges, 1000);
  },

  live(onChange) {
    let polling = null;
    const line = document.getElementById('status-line');
    const poll = () => { if (!polling) polling = setInterval(onChange, 5000); if (line) line.textContent = 'live: polling every 5 s'; };
    if (!window.EventSource) { poll(); return; }
    const events = new EventSource('/api/events');
    events.addEventListener('change', () => onChange());
    events.onopen = () => { if (line) line.textContent = 'live: event stream'; };
    events.onerror = () => { poll(); };
  },

  async json(url) {
    const r = await fetch(url, {credentials: 'same-origin', cache: 'no-store'});
    if (r.status === 401) { location.href = '/login'; throw new Error('log in'); }
    return r.json();
  },

  async post(url, form) {
    const r = await fetch(url, {method: 'POST', body: form, credentials: 'same-origin',
                                headers: {'X-CSRF-Token': Console.session ? Console.session.csrf : ''}});
    let body = {};
    try { body = await r.json(); } catch (e) { body = {error: 'HTTP ' + r.status}; }
    body.status = r.status;
    return body;
  },

  el(tag, attrs, ...children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k === 'class') e.className = v; else if (k.startsWith('on')) e[k] = v; else e.setAttribute(k, v);
    }
    for (const c of children) {
      if (c === null || c === undefined) continue;
      e.appendChild(typeof c === 'string' || typeof c === 'number' ? document.createTextNode(String(c)) : c);
    }
    return e;
  },

  // <span class="ago" data-utc=...>: "4 min ago" / "in 12 min", refreshed every second.
  ago(utc, future) {
    const s = Console.el('span', {class: 'ago', 'data-utc': utc || ''});
    if (future) s.setAttribute('data-future', '1');
    Console.fillAge(s);
    return s;
  },

  fillAge(span) {
    const utc = span.getAttribute('data-utc');
    if (!utc) { span.textContent = 'never'; return; }
    const dt = (Date.now() - Date.parse(utc)) / 1000;
    const text = Console.duration(Math.abs(dt));
    span.textContent = dt >= 0 ? text + ' ago' : 'in ' + text;
    if (span.getAttribute('data-future') && dt > 0) span.classList.add('bad');
  },

  tickAges() { document.querySelectorAll('span.ago').forEach(Console.fillAge); },

  duration(s) {
    if (s < 90) return Math.round(s) + ' s';
    if (s < 5400) return Math.round(s / 60) + ' min';
    if (s < 172800) return (s / 3600).toFixed(1) + ' h';
    return (s / 86400).toFixed(1) + ' d';
  },

  fix(f) { return f ? f.lat_deg.toFixed(5) + ', ' + f.lon_deg.toFixed(5) : 'no fix'; },
};
