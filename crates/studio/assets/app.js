// The studio page: one WebSocket session; the server runs every tick, the page draws.
'use strict';

const $ = s => document.querySelector(s);
const studio = window.studio = {
  model: null, records: [], cursor: -1, run: null, held: {}, armed: {}, ready: false,
  lastScenario: null, errors: [], svgs: [], layouts: {}, selection: [], tab: 'wave', hidden: new Set(),
};
const token = new URLSearchParams(location.search).get('token') || '';
let ws, nextId = 1;
const waiting = new Map();
let running = false, busy = false;

// The session's resume key lives in this tab's sessionStorage: a reload presents it and the
// server resumes the run (it keeps a closed page's session for a while, see docs/studio.md).
const RESUME = 'statecheck-resume';
function connect() {
  performance.mark('studio-connect');
  let resume = '';
  try { resume = sessionStorage.getItem(RESUME) || ''; } catch (e) { resume = ''; }
  ws = new WebSocket(`${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/ws?token=${encodeURIComponent(token)}` +
    (resume ? `&resume=${encodeURIComponent(resume)}` : ''));
  ws.onmessage = ev => receive(JSON.parse(ev.data));
  ws.onclose = () => { toast('connection closed — reload the page', true); setRunning(false); };
}

// Send a request; resolves with its reply.
function send(req) {
  const id = nextId++;
  req.id = id;
  return new Promise(resolve => { waiting.set(id, resolve); ws.send(JSON.stringify(req)); });
}
studio.send = send;

function receive(m) {
  if (m.resume) { try { sessionStorage.setItem(RESUME, m.resume); } catch (e) { /* storage disabled */ } }
  if (m.type === 'model') {
    performance.mark('studio-model');
    if (m.session !== undefined) setModel(m.model);
    performance.mark('studio-charts');
  } else if (m.type === 'diagnostics') {
    showDiagnostics(m.diagnostics);
  } else if (m.type === 'state') {
    applyState(m);
    if (m.note) toast(m.note, true);
  } else if (m.type === 'verdict') {
    showVerdict(m);
  } else if (m.type === 'verify_done') {
    for (const r of m.results || []) showVerdict(r);
    $('#vstate').textContent = m.error ? `error: ${m.error}` : `done in ${(m.time_s || 0).toFixed(1)} s`;
    $('#verify').disabled = false;
  } else if (m.type === 'scenario') {
    studio.lastScenario = m.text;
  } else if (m.type === 'error') {
    studio.errors.push(m);
    toast(m.message, true);
    if (running) setRunning(false);
  }
  if (m.id && waiting.has(m.id)) { waiting.get(m.id)(m); waiting.delete(m.id); }
}

function toast(text, err) {
  const t = document.createElement('div');
  t.className = 'toast' + (err ? ' err' : '');
  t.textContent = text;
  document.body.appendChild(t);
  setTimeout(() => t.remove(), err ? 5000 : 2500);
}

function showDiagnostics(list) {
  const d = $('#diag');
  d.hidden = false;
  d.innerHTML = '<h2>The model does not check</h2><p>Fix the file and save it: the page reloads by itself.</p>' +
    list.map(x => `<div class="d"><b>${x.severity}${x.code ? '[' + x.code + ']' : ''}</b>: ${escapeHtml(x.message)}<br><code>${escapeHtml(x.file)}${x.line ? ':' + x.line + ':' + x.col : ''}</code>` +
      (x.text ? `<pre>${escapeHtml(x.text)}\n${' '.repeat(Math.max(0, x.col - 1))}^</pre>` : '') + (x.hint ? `<i>help: ${escapeHtml(x.hint)}</i>` : '') + '</div>').join('');
  $('#charts').innerHTML = '';
  studio.model = null;
  studio.ready = true;
}

