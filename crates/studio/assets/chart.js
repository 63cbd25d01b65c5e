// Chart drawing: one ELK layered layout per chart (hierarchy included, so transitions between
// levels are routed), rendered as SVG the Stateflow way: rounded state boxes nested in their
// parents, parallel regions as dashed boxes numbered in execution order, a dot and arrow for
// default transitions, circles for junctions and history, `trigger [guard] / action` labels.
'use strict';

const Chart = (() => {
  const NAME_W = 7.6, MONO_W = 6.6, LINE_H = 13, LABEL_MAX = 46;
  // Created on first use: on the page ELK runs in a worker (`layout-worker.js`), so the page
  // itself never loads the 1.6 MB library.
  let elk = null;
  // Exclusive (OR) levels: layered, top-down, transitions routed orthogonally across levels.
  const LAYERED = {
    'elk.algorithm': 'layered',
    'elk.direction': 'DOWN',
    'elk.hierarchyHandling': 'INCLUDE_CHILDREN',
    'elk.layered.spacing.nodeNodeBetweenLayers': '34',
    'elk.spacing.nodeNode': '26',
    'elk.spacing.edgeLabel': '4',
    'elk.spacing.edgeNode': '14',
    'elk.layered.spacing.edgeNodeBetweenLayers': '12',
    'elk.edgeLabels.inline': 'false',
    'elk.layered.thoroughness': '4',
    'elk.edgeRouting': 'ORTHOGONAL',
  };
  // Parallel (AND) levels: the regions packed in rows, as Stateflow tiles parallel states.
  const PACK = {
    'elk.algorithm': 'rectpacking',
    'elk.aspectRatio': '1.9',
    'elk.spacing.nodeNode': '14',
    'elk.rectpacking.trybox': 'false',
  };

  function esc(s) {
    return String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
  }

  // Break a label into lines of at most `max` characters, preferring breaks after
  // `&&`, `||`, `;`, `,` and before `/`.
  function wrap(text, max) {
    if (text.length <= max) return [text];
    const words = text.split(' ');
    const lines = [];
    let cur = '';
    for (const w of words) {
      const brk = cur.length > 0 && (cur.length + 1 + w.length > max || (w === '/' && cur.length > max / 2));
      if (brk) { lines.push(cur); cur = w; } else { cur = cur ? cur + ' ' + w : w; }
    }
    if (cur) lines.push(cur);
    return lines.slice(0, 8).concat(lines.length > 8 ? ['…'] : []);
  }

  // The ELK graph of a chart, and the drawing facts ELK does not keep.
  function graph(chart) {
    const S = chart.states;
    const internal = {};   // state id -> internal transition labels
    for (const t of chart.transitions) {
      if (t.dest.kind === 'internal') (internal[t.source] = internal[t.source] || []).push(t);
    }
    const info = {};        // elk id -> {kind, sid, lines, order}
    const edges = [];
    const edgeInfo = {};
    const textLines = sid => {
      const s = S[sid];
      const lines = [];
      if (s.actions.length) lines.push(s.actions.join(', ') + ':  …');
      for (const t of internal[sid] || []) for (const l of wrap(t.label, LABEL_MAX)) lines.push(l);
      return lines;
    };
    function node(sid, order) {
      const s = S[sid];
      const id = 's' + sid;
      const lines = textLines(sid);
      info[id] = {kind: s.region ? 'region' : (s.kind === 'simple' ? 'state' : 'composite'), sid, lines, order};
      // Room for the name, the execution order and the coverage badge.
      const nameW = s.name.length * NAME_W + (order ? 30 : 22) + 36;
      const linesW = Math.max(0, ...lines.map(l => l.length * MONO_W)) + 18;
      if (s.kind === 'simple') {
        return {id, width: Math.max(86, nameW, linesW), height: 30 + lines.length * LINE_H};
      }
      const n = {id, children: [], edges: [], layoutOptions: Object.assign({
        'elk.padding': `[top=${26 + lines.length * LINE_H},left=14,bottom=14,right=14]`,
        'elk.nodeSize.constraints': 'MINIMUM_SIZE',
        'elk.nodeSize.minimum': `(${Math.max(nameW, linesW)},40)`,
      }, s.kind === 'and' ? PACK : LAYERED)};
      fill(n, sid);
      return n;
    }
    function fill(n, sid) {
      const s = S[sid];
      if (s.kind === 'and') {
        s.children.forEach((c, k) => n.children.push(node(c, k + 1)));
        return;
      }
      for (const c of s.children) n.children.push(node(c, 0));
      if (s.initial !== null && s.initial !== undefined) {
        const iid = 'i' + sid;
        info[iid] = {kind: 'init'};
        n.children.push({id: iid, width: 10, height: 10});
        edges.push({id: 'ei' + sid, sources: [iid], targets: ['s' + s.initial]});
        edgeInfo['ei' + sid] = {kind: 'init'};
      }
      if (s.history) {
        const hid = 'h' + sid;
        info[hid] = {kind: 'hist', deep: s.history === 'deep'};
        n.children.push({id: hid, width: 20, height: 20});
      }
    }
    const rootKind = S[0].kind;
    const root = {id: 'root', children: [], edges: [], layoutOptions: Object.assign({
      'elk.json.shapeCoords': 'ROOT',
      'elk.json.edgeCoords': 'ROOT',
      'elk.padding': '[top=12,left=12,bottom=12,right=12]',
    }, rootKind === 'and' ? PACK : LAYERED)};
    fill(root, 0);
    // Junction nodes live in the source state's parent.
    const parentNode = {};
    (function index(n) { for (const c of n.children || []) { parentNode[c.id] = n; index(c); } })(root);
    const label = (text, id) => {
      const lines = wrap(text, LABEL_MAX);
      // Room for the coverage badge after the text.
      return [{id, text: lines.join('\n'), width: Math.max(...lines.map(l => l.length)) * MONO_W + 34, height: lines.length * LINE_H}];
    };
    let jn = 0;
    function branches(t, from, list, counter, container) {
      for (const b of list) {
        const k = counter.k++;
        const eid = `e${t.id}b${k}`;
        edgeInfo[eid] = {kind: 'branch', t: t.id, b: k};
        if (b.dest.kind === 'state') {
          edges.push({id: eid, sources: [from], targets: ['s' + b.dest.state], labels: label(b.label, eid + 'l')});
        } else if (b.dest.kind === 'choice') {
          const j = 'j' + (jn++);
          info[j] = {kind: 'junction'};
          container.children.push({id: j, width: 12, height: 12});
          edges.push({id: eid, sources: [from], targets: [j], labels: label(b.label, eid + 'l')});
          branches(t, j, b.dest.branches, counter, container);
        }
      }
    }
    for (const t of chart.transitions) {
      if (t.dest.kind === 'internal') continue;
      const src = 's' + t.source;
      const eid = 'e' + t.id;
      if (t.dest.kind === 'state') {
        edgeInfo[eid] = {kind: 'tr', t: t.id};
        const e = {id: eid, sources: [src], targets: ['s' + t.dest.state]};
        if (t.label) e.labels = label(t.label, eid + 'l');
        edges.push(e);
      } else {
        const container = parentNode[src] || root;
        const j = 'j' + (jn++);
        info[j] = {kind: 'junction'};
        container.children.push({id: j, width: 12, height: 12});
        edgeInfo[eid] = {kind: 'tr', t: t.id};
        const e = {id: eid, sources: [src], targets: [j]};
        if (t.label) e.labels = label(t.label, eid + 'l');
        edges.push(e);
        branches(t, j, t.dest.branches, {k: 0}, container);
      }
    }
    // Each edge goes to the innermost compound holding both ends (ELK lays out a level with
    // its own edges; across levels only where the hierarchy is laid out as one).
    (function index(n) { for (const c of n.children || []) { parentNode[c.id] = n; index(c); } })(root);
    const chain = id => { const out = []; let n = parentNode[id]; while (n) { out.push(n); n = parentNode[n.id]; } return out; };
    for (const e of edges) {
      const a = chain(e.sources[0]), b = new Set(chain(e.targets[0]));
      const lca = a.find(n => b.has(n)) || root;
      lca.edges.push(e);
    }
    return {root, info, edgeInfo};
  }

  function pathOf(sections) {
    let d = '';
    for (const s of sections || []) {
      const pts = [s.startPoint, ...(s.bendPoints || []), s.endPoint];
      d += 'M' + pts.map(p => `${p.x.toFixed(1)},${p.y.toFixed(1)}`).join(' L');
    }
    return d;
  }

  // Lay out a chart; resolves to the SVG text (without instance-specific state).
  async function layout(chart) {
    const g = graph(chart);
    if (!elk) elk = new ELK();
    const out = await elk.layout(g.root);
    const parts = [];
    const W = Math.ceil(out.width), H = Math.ceil(out.height);
    parts.push(`<svg xmlns="http://www.w3.org/2000/svg" width="${W}" height="${H}" viewBox="0 0 ${W} ${H}">`);
    parts.push('<defs><marker id="arrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" markerHeight="7" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" fill="#4a5366"/></marker>' +
      '<marker id="arrowF" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="6" markerHeight="6" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" fill="#e0671b"/></marker></defs>');
    const nodes = [];
    (function walk(n, depth) { for (const c of n.children || []) { nodes.push([c, depth]); walk(c, depth + 1); } })(out, 0);
    nodes.sort((a, b) => a[1] - b[1]);
    for (const [n] of nodes) {
      const inf = g.info[n.id];
      if (!inf) continue;
      const x = n.x, y = n.y, w = n.width, h = n.height;
      if (inf.kind === 'init') {
        parts.push(`<g class="init"><circle cx="${x + w / 2}" cy="${y + h / 2}" r="4.5"/></g>`);
      } else if (inf.kind === 'junction') {
        parts.push(`<g class="junction"><circle cx="${x + w / 2}" cy="${y + h / 2}" r="6"/></g>`);
      } else if (inf.kind === 'hist') {
        parts.push(`<g class="hist"><circle cx="${x + w / 2}" cy="${y + h / 2}" r="9.5"/><text x="${x + w / 2}" y="${y + h / 2 + 3.5}">${inf.deep ? 'H*' : 'H'}</text></g>`);
      } else {
        const s = chart.states[inf.sid];
        const cls = 'st ' + (inf.kind === 'region' ? 'region' : inf.kind === 'composite' ? 'composite' : 'leaf');
        const rx = inf.kind === 'region' ? 3 : 9;
        parts.push(`<g class="${cls}" data-sid="${inf.sid}"><title>${esc(s.path)}</title><rect x="${x}" y="${y}" width="${w}" height="${h}" rx="${rx}"/>`);
        parts.push(`<text class="name" x="${x + 8}" y="${y + 16}">${esc(s.name)}</text>`);
        if (inf.order) parts.push(`<text class="acts" x="${x + w - 8}" y="${y + 14}" text-anchor="end">${inf.order}</text>`);
        inf.lines.forEach((l, k) => parts.push(`<text class="acts" x="${x + 8}" y="${y + 30 + k * LINE_H}">${esc(l)}</text>`));
        parts.push(`<g class="badge" data-badge-sid="${inf.sid}" transform="translate(${x + w - (inf.order ? 40 : 10)},${y + 4})"></g></g>`);
      }
    }
    const allEdges = [];
    (function walk(n) { for (const e of n.edges || []) allEdges.push(e); for (const c of n.children || []) walk(c); })(out);
    for (const e of allEdges) {
      const ei = g.edgeInfo[e.id] || {};
      const attrs = ei.kind === 'tr' ? ` data-t="${ei.t}"` : ei.kind === 'branch' ? ` data-t="${ei.t}" data-b="${ei.b}"` : '';
      parts.push(`<g class="tr ${ei.kind || ''}"${attrs}><path d="${pathOf(e.sections)}" marker-end="url(#arrow)"/>`);
      for (const l of e.labels || []) {
        const lines = l.text.split('\n');
        lines.forEach((t, k) => parts.push(`<text x="${(l.x + 2).toFixed(1)}" y="${(l.y + 10 + k * LINE_H).toFixed(1)}">${esc(t)}</text>`));
        parts.push(`<g class="badge" data-badge-t="${ei.t}" data-badge-b="${ei.b === undefined ? '' : ei.b}" transform="translate(${(l.x + l.width - 28).toFixed(1)},${(l.y).toFixed(1)})"></g>`);
      }
      parts.push('</g>');
    }
    parts.push('</svg>');
    return parts.join('');
  }


  // A provisional drawing computed at once, without ELK, shown while the worker lays the chart
  // out: the same state boxes (classes, `data-sid`, badges) nested in a simple grid, the
  // transitions as straight arrows (same `data-t`, so firing is marked) with their labels as
  // tooltips. Replaced by the ELK drawing when it arrives.
  function quick(chart) {
    const S = chart.states;
    const internal = {};
    for (const t of chart.transitions) {
      if (t.dest.kind === 'internal') (internal[t.source] = internal[t.source] || []).push(t);
    }
    const textLines = sid => {
      const st = S[sid];
      const lines = [];
      if (st.actions.length) lines.push(st.actions.join(', ') + ':  …');
      for (const t of internal[sid] || []) for (const l of wrap(t.label, LABEL_MAX)) lines.push(l);
      return lines;
    };
    const box = {};  // sid -> {w, h, lines, order, kids}
    const GAP = 26;
    function size(sid, order, depth) {
      const st = S[sid];
      const lines = sid === 0 ? [] : textLines(sid);
      const nameW = st.name.length * NAME_W + (order ? 30 : 22) + 36;
      const linesW = Math.max(0, ...lines.map(l => l.length * MONO_W)) + 18;
      const b = {w: 0, h: 0, lines, order, kids: []};
      box[sid] = b;
      if (st.kind === 'simple' || !st.children.length || depth > 64) {
        b.w = Math.max(86, nameW, linesW);
        b.h = 30 + lines.length * LINE_H;
        return b;
      }
      const and = st.kind === 'and';
      const kids = st.children.map((c, k) => size(c, and ? k + 1 : 0, depth + 1));
      const cols = Math.max(1, Math.ceil(Math.sqrt(kids.length * (and ? 1.9 : 1.2))));
      const top = (sid === 0 ? 12 : 26 + lines.length * LINE_H) + (st.initial !== null && st.initial !== undefined ? 14 : 0);
      const pad = sid === 0 ? 12 : 14;
      let y = top, maxW = 0;
      for (let r = 0; r < kids.length; r += cols) {
        const row = kids.slice(r, r + cols);
        let x = pad, rowH = 0;
        for (const k of row) { k.x = x; k.y = y; x += k.w + (and ? 14 : GAP); rowH = Math.max(rowH, k.h); }
        maxW = Math.max(maxW, x - (and ? 14 : GAP) + pad);
        y += rowH + (and ? 14 : GAP + 8);
      }
      b.kids = st.children;
      b.w = Math.max(maxW, nameW, linesW, 60);
      b.h = y - (and ? 14 : GAP + 8) + pad;
      return b;
    }
    const root = size(0, 0, 0);
    const abs = {};
    (function place(sid, ox, oy) {
      const b = box[sid];
      abs[sid] = {x: ox, y: oy, w: b.w, h: b.h};
      for (const c of b.kids) place(c, ox + box[c].x, oy + box[c].y);
    })(0, 0, 0);
    const W = Math.ceil(root.w), H = Math.ceil(root.h);
    const parts = [`<svg xmlns="http://www.w3.org/2000/svg" class="provisional" width="${W}" height="${H}" viewBox="0 0 ${W} ${H}">`];
    parts.push('<defs><marker id="arrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" markerHeight="7" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" fill="#4a5366"/></marker>' +
      '<marker id="arrowF" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="6" markerHeight="6" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" fill="#e0671b"/></marker></defs>');
    (function draw(sid) {
      const st = S[sid], b = box[sid], a = abs[sid];
      if (sid !== 0) {
        const kind = st.region ? 'region' : st.kind === 'simple' ? 'leaf' : 'composite';
        parts.push(`<g class="st ${kind}" data-sid="${sid}"><title>${esc(st.path)}</title><rect x="${a.x}" y="${a.y}" width="${a.w}" height="${a.h}" rx="${st.region ? 3 : 9}"/>`);
        parts.push(`<text class="name" x="${a.x + 8}" y="${a.y + 16}">${esc(st.name)}</text>`);
        if (b.order) parts.push(`<text class="acts" x="${a.x + a.w - 8}" y="${a.y + 14}" text-anchor="end">${b.order}</text>`);
        b.lines.forEach((l, k) => parts.push(`<text class="acts" x="${a.x + 8}" y="${a.y + 30 + k * LINE_H}">${esc(l)}</text>`));
        parts.push(`<g class="badge" data-badge-sid="${sid}" transform="translate(${a.x + a.w - (b.order ? 40 : 10)},${a.y + 4})"></g></g>`);
      }
      if (st.initial !== null && st.initial !== undefined && abs[st.initial]) {
        const t = abs[st.initial];
        const cx = t.x + 10, cy = t.y - 12;
        parts.push(`<g class="init"><circle cx="${cx}" cy="${cy}" r="4.5"/></g><g class="tr init"><path d="M${cx},${cy + 4} L${cx},${t.y}" marker-end="url(#arrow)"/></g>`);
      }
      if (st.history && sid !== 0) {
        parts.push(`<g class="hist"><circle cx="${a.x + a.w - 16}" cy="${a.y + 16}" r="9.5"/><text x="${a.x + a.w - 16}" y="${a.y + 19.5}">${st.history === 'deep' ? 'H*' : 'H'}</text></g>`);
      }
      for (const c of b.kids) draw(c);
    })(0);
    // Where the segment from the centre of `a` towards `p` leaves the box `a`.
    const exit = (a, p) => {
      const cx = a.x + a.w / 2, cy = a.y + a.h / 2, dx = p.x - cx, dy = p.y - cy;
      const k = Math.min(dx ? (a.w / 2) / Math.abs(dx) : Infinity, dy ? (a.h / 2) / Math.abs(dy) : Infinity, 1);
      return {x: cx + dx * k, y: cy + dy * k};
    };
    const firstState = d => {
      if (d.kind === 'state') return d.state;
      if (d.kind === 'choice') for (const br of d.branches) { const s = firstState(br.dest); if (s !== null) return s; }
      return null;
    };
    for (const t of chart.transitions) {
      const to = firstState(t.dest);
      if (to === null || !abs[t.source] || !abs[to]) continue;
      const a = abs[t.source], b = abs[to];
      let p, q;
      if (t.source === to) {
        p = {x: a.x + a.w, y: a.y + a.h / 3};
        q = {x: a.x + a.w, y: a.y + (2 * a.h) / 3};
        parts.push(`<g class="tr tr" data-t="${t.id}"><title>${esc(t.label || '')}</title><path d="M${p.x},${p.y} C${p.x + 30},${p.y} ${q.x + 30},${q.y} ${q.x},${q.y}" marker-end="url(#arrow)"/></g>`);
        continue;
      }
      const ca = {x: a.x + a.w / 2, y: a.y + a.h / 2}, cb = {x: b.x + b.w / 2, y: b.y + b.h / 2};
      p = exit(a, cb);
      q = exit(b, ca);
      parts.push(`<g class="tr tr" data-t="${t.id}"><title>${esc(t.label || '')}</title><path d="M${p.x.toFixed(1)},${p.y.toFixed(1)} L${q.x.toFixed(1)},${q.y.toFixed(1)}" marker-end="url(#arrow)"/></g>`);
    }
    parts.push('</svg>');
    return parts.join('');
  }

  // Highlight one instance's chart for a tick record; coverage: counts per cover item or null.
  function paint(svg, inst, rec, model, coverage) {
    const active = new Set(rec && rec.active_ids ? rec.active_ids[inst] : []);
    for (const g of svg.querySelectorAll('g.st')) g.classList.toggle('active', active.has(+g.dataset.sid));
    const fired = new Set();
    if (rec && rec.fired) {
      for (const k of rec.fired) {
        const c = model.covers[k];
        if (c && c.instance === inst && c.kind !== 'state') fired.add(c.kind === 'branch' ? `${c.transition}/${c.branch}` : `${c.transition}`);
      }
    }
    for (const g of svg.querySelectorAll('g.tr[data-t]')) {
      const key = g.dataset.b !== undefined ? `${g.dataset.t}/${g.dataset.b}` : g.dataset.t;
      const on = fired.has(key);
      g.classList.toggle('fired', on);
      const p = g.querySelector('path');
      if (p) p.setAttribute('marker-end', on ? 'url(#arrowF)' : 'url(#arrow)');
    }
    // Coverage badges.
    for (const b of svg.querySelectorAll('g.badge')) b.innerHTML = '';
    for (const g of svg.querySelectorAll('.never')) g.classList.remove('never');
    if (!coverage) return;
    model.covers.forEach((c, k) => {
      if (c.instance !== inst) return;
      const n = coverage[k] || 0;
      let holder, owner;
      if (c.kind === 'state') {
        holder = svg.querySelector(`g.badge[data-badge-sid="${c.state}"]`);
        owner = svg.querySelector(`g.st[data-sid="${c.state}"]`);
      } else if (c.kind === 'transition') {
        holder = svg.querySelector(`g.badge[data-badge-t="${c.transition}"][data-badge-b=""]`);
        owner = svg.querySelector(`g.tr[data-t="${c.transition}"]:not([data-b])`);
      } else {
        holder = svg.querySelector(`g.badge[data-badge-t="${c.transition}"][data-badge-b="${c.branch}"]`);
        owner = svg.querySelector(`g.tr[data-t="${c.transition}"][data-b="${c.branch}"]`);
      }
      // An observer's `error` state is meant never to be entered: not a gap.
      const gap = n === 0 && !c.expected_unreached;
      if (owner && gap) owner.classList.add('never');
      if (holder) {
        const txt = '×' + n;
        const w = txt.length * 6 + 6;
        const dx = c.kind === 'state' ? -w : 0;
        holder.innerHTML = `<rect x="${dx}" y="0" width="${w}" height="13" rx="6.5" class="${gap ? 'never' : ''}" style="fill:${gap ? '#c0392b' : '#6a7383'}"/><text x="${dx + 3}" y="10">${txt}</text>`;
      }
    });
  }

  // Create the ELK instance now (in a worker, ELK's bundle installs its own `onmessage` when
  // first instantiated; the worker sets its handler after this).
  function init() { if (!elk) elk = new ELK(); }

  return {init, layout, quick, paint, wrap};
})();
