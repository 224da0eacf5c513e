// SPDX-License-Identifier: Apache-2.0
'use strict';
document.getElementById('login').onsubmit = async (event) => {
  event.preventDefault();
  const r = await fetch('/api/login', {method: 'POST', body: new FormData(event.target), credentials: 'same-origin'});
  if (r.ok) { location.href = '/'; return; }
  let message = 'HTTP ' + r.status;
  try { message = (await r.json()).error; } catch (e) { /* not JSON */ }
  document.getElementById('login-error').textContent = message;
};