function escapeHtml(s) { return String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;'); }

function setModel(model) {
  studio.ready = false;
  $('#diag').hidden = true;
  studio.model = model;
  studio.records = [];
  studio.cursor = -1;
  studio.layouts = {};
  $('#title').textContent = `${model.system} — ${model.path}`;
  document.title = `${model.system} · statecheck studio`;
  buildPresets();
  buildControls();
  defaultSelection();
  studio.layoutStart = performance.now();
  buildCharts();
  if (studio.laidOut) { studio.layoutMs = 0; performance.mark('studio-laid-out'); }
  render();
  studio.painted = false;
  studio.ready = true;
}

// ---------------------------------------------------------------- environment controls
function inputsOf(inst) { return studio.model.inputs.filter(i => i.instance === inst); }

function buildControls() {
  const box = $('#controls');
  box.innerHTML = '';
  const m = studio.model;
  if (!m.inputs.length) { box.innerHTML = '<p class="muted">The system is closed: no free inputs.</p>'; return; }
  m.instances.forEach((inst, k) => {
    const ins = inputsOf(k).filter(i => !studio.hidden.has(i.name));
    if (!ins.length) return;
    const h = document.createElement('h3');
    h.textContent = inst.name;
    box.appendChild(h);
    for (const i of ins) box.appendChild(control(i));
  });
}

function control(i) {
  const row = document.createElement('div');
  row.className = 'ctl';
  row.dataset.input = i.name;
  const short = i.name.slice(i.name.indexOf('.') + 1);
  const lab = document.createElement('label');
  lab.className = 'name'; lab.textContent = short; lab.title = i.name;
  row.appendChild(lab);
  const right = document.createElement('div');
  right.className = 'range';
  const setHeld = v => send({op: 'set', set: {[i.name]: v}});
  if (i.event || i.type === 'bool') {
    if (!i.event) {
      const sw = document.createElement('label');
      sw.className = 'switch'; sw.title = 'held value';
      sw.innerHTML = `<input type="checkbox" data-held="${i.name}"><span></span>`;
      sw.querySelector('input').addEventListener('change', e => setHeld(e.target.checked));
      right.appendChild(sw);
    } else {
      const hold = document.createElement('label');
      hold.className = 'chk'; hold.title = 'hold: present every tick';
      hold.innerHTML = `<input type="checkbox" data-held="${i.name}">hold`;
      hold.querySelector('input').addEventListener('change', e => setHeld(e.target.checked));
      right.appendChild(hold);
    }
    const b = document.createElement('button');
    b.className = 'pulse'; b.dataset.pulse = i.name;
    b.textContent = i.event ? 'raise' : '1 tick';
    b.title = i.event ? 'present in the next tick only' : 'the opposite value for the next tick only';
    b.addEventListener('click', () => {
      if (i.name in studio.armed) delete studio.armed[i.name];
      else studio.armed[i.name] = i.event ? true : !studio.held[i.name];
      b.classList.toggle('armed', i.name in studio.armed);
    });
    right.appendChild(b);
  } else if (i.type === 'enum') {
    const s = document.createElement('select');
    s.dataset.held = i.name;
    for (const v of i.variants) s.add(new Option(v, v));
    s.addEventListener('change', () => setHeld(s.value));
    right.appendChild(s);
  } else {
    const wide = i.hi - i.lo <= 100000;
    if (wide) {
      const r = document.createElement('input');
      r.type = 'range'; r.min = i.lo; r.max = i.hi; r.dataset.heldRange = i.name;
      r.addEventListener('change', () => setHeld(+r.value));
      r.addEventListener('input', () => { const n = row.querySelector('input[type=number]'); if (n) n.value = r.value; });
      right.appendChild(r);
    }
    const n = document.createElement('input');
    n.type = 'number'; n.min = i.lo; n.max = i.hi; n.dataset.held = i.name;
    n.title = `${i.lo}..${i.hi}`;
    n.addEventListener('change', () => {
      const v = Math.round(+n.value);
      if (Number.isFinite(v) && v >= i.lo && v <= i.hi) setHeld(v); else { toast(`${i.name} must be in ${i.lo}..${i.hi}`, true); syncControls(); }
    });
    right.appendChild(n);
  }
  row.appendChild(right);
  return row;
}

function syncControls() {
  for (const el of document.querySelectorAll('[data-held]')) {
    const v = studio.held[el.dataset.held];
    if (v === undefined) continue;
    if (el.type === 'checkbox') el.checked = !!v; else if (document.activeElement !== el) el.value = v;
  }
  for (const el of document.querySelectorAll('[data-held-range]')) {
    const v = studio.held[el.dataset.heldRange];
    if (v !== undefined && document.activeElement !== el) el.value = v;
  }
  for (const b of document.querySelectorAll('button.pulse')) b.classList.toggle('armed', b.dataset.pulse in studio.armed);
}

// ---------------------------------------------------------------- presets (thesis ch. 4)
function buildPresets() {
  const sel = $('#preset');
  sel.innerHTML = '';
  sel.add(new Option('all inputs', 'all'));
  const m = studio.model;
  const names = m.inputs.map(i => i.name);
  const fault = n => /(stall|fault|powerloss|savefails|cofnow|fail|corrupt)/i.test(n.split('.').pop());
  if (names.some(n => /\.runMode$/.test(n))) sel.add(new Option('FAM mode: you are the master', 'fam'));
  if (names.some(n => /ccm/i.test(n))) sel.add(new Option('closed loop: CCM and faults', 'closed'));
  sel.onchange = () => applyPreset(sel.value, fault);
}

function applyPreset(p, fault) {
  const m = studio.model;
  studio.hidden = new Set();
  const set = {};
  if (p === 'fam') {
    for (const i of m.inputs) {
      const short = i.name.split('.').pop();
      if (short === 'runMode') set[i.name] = 'NORMAL_RUN';
    }
  } else if (p === 'closed') {
    for (const i of m.inputs) if (!/ccm/i.test(i.name) && !fault(i.name)) studio.hidden.add(i.name);
  }
  buildControls();
  syncControls();
  if (Object.keys(set).length) send({op: 'set', set});
}

// ---------------------------------------------------------------- charts
// Layouts are computed by ELK in a worker (layout-worker.js), once per chart (instances share
// it), and kept in the browser's storage keyed by a hash of the chart's description. Until a
// chart's layout arrives its cards show the provisional drawing of `Chart.quick`, already
// highlighted and animated, so the page is interactive at once.
let worker = null, workerSeq = 0;
const workerWaiting = new Map();
function startWorker() {
  if (!worker) {
    worker = new Worker('/layout-worker.js');
    worker.onmessage = e => {
      const w = workerWaiting.get(e.data.id);
      workerWaiting.delete(e.data.id);
      if (w) { if (e.data.error) w.reject(new Error(e.data.error)); else w.resolve(e.data.svg); }
    };
    worker.onerror = e => {
      for (const w of workerWaiting.values()) w.reject(new Error(e.message || 'layout worker failed'));
      workerWaiting.clear();
      worker = null;
    };
  }
}
function layoutInWorker(chart) {
  startWorker();
  const id = ++workerSeq;
  return new Promise((resolve, reject) => {
    workerWaiting.set(id, {resolve, reject});
    worker.postMessage({id, chart});
  });
}

let generation = 0;
function buildCharts() {
  const box = $('#charts');
  box.innerHTML = '';
  const m = studio.model;
  const gen = ++generation;
  studio.afterPaint = null;
  const svgText = {}, pending = [];
  for (const inst of m.instances) {
    if (inst.chart in svgText) continue;
    const key = 'statecheck-layout-v1:' + hash(JSON.stringify(m.charts[inst.chart]));
    let svg = null;
    try { svg = localStorage.getItem(key); } catch (e) { svg = null; }
    if (!svg) {
      svg = Chart.quick(m.charts[inst.chart]);
      pending.push({chart: inst.chart, key});
    }
    svgText[inst.chart] = svg;
  }
  studio.svgs = m.instances.map(inst => {
    const card = document.createElement('div');
    card.className = 'card' + (pending.some(p => p.chart === inst.chart) ? ' pending' : '');
    card.dataset.instance = inst.name;
    card.innerHTML = `<div class="cardhead">${escapeHtml(inst.name)}<span class="chartname">${escapeHtml(m.charts[inst.chart].name)}${inst.observer ? ' · observer' : ''}</span></div>` + svgText[inst.chart];
    box.appendChild(card);
    return card.querySelector('svg');
  });
  // Many instances side by side: start smaller (master + 5 FAMs has 19 instances).
  $('#zoom').value = m.instances.length > 8 ? '0.5' : '1';
  zoom();
  studio.laidOut = !pending.length;
  if (!pending.length) return;
  // The layouts start once the first state is drawn (the page is interactive first; the worker
  // would compete with it for the processor), in instance order.
  studio.afterPaint = () => layoutPending(m, gen, pending);
}

function layoutPending(m, gen, pending) {
  let left = pending.length;
  for (const {chart, key} of pending) {
    layoutInWorker(m.charts[chart]).then(svg => {
      try { localStorage.setItem(key, svg); } catch (e) { /* storage full or disabled */ }
      if (gen !== generation) return;
      m.instances.forEach((inst, k) => {
        if (inst.chart !== chart) return;
        const old = studio.svgs[k];
        const holder = document.createElement('div');
        holder.innerHTML = svg;
        const fresh = holder.firstChild;
        old.replaceWith(fresh);
        studio.svgs[k] = fresh;
        const card = fresh.closest('.card');
        if (card) card.classList.remove('pending');
      });
      zoom();
      render();
    }).catch(e => {
      if (gen !== generation) return;
      toast(`layout of ${m.charts[chart].name} failed (${e.message}); the provisional drawing stays`, true);
      m.instances.forEach((inst, k) => { if (inst.chart === chart && studio.svgs[k]) studio.svgs[k].closest('.card').classList.remove('pending'); });
    }).finally(() => {
      if (gen !== generation) return;
      if (--left === 0) {
        studio.laidOut = true;
        studio.layoutMs = performance.now() - studio.layoutStart;
        performance.mark('studio-laid-out');
      }
    });
  }
}

// A 53-bit string hash (cyrb53), for layout cache keys.
function hash(str) {
  let h1 = 0xdeadbeef, h2 = 0x41c6ce57;
  for (let i = 0; i < str.length; i++) {
    const ch = str.charCodeAt(i);
    h1 = Math.imul(h1 ^ ch, 2654435761);
    h2 = Math.imul(h2 ^ ch, 1597334677);
  }
  h1 = Math.imul(h1 ^ (h1 >>> 16), 2246822507) ^ Math.imul(h2 ^ (h2 >>> 13), 3266489909);
  h2 = Math.imul(h2 ^ (h2 >>> 16), 2246822507) ^ Math.imul(h1 ^ (h1 >>> 13), 3266489909);
  return (4294967296 * (2097151 & h2) + (h1 >>> 0)).toString(36) + ':' + str.length;
}

function zoom() {
  const z = +$('#zoom').value || 1;
  for (const svg of studio.svgs) {
    const w = +svg.getAttribute('width'), h = +svg.getAttribute('height');
    svg.style.width = `${w * z}px`;
    svg.style.height = `${h * z}px`;
  }
}

// ---------------------------------------------------------------- state and rendering
function applyState(m) {
  if (m.truncate !== null && m.truncate !== undefined) studio.records.length = Math.min(studio.records.length, m.truncate);
  for (const r of m.ticks) studio.records[r.tick] = r;
  studio.records.length = Math.min(studio.records.length, m.run.ticks + (m.run.stop && m.run.stop.status === 'assume_violated' ? 0 : 0));
  studio.run = m.run;
  studio.held = m.held;
  studio.cursor = studio.records.length - 1;
  syncControls();
  render();
  if (!studio.painted) {
    studio.painted = true;
    performance.mark('studio-interactive');
    const then = studio.afterPaint;
    studio.afterPaint = null;
    if (then) then();
  }
}

function shown() {
  const r = studio.records;
  let c = studio.cursor;
  while (c >= 0 && r[c] && !r[c].active) c--;
  return c >= 0 ? r[c] : null;
}

function render() {
  const m = studio.model;
  if (!m) return;
  const rec = shown();
  const cov = $('#cov').checked && studio.run ? studio.run.coverage : null;
  studio.svgs.forEach((svg, k) => svg && Chart.paint(svg, k, rec, m, cov));
  renderStatus();
  renderVars(rec);
  renderMessages();
  renderSignals();
}

// Times come from the server (`time_text`, exact seconds computed by the IR's one helper).

function renderStatus() {
  const run = studio.run;
  if (!run) return;
  const m = studio.model;
  const t = run.ticks;
  let s = `<b>${t}</b> tick${t === 1 ? '' : 's'}` + (run.time_text ? ` · ${run.time_text} s` : '');
  if (studio.cursor < studio.records.length - 1) s += ` · viewing tick ${studio.cursor}`;
  if (run.future) s += ` · ${run.future} to redo`;
  if (run.stop) s += ` · <span class="stop">${escapeHtml(run.stop.message)}</span>`;
  const l = run.lasso;
  if (l) {
    s += l.broken ? ` · <span class="stop">not a lasso of this model</span>`
      : ` · <span class="lasso">loop ${l.start}–${l.end - 1}${l.following ? ' (Step goes around it)' : ', left'}</span>`;
    if (l.violated) s += ` · <span class="stop">${escapeHtml(l.violated.message)} (on the infinite run)</span>`;
  }
  $('#status').innerHTML = s;
  // Viewing an earlier tick, Back branches there.
  const past = studio.cursor >= 0 && studio.cursor < studio.records.length - 1;
  $('#back').textContent = past ? `⑂ Branch at ${studio.cursor}` : '◀ Back';
  $('#back').title = past ? `Continue interactively from tick ${studio.cursor} (the later ticks are kept for Redo)` : 'Step back one tick (←)';
  $('#forward').disabled = !run.future;
  $('#back').disabled = t === 0;
  for (const id of ['#step', '#stepn', '#run']) $(id).disabled = !!run.stop;
}

function renderVars(rec) {
  const tb = $('#vars tbody');
  $('#cursor-tick').textContent = studio.cursor >= 0 ? studio.cursor + (rec && rec.time_text ? ` (${rec.time_text} s)` : '') : '–';
  if (!rec) { tb.innerHTML = ''; return; }
  const prev = studio.records[rec.tick - 1];
  const rows = [];
  const m = studio.model;
  m.instances.forEach((inst, k) => {
    rows.push(`<tr class="inst"><td colspan="2">${escapeHtml(inst.name)} <span style="font-weight:normal;color:#6a7383">${escapeHtml((rec.active[inst.name] || []).filter(p => !(rec.active[inst.name] || []).some(q => q.startsWith(p + '.'))).join(', '))}</span></td></tr>`);
    for (const v of m.vars) {
      if (v.instance !== k) continue;
      const val = rec.vars[v.name];
      const ch = prev && prev.vars && prev.vars[v.name] !== val;
      rows.push(`<tr class="${ch ? 'changed' : ''}"><td title="${v.name} (${v.kind})">${escapeHtml(v.name.slice(inst.name.length + 1))}</td><td>${escapeHtml(String(val))}</td></tr>`);
    }
    for (const e of m.events) {
      if (e.instance !== k) continue;
      if (rec.events.includes(e.name)) rows.push(`<tr class="changed"><td>${escapeHtml(e.name.slice(inst.name.length + 1))}</td><td>⚡ present</td></tr>`);
    }
  });
  tb.innerHTML = rows.join('');
}

function renderMessages() {
  const box = $('#messages');
  const run = studio.run;
  const items = [];
  if (run && run.stop) items.push(`<div class="msg" data-t="${run.stop.tick}">${escapeHtml(run.stop.message)}</div>`);
  const l = run && run.lasso;
  if (l) {
    if (l.violated) items.push(`<div class="msg lassov" data-t="${l.violated.tick}">${escapeHtml(l.violated.message)}: the ticks 0–${l.end - 1}, then ${l.start}–${l.end - 1} forever</div>`);
    if (l.broken) items.push(`<div class="msg" data-t="${l.end - 1}">${escapeHtml(l.broken)}</div>`);
    else items.push(`<div class="msg info lassostart" data-t="${l.start}">↻ the loop starts at tick ${l.start}${l.fair ? '' : ' (not fair: temporal properties not evaluated)'}</div>`);
  }
  if (studio.lastLoaded) items.push(`<div class="msg info">replaying ${escapeHtml(studio.lastLoaded)}</div>`);
  box.innerHTML = items.join('');
  for (const d of box.querySelectorAll('.msg[data-t]')) d.onclick = () => { setCursor(+d.dataset.t); };
}

// ---------------------------------------------------------------- verify from the page
studio.verdicts = {};
function showVerdict(v) {
  studio.verdicts[v.name] = v;
  const list = $('#rlist');
  let row = list.querySelector(`.res[data-name="${CSS.escape(v.name)}"]`);
  if (!row) {
    row = document.createElement('div');
    row.dataset.name = v.name;
    list.appendChild(row);
  }
  row.className = 'res' + (v.scenario ? ' replay' : '');
  const at = v.time_text ? `, decided at tick ${v.tick} (${v.time_text} s)` : '';
  const what = v.scenario ? `${v.verdict === 'reachable' ? 'witness' : 'counterexample'}: ${v.depth} ticks${at} — click to replay` : (v.reason || v.note || '');
  row.innerHTML = `<span>${escapeHtml(v.name)}</span><span class="v ${v.verdict}">${v.verdict}</span>` +
    `<span class="sub">${escapeHtml(v.kind)} · ${escapeHtml(v.engine || '')}${what ? ' · ' + escapeHtml(what) : ''}</span>`;
  row.onclick = v.scenario ? () => {
    setRunning(false);
    studio.lastLoaded = `${v.name} (${v.verdict})`;
    send({op: 'load_scenario', text: v.scenario});
  } : null;
}

async function verifyAll() {
  $('#results').hidden = false;
  $('#rlist').innerHTML = '';
  studio.verdicts = {};
  $('#vstate').textContent = 'running…';
  $('#verify').disabled = true;
  const r = await send({op: 'verify', engine: $('#engine').value, timeout_s: 60});
  if (r.type === 'error') { $('#verify').disabled = false; $('#vstate').textContent = r.message; }
}

function setCursor(t) {
  studio.cursor = Math.max(0, Math.min(studio.records.length - 1, t));
  render();
}

// ---------------------------------------------------------------- signals
function defaultSelection() {
  const m = studio.model;
  const sel = [];
  // The free inputs, then the outputs of the instances with the most states (the plant and
  // the controller rather than glue charts), a dozen rows in all.
  for (const v of m.vars) if (v.free && sel.length < 5) sel.push(v);
  for (const e of m.events) if (e.free && sel.length < 7) sel.push(Object.assign({isEvent: true}, e));
  const size = k => m.charts[m.instances[k].chart].states.length;
  const order = m.instances.map((_, k) => k).filter(k => !m.instances[k].observer).sort((a, b) => size(b) - size(a));
  for (const k of order) {
    for (const v of m.vars) if (v.instance === k && v.kind === 'output' && sel.length < 13 && !sel.includes(v)) sel.push(v);
  }
  studio.selection = sel;
  const pk = $('#picker');
  pk.innerHTML = m.vars.map(v => `<label><input type="checkbox" data-sig="${v.name}"${sel.includes(v) ? ' checked' : ''}> ${v.name}</label>`).join('') +
    m.events.map(e => `<label><input type="checkbox" data-ev="${e.name}"${sel.some(s => s.name === e.name) ? ' checked' : ''}> ⚡ ${e.name}</label>`).join('');
  pk.onchange = () => {
    studio.selection = [];
    for (const c of pk.querySelectorAll('input:checked')) {
      if (c.dataset.sig) studio.selection.push(m.vars.find(v => v.name === c.dataset.sig));
      else studio.selection.push(Object.assign({isEvent: true}, m.events.find(v => v.name === c.dataset.ev)));
    }
    renderSignals();
  };
}

let waveGeom = null;
function renderSignals() {
  const m = studio.model;
  if (studio.tab === 'wave') {
    waveGeom = Wave.draw($('#wave'), m, studio.records, studio.selection, studio.cursor, studio.run && studio.run.lasso);
  } else {
    Wave.drawMsc($('#msc'), m, studio.records, studio.cursor, t => setCursor(t));
  }
  $('#timeinfo').textContent = `time axis in ticks${m.tick_ms ? ` (1 tick = ${m.tick_ms} ms)` : ''} · click to move the cursor; Back from a past tick branches there`;
}

// ---------------------------------------------------------------- actions
async function stepOnce(n) {
  if (busy || !studio.model) return null;
  busy = true;
  try {
    if ($('#random').checked) return await send({op: 'random', n, seed: +$('#seed').value || 0});
    const pulse = studio.armed;
    studio.armed = {};
    return await send({op: 'step', n, pulse});
  } finally { busy = false; }
}

function setRunning(on) {
  running = on;
  $('#run').textContent = on ? '❚❚ Pause' : '▶▶ Run';
  if (on) loop();
}

async function loop() {
  while (running) {
    const t0 = performance.now();
    const r = await stepOnce(1);
    if (!r || r.type === 'error' || (studio.run && studio.run.stop)) { setRunning(false); break; }
    const wait = 1000 / +$('#rate').value - (performance.now() - t0);
    if (wait > 0) await new Promise(res => setTimeout(res, wait));
  }
}

async function back() {
  const n = studio.records.length;
  // From a past tick: branch there (keep ticks 0..cursor); else one tick back.
  const to = studio.cursor < n - 1 ? studio.cursor + 1 : Math.max(0, (studio.run ? studio.run.ticks : n) - 1);
  return send({op: 'back', tick: to});
}

function download(name, text) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([text], {type: 'text/plain'}));
  a.download = name;
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

