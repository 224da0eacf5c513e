// SPDX-License-Identifier: Apache-2.0
// The glider's map: Leaflet with no tile layer (offline: no tile server, no CDN),
// a plain latitude/longitude grid, the fixes, the dead-reckoned track, the
// waypoints and the forecast's next-surfacing ellipse.
'use strict';
const GliderMap = {
  map: null, layer: null, userMoved: false,

  // Leaflet puts a string tooltip in as HTML; names come from files and the glider: always as text.
  tip(text) { const span = document.createElement('span'); span.textContent = text; return span; },

  init() {
    if (!window.L) {
      document.getElementById('map').textContent = 'Leaflet is missing (Debian package libjs-leaflet): no map.';
      return;
    }
    GliderMap.map = L.map('map', {zoomSnap: 0.25, attributionControl: false});
    L.control.scale({imperial: false}).addTo(GliderMap.map);
    // The map follows what is drawn (a new fix, a new waypoint) until the pilot pans or zooms it.
    const container = document.getElementById('map');
    for (const e of ['mousedown', 'wheel', 'touchstart']) container.addEventListener(e, () => { GliderMap.userMoved = true; });
    GliderMap.map.on('mousemove', e => {
      document.getElementById('cursor').textContent = e.latlng.lat.toFixed(5) + ', ' + e.latlng.lng.toFixed(5);
    });
  },

  // The 95 % ellipse: semi-axes in metres, orientation of the major axis in degrees clockwise from north.
  ellipse(lat, lon, e) {
    const o = e.orientation_deg * Math.PI / 180, pts = [];
    const mLat = 111320, mLon = 111320 * Math.cos(lat * Math.PI / 180);
    for (let i = 0; i <= 72; i++) {
      const t = i * Math.PI / 36, a = e.semi_major_m * Math.cos(t), b = e.semi_minor_m * Math.sin(t);
      const north = a * Math.cos(o) - b * Math.sin(o), east = a * Math.sin(o) + b * Math.cos(o);
      pts.push([lat + north / mLat, lon + east / mLon]);
    }
    return pts;
  },

  grid(bounds) {
    const lines = [];
    const span = Math.max(bounds.getNorth() - bounds.getSouth(), bounds.getEast() - bounds.getWest(), 1e-4);
    const step = Math.pow(10, Math.floor(Math.log10(span / 2)));
    for (let x = Math.floor(bounds.getWest() / step) * step; x <= bounds.getEast() + step; x += step) {
      lines.push(L.polyline([[bounds.getSouth() - step, x], [bounds.getNorth() + step, x]], {color: '#bbc', weight: 1, interactive: false, className: 'grid'}));
    }
    for (let y = Math.floor(bounds.getSouth() / step) * step; y <= bounds.getNorth() + step; y += step) {
      lines.push(L.polyline([[y, bounds.getWest() - step], [y, bounds.getEast() + step]], {color: '#bbc', weight: 1, interactive: false, className: 'grid'}));
    }
    return lines;
  },

  draw(g) {
    if (!GliderMap.map) return;
    if (GliderMap.layer) GliderMap.layer.remove();
    const items = [], all = [];
    if (g.dr_track && g.dr_track.length > 1) {
      items.push(L.polyline(g.dr_track, {color: '#06c', weight: 2, className: 'dr-track'}));
      all.push(...g.dr_track);
    }
    for (const w of g.waypoints || []) {
      items.push(L.polyline(w.points, {color: '#080', weight: 2, dashArray: '6 6', className: 'waypoints'}).bindTooltip(GliderMap.tip(w.file + ' (' + w.source + ')')));
      w.points.forEach((p, i) => items.push(L.circleMarker(p, {radius: 5, color: '#080', className: 'waypoint'}).bindTooltip(GliderMap.tip(w.file + ' #' + i))));
      all.push(...w.points);
    }
    for (const f of g.fixes || []) {
      items.push(L.circleMarker([f[0], f[1]], {radius: 4, color: '#c00', fillOpacity: 0.8, className: 'fix'}).bindTooltip(GliderMap.tip('fix ' + f[2])));
      all.push([f[0], f[1]]);
    }
    const fc = g.forecast && g.forecast.next_surfacing;
    if (fc && isFinite(fc.lat_deg) && isFinite(fc.lon_deg)) {
      if (fc.ellipse && fc.ellipse.semi_major_m > 0) {
        const pts = GliderMap.ellipse(fc.lat_deg, fc.lon_deg, fc.ellipse);
        items.push(L.polygon(pts, {color: '#a0a', weight: 2, fillOpacity: 0.1, className: 'forecast-ellipse'})
          .bindTooltip(GliderMap.tip('forecast next surfacing, ' + Math.round(100 * (fc.ellipse.level || 0.95)) + ' %')));
        all.push(...pts);
      }
      items.push(L.circleMarker([fc.lat_deg, fc.lon_deg], {radius: 6, color: '#a0a', className: 'forecast-point'}).bindTooltip(GliderMap.tip('forecast ' + (fc.time_utc || ''))));
      all.push([fc.lat_deg, fc.lon_deg]);
    }
    if (!all.length) { GliderMap.map.setView([0, 0], 2); return; }
    const bounds = L.latLngBounds(all);
    GliderMap.layer = L.layerGroup([...GliderMap.grid(bounds), ...items]).addTo(GliderMap.map);
    if (!GliderMap.userMoved) GliderMap.map.fitBounds(bounds.pad(0.15));
  },
};
