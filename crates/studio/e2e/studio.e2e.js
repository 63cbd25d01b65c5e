// End-to-end tests of `statecheck serve` in a real browser (Debian's chromium, driven by
// playwright-core). Run: STATECHECK_BIN=path/to/statecheck node studio.e2e.js
// Checks the page against `statecheck sim --json` of the scenario it saves, replays a
// counterexample of `statecheck verify --cex-dir`, steps back and forward, and writes
// screenshots to docs/studio/ (or $STUDIO_SHOTS).
'use strict';

const {chromium} = require('playwright-core');
const {spawn, execFileSync} = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');
const assert = require('assert');

const ROOT = path.resolve(__dirname, '../../..');
const BIN = process.env.STATECHECK_BIN;
const SHOTS = process.env.STUDIO_SHOTS || path.join(ROOT, 'docs/studio');
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
const TMP = fs.mkdtempSync(path.join(os.tmpdir(), 'studio-e2e-'));
if (!BIN) { console.error('set STATECHECK_BIN to the statecheck binary'); process.exit(2); }

const servers = [];
function serve(model, system) {
  const args = ['serve', model, '--port', '0'];
  if (system) args.push('--system', system);
  const p = spawn(BIN, args, {cwd: ROOT, stdio: ['ignore', 'pipe', 'pipe']});
  servers.push(p);
  return new Promise((resolve, reject) => {
    let out = '';
    const timer = setTimeout(() => reject(new Error('server did not start: ' + out)), 30000);
    p.stdout.on('data', d => {
      out += d;
      const m = out.match(/(http:\/\/\S+)/);
      if (m) { clearTimeout(timer); resolve(m[1]); }
    });
    p.stderr.on('data', d => { out += d; });
    p.on('exit', c => reject(new Error(`server exited ${c}: ${out}`)));
  });
}

function sim(model, system, scn) {
  const args = ['sim', model, '--scenario', scn, '--json'];
  if (system) args.push('--system', system);
  let out;
  try { out = execFileSync(BIN, args, {cwd: ROOT}); } catch (e) { out = e.stdout; }
  return JSON.parse(out.toString());
}

// Open the page; wait until it is interactive and every chart has its final (ELK) layout.
async function open(page, url) {
  const t0 = Date.now();
  await page.goto(url);
  await page.waitForFunction(() => window.studio && window.studio.ready && window.studio.run && window.studio.laidOut, null, {timeout: 60000});
  return Date.now() - t0;
}

// Highlighted (active) state paths per instance, read from the drawn SVGs.
async function highlighted(page) {
  return page.evaluate(() => {
    const s = window.studio, out = {};
    s.model.instances.forEach((inst, k) => {
      const chart = s.model.charts[inst.chart];
      const svg = s.svgs[k];
      out[inst.name] = [...svg.querySelectorAll('g.st.active')].map(g => chart.states[+g.dataset.sid].path).sort();
    });
    return out;
  });
}

const sortActive = a => Object.fromEntries(Object.entries(a).map(([k, v]) => [k, [...v].sort()]));

async function ticks(page) { return page.evaluate(() => window.studio.run.ticks); }
async function waitTicks(page, n) {
  await page.waitForFunction(n => window.studio.run && window.studio.run.ticks === n, n, {timeout: 30000});
}

async function setHeld(page, name, value) {
  await page.evaluate(([name, value]) => window.studio.send({op: 'set', set: {[name]: value}}), [name, value]);
}

async function stepN(page, n) {
  const before = await ticks(page);
  await page.fill('#n', String(n));
  await page.click('#stepn');
  await waitTicks(page, before + n);
}

async function save(page, file) {
  const [dl] = await Promise.all([page.waitForEvent('download'), page.click('#save')]);
  await dl.saveAs(file);
  return fs.readFileSync(file, 'utf8');
}