function wire() {
  $('#step').onclick = () => stepOnce(1);
  $('#stepn').onclick = () => stepOnce(Math.max(1, Math.min(1000, +$('#n').value || 1)));
  $('#run').onclick = () => setRunning(!running);
  $('#back').onclick = back;
  $('#forward').onclick = () => send({op: 'forward', n: 1});
  $('#reset').onclick = () => { setRunning(false); studio.lastLoaded = null; send({op: 'reset'}); };
  $('#cov').onchange = render;
  $('#verify').onclick = verifyAll;
  $('#zoom').onchange = zoom;
  $('#save').onclick = async () => {
    const r = await send({op: 'save'});
    download(`${studio.model.system}.scn`, r.text);
  };
  $('#load').onchange = async e => {
    const f = e.target.files[0];
    if (!f) return;
    studio.lastLoaded = f.name;
    await send({op: 'load_scenario', text: await f.text()});
    e.target.value = '';
  };
  $('#wave').addEventListener('click', e => {
    if (!waveGeom) return;
    const r = e.target.getBoundingClientRect();
    const t = waveGeom.tickAt(e.clientX - r.left);
    if (t >= 0) setCursor(t);
  });
  $('#pick').onclick = () => { $('#picker').hidden = !$('#picker').hidden; };
  for (const b of document.querySelectorAll('.tab[data-tab]')) {
    b.onclick = () => {
      studio.tab = b.dataset.tab;
      for (const x of document.querySelectorAll('.tab[data-tab]')) x.classList.toggle('on', x === b);
      $('#wavewrap').hidden = studio.tab !== 'wave';
      $('#mscwrap').hidden = studio.tab !== 'msc';
      renderSignals();
    };
  }
  document.addEventListener('keydown', e => {
    if (e.target.tagName === 'INPUT' || e.target.tagName === 'SELECT') return;
    if (e.key === 'ArrowRight' || e.key === ' ') { e.preventDefault(); stepOnce(1); }
    else if (e.key === 'ArrowLeft') { e.preventDefault(); back(); }
    else if (e.key === 'p' || e.key === 'P') setRunning(!running);
    else if (e.key === 'r' || e.key === 'R') $('#reset').click();
  });
  window.addEventListener('resize', () => renderSignals());
}

wire();
connect();

