// Signals: a waveform canvas (bools as levels, integers as steps, enums as labelled bands,
// events as impulses) on a tick axis, and a sequence chart of the messages between instances.
'use strict';

const Wave = (() => {
  const LABEL_W = 170, AXIS_H = 22;
  const PALETTE = ['#dbe8ff', '#ffe9c7', '#dff5e1', '#f7dcf2', '#e6e1ff', '#d9f3f7', '#fde2e0', '#eeeeee'];

  function laneHeight(v) { return v.type === 'bool' || v.isEvent ? 22 : 34; }

  function draw(canvas, model, records, sel, cursor, lasso) {
    const dpr = window.devicePixelRatio || 1;
    const wrap = canvas.parentElement;
    const n = Math.max(records.length, 1);
    const avail = Math.max(200, wrap.clientWidth - LABEL_W - 16);
    const px = Math.max(3, Math.min(28, avail / n));
    const W = LABEL_W + Math.ceil(px * n) + 16;
    const H = AXIS_H + sel.reduce((h, v) => h + laneHeight(v), 0) + 4;
    canvas.width = W * dpr; canvas.height = H * dpr;
    canvas.style.width = W + 'px'; canvas.style.height = H + 'px';
    const g = canvas.getContext('2d');
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.clearRect(0, 0, W, H);
    g.font = '11px Helvetica, Arial, sans-serif';
    // Axis.
    g.fillStyle = '#6a7383'; g.strokeStyle = '#e3e6eb';
    const every = Math.max(1, Math.ceil(60 / px));
    const nice = [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000].find(k => k >= every) || every;
    for (let t = 0; t <= n; t += nice) {
      const x = LABEL_W + t * px;
      g.beginPath(); g.moveTo(x, AXIS_H - 4); g.lineTo(x, H); g.stroke();
      const ms = records[t] && records[t].time_text ? ` (${records[t].time_text} s)` : '';
      g.fillText(`${t}${ms}`, x + 2, 13);
    }
    let y = AXIS_H;
    for (const v of sel) {
      const h = laneHeight(v);
      g.fillStyle = '#2d3546';
      g.fillText(v.name, 6, y + h / 2 + 4, LABEL_W - 10);
      g.strokeStyle = '#eef0f3';
      g.beginPath(); g.moveTo(0, y + h); g.lineTo(W, y + h); g.stroke();
      const top = y + 4, bot = y + h - 4;
      if (v.isEvent) {
        g.strokeStyle = '#e0671b'; g.lineWidth = 2;
        records.forEach((r, t) => {
          if (r.events && r.events.includes(v.name)) {
            const x = LABEL_W + (t + 0.5) * px;
            g.beginPath(); g.moveTo(x, bot); g.lineTo(x, top); g.stroke();
            g.beginPath(); g.arc(x, top + 2, 2.5, 0, 7); g.fill();
          }
        });
        g.lineWidth = 1;
      } else if (v.type === 'bool') {
        g.strokeStyle = '#2f6fdf'; g.lineWidth = 1.6; g.beginPath();
        records.forEach((r, t) => {
          if (!r.vars) return;
          const yy = r.vars[v.name] ? top : bot;
          const x0 = LABEL_W + t * px;
          if (t === 0) g.moveTo(x0, yy); else g.lineTo(x0, yy);
          g.lineTo(x0 + px, yy);
        });
        g.stroke(); g.lineWidth = 1;
        g.fillStyle = 'rgba(47,111,223,0.10)';
        records.forEach((r, t) => { if (r.vars && r.vars[v.name]) g.fillRect(LABEL_W + t * px, top, px, bot - top); });
      } else if (v.type === 'enum') {
        let start = 0;
        const val = t => records[t] && records[t].vars ? records[t].vars[v.name] : undefined;
        for (let t = 1; t <= records.length; t++) {
          if (t === records.length || val(t) !== val(start)) {
            const x0 = LABEL_W + start * px, x1 = LABEL_W + t * px;
            const k = v.variants.indexOf(val(start));
            g.fillStyle = PALETTE[(k < 0 ? 7 : k) % PALETTE.length];
            g.fillRect(x0, top, x1 - x0, bot - top);
            g.strokeStyle = '#8a93a3'; g.strokeRect(x0 + 0.5, top + 0.5, x1 - x0 - 1, bot - top - 1);
            g.fillStyle = '#1d2430';
            if (x1 - x0 > 18) g.fillText(String(val(start) ?? ''), x0 + 3, top + (bot - top) / 2 + 4, x1 - x0 - 5);
            start = t;
          }
        }
      } else {
        const lo = v.lo, hi = v.hi;
        const vals = records.map(r => r.vars ? r.vars[v.name] : null).filter(x => x !== null && x !== undefined);
        const mn = vals.length ? Math.min(...vals) : lo, mx = vals.length ? Math.max(...vals) : hi;
        const span = mx - mn || 1;
        const Y = x => bot - ((x - mn) / span) * (bot - top);
        g.strokeStyle = '#1e8a5a'; g.lineWidth = 1.6; g.beginPath();
        let started = false;
        records.forEach((r, t) => {
          if (!r.vars) return;
          const yy = Y(r.vars[v.name]);
          const x0 = LABEL_W + t * px;
          if (!started) { g.moveTo(x0, yy); started = true; } else g.lineTo(x0, yy);
          g.lineTo(x0 + px, yy);
        });
        g.stroke(); g.lineWidth = 1;
        g.fillStyle = '#8a93a3'; g.font = '9px Helvetica, Arial';
        g.fillText(String(mx), LABEL_W - 36, top + 7); g.fillText(String(mn), LABEL_W - 36, bot);
        g.font = '11px Helvetica, Arial, sans-serif';
      }
      y += h;
    }
    // A lasso: its loop shaded, each further lap too, the loop's start marked on the axis.
    if (lasso && lasso.end > lasso.start) {
      const period = lasso.end - lasso.start;
      for (let a = lasso.start, lap = 0; a < n; a += period, lap++) {
        g.fillStyle = lap % 2 ? 'rgba(142,68,173,0.05)' : 'rgba(142,68,173,0.10)';
        g.fillRect(LABEL_W + a * px, AXIS_H - 4, Math.min(period, n - a) * px, H - AXIS_H + 4);
      }
      const x = LABEL_W + lasso.start * px;
      g.strokeStyle = '#8e44ad'; g.lineWidth = 1.5; g.setLineDash([4, 3]);
      g.beginPath(); g.moveTo(x, AXIS_H - 6); g.lineTo(x, H); g.stroke();
      g.setLineDash([]); g.lineWidth = 1;
      g.fillStyle = '#8e44ad';
      g.fillText(`↻ loop ${lasso.start}–${lasso.end - 1}`, x + 3, AXIS_H - 1);
    }
    if (cursor >= 0) {
      const x = LABEL_W + (cursor + 0.5) * px;
      g.strokeStyle = '#c0392b'; g.lineWidth = 1.5;
      g.beginPath(); g.moveTo(x, AXIS_H - 6); g.lineTo(x, H); g.stroke(); g.lineWidth = 1;
    }
    return {px, tickAt: x => Math.floor((x - LABEL_W) / px)};
  }

  // Messages between instances: present events from their sender to their receivers, and
  // changes of connected variables; "environment" sends the free inputs.
  function messages(model, records) {
    const bySlot = {};
    for (const v of model.vars.concat(model.events.map(e => Object.assign({isEvent: true}, e)))) {
      (bySlot[v.slot] = bySlot[v.slot] || []).push(v);
    }
    const chans = [];
    for (const group of Object.values(bySlot)) {
      const free = group.some(v => v.free);
      const sender = free ? -1 : (group.find(v => v.kind !== 'input') || group[0]).instance;
      const receivers = group.filter(v => v.kind === 'input' && v.instance !== sender);
      if (!receivers.length) continue;
      chans.push({group, sender, receivers, isEvent: !!group[0].isEvent});
    }
    const rows = [];
    records.forEach((r, t) => {
      if (!r.vars) return;
      const prev = t > 0 ? records[t - 1] : null;
      for (const c of chans) {
        const src = c.group.find(v => v.instance === c.sender) || c.receivers[0];
        if (c.isEvent) {
          if (r.events.includes(src.name)) for (const rv of c.receivers) rows.push({t, from: c.sender, to: rv.instance, label: rv.name.split('.').pop()});
        } else {
          const val = r.vars[src.name];
          const before = prev && prev.vars ? prev.vars[src.name] : undefined;
          if (prev ? val !== before : false) for (const rv of c.receivers) rows.push({t, from: c.sender, to: rv.instance, label: `${rv.name.split('.').pop()} = ${val}`});
        }
      }
    });
    return rows;
  }

  function drawMsc(svg, model, records, cursor, onPick) {
    const rows = messages(model, records).slice(-300);
    const lanes = [{name: 'environment'}].concat(model.instances);
    const COL = 170, ROW = 22, TOP = 30, LEFT = 60;
    const W = LEFT + lanes.length * COL, H = TOP + rows.length * ROW + 20;
    const xOf = i => LEFT + (i + 1) * COL + COL / 2;
    const out = [];
    lanes.forEach((l, i) => {
      const x = LEFT + i * COL + COL / 2;
      out.push(`<rect x="${x - 60}" y="4" width="120" height="20" rx="3" fill="#eef2f8" stroke="#8a93a3"/><text x="${x}" y="18" text-anchor="middle" font-size="11">${l.name}</text>`);
      out.push(`<line x1="${x}" y1="24" x2="${x}" y2="${H}" stroke="#b9c0cc" stroke-dasharray="4 3"/>`);
    });
    rows.forEach((m, k) => {
      const y = TOP + k * ROW + 12;
      const x1 = xOf(m.from), x2 = xOf(m.to);
      const hot = m.t === cursor;
      const col = hot ? '#e0671b' : '#2d3546';
      out.push(`<g class="msg" data-t="${m.t}" style="cursor:pointer"><text x="6" y="${y + 4}" font-size="10" fill="#6a7383">t=${m.t}</text>` +
        `<line x1="${x1}" y1="${y}" x2="${x2}" y2="${y}" stroke="${col}" stroke-width="${hot ? 2 : 1.2}" marker-end="url(#mscarrow)"/>` +
        `<text x="${(x1 + x2) / 2}" y="${y - 3}" text-anchor="middle" font-size="10" font-family="Menlo, monospace" fill="${col}">${m.label.replace(/</g, '&lt;')}</text></g>`);
    });
    svg.setAttribute('width', W); svg.setAttribute('height', H);
    svg.innerHTML = '<defs><marker id="mscarrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="6" markerHeight="6" orient="auto"><path d="M0,0 L10,5 L0,10 z" fill="#2d3546"/></marker></defs>' + out.join('');
    for (const g of svg.querySelectorAll('g.msg')) g.addEventListener('click', () => onPick(+g.dataset.t));
    return rows.length;
  }

  return {draw, drawMsc, messages};
})();