// The page's records and highlighted states against `sim --json` of its own saved scenario.
async function checkAgainstSim(page, model, system, name) {
  const file = path.join(TMP, name);
  await save(page, file);
  const ref = sim(model, system, file);
  const recs = await page.evaluate(() => window.studio.records);
  assert.strictEqual(recs.length, ref.ticks.length, 'tick count');
  recs.forEach((r, k) => {
    for (const key of ['tick', 'active', 'vars', 'events']) assert.deepStrictEqual(r[key], ref.ticks[k][key], `tick ${k} ${key}`);
  });
  const last = ref.ticks[ref.ticks.length - 1];
  assert.deepStrictEqual(await highlighted(page), sortActive(last.active), 'highlighted states = sim --json');
  return ref;
}

// The layout bar: in every chart's final drawing no two state boxes overlap unless one
// holds the other, no two transition labels overlap, and no label overlaps a leaf state.
// Measured on the SVG the browser rendered (text boxes as the browser sizes them).
async function overlaps(page) {
  return page.evaluate(() => {
    const out = [], seen = new Set();
    const inter = (a, b) => a.x < b.x + b.w - 0.5 && b.x < a.x + a.w - 0.5 && a.y < b.y + b.h - 0.5 && b.y < a.y + a.h - 0.5;
    const holds = (p, q) => p.x <= q.x && p.y <= q.y && p.x + p.w >= q.x + q.w && p.y + p.h >= q.y + q.h;
    const box = b => ({x: b.x, y: b.y, w: b.width, h: b.height});
    studio.model.instances.forEach((inst, k) => {
      if (seen.has(inst.chart)) return;
      seen.add(inst.chart);
      const svg = studio.svgs[k], name = studio.model.charts[inst.chart].name;
      const states = [...svg.querySelectorAll('g.st > rect')].map(r => ({n: r.parentNode.querySelector('title').textContent, leaf: r.parentNode.classList.contains('leaf'), ...box(r.getBBox())}));
      const labels = [...svg.querySelectorAll('g.tr')].filter(g => g.querySelector(':scope > text')).map(g => {
        const ts = [...g.querySelectorAll(':scope > text')].map(t => t.getBBox());
        const x = Math.min(...ts.map(b => b.x)), y = Math.min(...ts.map(b => b.y));
        return {n: g.querySelector('text').textContent, x, y, w: Math.max(...ts.map(b => b.x + b.width)) - x, h: Math.max(...ts.map(b => b.y + b.height)) - y};
      });
      for (let i = 0; i < states.length; i++) for (let j = i + 1; j < states.length; j++) {
        const a = states[i], b = states[j];
        if (!holds(a, b) && !holds(b, a) && inter(a, b)) out.push(`${name}: states ${a.n} and ${b.n}`);
      }
      for (let i = 0; i < labels.length; i++) for (let j = i + 1; j < labels.length; j++) {
        if (inter(labels[i], labels[j])) out.push(`${name}: labels "${labels[i].n}" and "${labels[j].n}"`);
      }
      for (const l of labels) for (const st of states) if (st.leaf && inter(l, st)) out.push(`${name}: label "${l.n}" on state ${st.n}`);
    });
    return out;
  });
}

async function famClosedLoop(browser) {
  const model = 'examples/fam/fam_system.sc';
  const url = await serve(model);
  const page = await browser.newPage({viewport: {width: 1680, height: 1050}, acceptDownloads: true});
  const ms = await open(page, url);
  assert.deepStrictEqual(await overlaps(page), [], 'no overlapping boxes or labels (FAM closed loop)');
  console.log(`page load (fam_system.sc): ${ms} ms (layout ${Math.round(await page.evaluate(() => window.studio.layoutMs))} ms)`);
  await page.selectOption('#preset', 'closed');
  // The closed-loop preset shows the CCM and the faults only.
  const shown = await page.$$eval('.ctl', els => els.map(e => e.dataset.input));
  assert.ok(shown.includes('ctrl.ccm') && shown.includes('fam.stallNow') && !shown.includes('tie.low'), shown.join(','));
  await page.fill('.ctl[data-input="ctrl.ccm"] input[type=number]', '1000');
  await page.dispatchEvent('.ctl[data-input="ctrl.ccm"] input[type=number]', 'change');
  await page.waitForFunction(() => window.studio.held['ctrl.ccm'] === 1000);
  // The FAM runs from tick 13 on (its calibration move, by sim of `ctrl.ccm = 1000`): inject
  // a stall for one tick while it runs, at tick 17.
  await page.check('#cov');
  await stepN(page, 17);
  await page.click('.ctl[data-input="fam.stallNow"] button.pulse');
  await page.click('#step');
  await waitTicks(page, 18);
  const rec = await page.evaluate(() => window.studio.records[17]);
  assert.deepStrictEqual(rec.vars['fam.stallNow'], true, 'the pulse reached tick 17');
  assert.ok(rec.active.fam.includes('stallHandler.stallMode'), 'the FAM stalled: ' + rec.active.fam);
  assert.deepStrictEqual(await highlighted(page), sortActive(rec.active));
  await stepN(page, 2);
  await page.screenshot({path: path.join(SHOTS, 'fam_closed_loop.png')});
  await stepN(page, 31);
  const ref = await checkAgainstSim(page, model, null, 'fam.scn');
  // Step back: the chart shows tick 49 as sim has it; forward again: tick 50.
  await page.click('#back');
  await waitTicks(page, 50);
  assert.deepStrictEqual(await highlighted(page), sortActive(ref.ticks[49].active), 'after back');
  await page.click('#forward');
  await waitTicks(page, 51);
  assert.deepStrictEqual(await highlighted(page), sortActive(ref.ticks[50].active), 'after forward');
  await stepN(page, 60);
  await checkAgainstSim(page, model, null, 'fam2.scn');
  await page.click('.tab[data-tab="msc"]');
  await page.screenshot({path: path.join(SHOTS, 'sequence.png')});
  const msgs = await page.$$eval('#msc g.msg', g => g.length);
  assert.ok(msgs > 0, 'the sequence view shows messages between instances');
  await page.close();
}

async function counterexample(browser) {
  const model = 'examples/fam/fam_alone.sc', system = 'FamAloneSmall';
  const dir = path.join(TMP, 'cex');
  try {
    execFileSync(BIN, ['verify', model, '--system', system, '--property', 'fam_cof_with_notcalib', '--cex-dir', dir], {cwd: ROOT, stdio: 'ignore'});
  } catch (e) { assert.strictEqual(e.status, 1, 'verify: violated'); }
  const cex = path.join(dir, 'fam_cof_with_notcalib.scn');
  const ref = sim(model, system, cex);
  assert.strictEqual(ref.result.status, 'violated');
  const url = await serve(model, system);
  const page = await browser.newPage({viewport: {width: 1680, height: 1000}, acceptDownloads: true});
  await open(page, url);
  await page.selectOption('#preset', 'fam');
  await page.setInputFiles('#load', cex);
  await waitTicks(page, ref.ticks.length);
  const stop = await page.evaluate(() => window.studio.run.stop);
  assert.strictEqual(stop.tick, ref.result.tick, 'violating tick');
  assert.strictEqual(stop.message, ref.result.message);
  const status = await page.textContent('#status');
  assert.ok(status.includes(`violated at tick ${ref.result.tick}`), status);
  const marked = await page.$eval('#messages .msg', d => +d.dataset.t);
  assert.strictEqual(marked, ref.result.tick, 'the violating tick is marked');
  assert.deepStrictEqual(await highlighted(page), sortActive(ref.ticks[ref.ticks.length - 1].active));
  await page.check('#cov');
  await page.screenshot({path: path.join(SHOTS, 'counterexample.png')});
  // Branch here: back one tick and continue interactively.
  await page.click('#back');
  await waitTicks(page, ref.ticks.length - 1);
  // fam_alone.sc assumes no new major fault while one is set: choose no fault, then step.
  await page.selectOption('.ctl[data-input="env.fault"] select', 'NONE');
  await page.waitForFunction(() => window.studio.held['env.fault'] === 'NONE');
  await page.click('#step');
  await waitTicks(page, ref.ticks.length);
  await checkAgainstSim(page, model, system, 'branch.scn');
  await page.close();
}

// Verify from the page (the verify library, verdicts streamed as decided), then replay a
// result. The model, by hand: tick 0 enters A, each later tick with `go` adds 1 to n, so the
// shortest run to n = 3 has 4 ticks and violates `small` at tick 3.
async function verifyInPage(browser) {
  const model = path.join(TMP, 'count.sc');
  fs.writeFileSync(model, 'chart Count {\n  input go: bool = false;\n  output n: int[0..9] = 0;\n  initial A;\n' +
    '  state A { during { if go { n = min(9, n + 1); } } on [n == 9] -> B; }\n  state B { }\n  invariant small: n < 3;\n  reachable full: in(B);\n}\n');
  const url = await serve(model);
  const page = await browser.newPage({viewport: {width: 1500, height: 900}, acceptDownloads: true});
  await open(page, url);
  await page.selectOption('#engine', 'explicit');
  await page.click('#verify');
  await page.waitForFunction(() => /done/.test(document.querySelector('#vstate').textContent), null, {timeout: 120000});
  const v = await page.evaluate(() => window.studio.verdicts);
  assert.strictEqual(v.small.verdict, 'violated');
  assert.strictEqual(v.small.depth, 4);
  // `full`: n = 9 after tick 9, B entered in tick 10: a witness of 11 ticks.
  assert.strictEqual(v.full.verdict, 'reachable');
  assert.strictEqual(v.full.depth, 11);
  await page.click('#rlist .res[data-name="small"]');
  await page.waitForFunction(() => window.studio.run.stop && window.studio.run.ticks === 4);
  assert.strictEqual(await page.evaluate(() => window.studio.run.stop.tick), 3);
  await page.check('#cov');
  await page.screenshot({path: path.join(SHOTS, 'verify.png')});
  // The same verdicts from CEGAR (IC3 on localization abstractions), with counterexample and
  // witness of the same shortest lengths, each row decided by `cegar`.
  await page.selectOption('#engine', 'cegar');
  await page.click('#verify');
  await page.waitForFunction(() => {
    const v = window.studio.verdicts;
    return v.small && v.full && /done/.test(document.querySelector('#vstate').textContent);
  }, null, {timeout: 120000});
  const c = await page.evaluate(() => window.studio.verdicts);
  assert.deepStrictEqual([c.small.verdict, c.small.depth, c.small.engine], ['violated', 4, 'cegar']);
  assert.deepStrictEqual([c.full.verdict, c.full.depth, c.full.engine], ['reachable', 11, 'cegar']);
  // The file changes under the page: a broken model shows its diagnostics (line 5: an unknown
  // state), the fixed one (n counts by 2 now) re-applies the replayed ticks: with `go` in
  // ticks 1.. n is 0, 2, 4 after ticks 0..2, so `small` (n < 3) is violated at tick 2 now and
  // the run stops there, as sim stops.
  const src = fs.readFileSync(model, 'utf8');
  fs.writeFileSync(model, src.replace('-> B;', '-> Nowhere;'));
  await page.waitForFunction(() => !document.querySelector('#diag').hidden, null, {timeout: 30000});
  const diag = await page.textContent('#diag');
  assert.ok(diag.includes(':5:') && diag.includes('Nowhere'), diag);
  fs.writeFileSync(model, src.replace('n + 1', 'n + 2'));
  await page.waitForFunction(() => document.querySelector('#diag').hidden && window.studio.model && window.studio.run && window.studio.records.length > 0, null, {timeout: 30000});
  const after = await page.evaluate(() => ({n: window.studio.records.map(r => r.vars && r.vars['Count.n']), stop: window.studio.run.stop}));
  assert.deepStrictEqual(after.n, [0, 2, 4], JSON.stringify(after));
  assert.strictEqual(after.stop.message, 'property `small` violated at tick 2');
  await page.close();
}

// A lasso from the page: verify a temporal property, replay its counterexample (prefix and
// loop, the loop's start marked), step past the end around the loop. tests/verify/temporal.sc
// system Free (by hand in its comments): `reaches3: F c.n == 3` is violated by a lasso on
// which n never reaches 3. Independent checks: sim --json of the same scenario gives the same
// ticks and message, and after the end the run repeats the loop (the lasso's definition:
// the state after tick end-1+j is the state after tick start-1+j).
async function lassoInPage(browser) {
  const model = 'tests/verify/temporal.sc', system = 'Free';
  const url = await serve(model, system);
  const page = await browser.newPage({viewport: {width: 1500, height: 900}, acceptDownloads: true});
  await open(page, url);
  await page.selectOption('#engine', 'explicit');
  await page.click('#verify');
  await page.waitForFunction(() => /done/.test(document.querySelector('#vstate').textContent), null, {timeout: 120000});
  const v = await page.evaluate(() => window.studio.verdicts.reaches3);
  assert.strictEqual(v.verdict, 'violated');
  assert.ok(/\nloop:\n/.test(v.scenario), v.scenario);
  const file = path.join(TMP, 'lasso.scn');
  fs.writeFileSync(file, v.scenario);
  const ref = sim(model, system, file);
  assert.strictEqual(ref.result.status, 'violated');
  await page.click('#rlist .res[data-name="reaches3"]');
  await page.waitForFunction(n => window.studio.run.lasso && window.studio.run.ticks === n, ref.ticks.length);
  const lasso = await page.evaluate(() => window.studio.run.lasso);
  assert.strictEqual(lasso.end, ref.ticks.length);
  // The ticks written before the `loop:` line (a line `… * N` stands for N ticks).
  const before = v.scenario.split('\nloop:\n')[0].split('\n').map(l => l.replace(/#.*/, '').trim()).filter(l => l);
  const k = before.reduce((a, l) => a + (/\*\s*(\d+)$/.test(l) ? +l.match(/\*\s*(\d+)$/)[1] : 1), 0);
  assert.strictEqual(lasso.start, k, 'loop start: ' + v.scenario);
  assert.strictEqual(lasso.violated.message, ref.result.message);
  const recs = await page.evaluate(() => window.studio.records);
  recs.forEach((r, k) => { for (const key of ['active', 'vars', 'events']) assert.deepStrictEqual(r[key], ref.ticks[k][key], `tick ${k} ${key}`); });
  assert.strictEqual(await page.$eval('#messages .lassostart', d => +d.dataset.t), lasso.start, 'the loop start is marked');
  assert.ok((await page.textContent('#status')).includes(`loop ${lasso.start}–${lasso.end - 1}`));
  await page.screenshot({path: path.join(SHOTS, 'lasso.png')});
  // Around the loop, twice.
  const period = lasso.end - lasso.start;
  await stepN(page, 2 * period);
  const all = await page.evaluate(() => window.studio.records);
  for (let j = 0; j < 2 * period; j++) {
    const a = all[lasso.end + j], b = all[lasso.start + (j % period)];
    assert.deepStrictEqual([a.active, a.vars], [b.active, b.vars], `tick ${lasso.end + j} repeats tick ${lasso.start + (j % period)}`);
  }
  await checkAgainstSim(page, model, system, 'lasso-around.scn');
  await page.close();
}

async function fam5(browser) {
  const model = 'examples/fam/fam_system5.sc';
  const url = await serve(model);
  const page = await browser.newPage({viewport: {width: 1920, height: 1200}, acceptDownloads: true});
  const ms = await open(page, url);
  console.log(`page load (fam_system5.sc), first visit: ${ms} ms (layout ${Math.round(await page.evaluate(() => window.studio.layoutMs))} ms)`);
  assert.deepStrictEqual(await overlaps(page), [], 'no overlapping boxes or labels (Fam, Controller, MasterBus5, …)');
  const again = await open(page, url);
  console.log(`page load (fam_system5.sc), reload with the layout cached: ${again} ms`);
  await page.check('#random');
  await page.fill('#seed', '5');
  await page.fill('#n', '80');
  await page.click('#stepn');
  await page.waitForFunction(() => window.studio.run.ticks > 0);
  await page.waitForTimeout(300);
  await checkAgainstSim(page, model, null, 'fam5.scn');
  await page.screenshot({path: path.join(SHOTS, 'fam_system5.png')});
  await page.close();
  return ms;
}

// Time in the user's units: tests/time/station.sc (by hand in its comments) has ticks of
// 1.25 s and violates `never_at_end` in tick 95, at 118.75 s; the run has 96 ticks (120.00 s).
// The page shows the server's times: in the status, the message and the cursor's heading.
async function timeUnits(browser) {
  const model = 'tests/time/station.sc';
  const url = await serve(model);
  const page = await browser.newPage({viewport: {width: 1200, height: 800}});
  await open(page, url);
  await page.setInputFiles('#load', path.join(ROOT, 'tests/time/station.scn'));
  await waitTicks(page, 96);
  const status = await page.textContent('#status');
  assert.ok(status.includes('120.00 s'), status);
  assert.ok(status.includes('violated at tick 95 (118.75 s)'), status);
  assert.strictEqual(await page.textContent('#cursor-tick'), '95 (118.75 s)');
  await page.close();
}

async function linearDrive(browser) {
  const model = 'examples/linear_drive/linear_drive.sc';
  const url = await serve(model);
  const page = await browser.newPage({viewport: {width: 1500, height: 950}, acceptDownloads: true});
  await open(page, url);
  assert.deepStrictEqual(await overlaps(page), [], 'no overlapping boxes or labels (linear drive)');
  await page.check('#random');
  await page.fill('#n', '25');
  await page.click('#stepn');
  await page.waitForFunction(() => window.studio.run.ticks > 0);
  await page.waitForTimeout(300);
  const ref = await checkAgainstSim(page, model, null, 'linear.scn');
  await page.screenshot({path: path.join(SHOTS, 'linear_drive.png')});
  // A browser reload resumes the session: the same ticks, as sim has them.
  await page.reload();
  await page.waitForFunction(n => window.studio && window.studio.ready && window.studio.run && window.studio.run.ticks === n && window.studio.laidOut, ref.ticks.length, {timeout: 60000});
  await checkAgainstSim(page, model, null, 'linear-reloaded.scn');
  await page.close();
}

(async () => {
  fs.mkdirSync(SHOTS, {recursive: true});
  const browser = await chromium.launch({executablePath: CHROMIUM, args: ['--no-sandbox', '--disable-gpu']});
  let failed = false;
  const only = process.env.STUDIO_E2E_ONLY;
  for (const [name, t] of [['fam closed loop', famClosedLoop], ['counterexample', counterexample], ['verify in the page', verifyInPage], ['lasso', lassoInPage], ['fam_system5', fam5], ['time units', timeUnits], ['linear drive', linearDrive]]) {
    if (only && !name.includes(only)) continue;
    try { await t(browser); console.log(`ok   ${name}`); } catch (e) { failed = true; console.log(`FAIL ${name}: ${e.stack || e}`); }
  }
  await browser.close();
  for (const s of servers) s.kill();
  fs.rmSync(TMP, {recursive: true, force: true});
  process.exit(failed ? 1 : 0);
})();
