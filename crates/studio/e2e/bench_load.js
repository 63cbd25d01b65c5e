// Page-load benchmark of `statecheck serve` in chromium (a script that prints figures, not a
// test). Run: STATECHECK_BIN=path/to/statecheck node bench_load.js [MODEL] [N]
// For N loads of the page it reads the page's own performance marks:
//   interactive  navigation start → every chart drawn and the controls live (`studio.ready`)
//   laid out     navigation start → every chart in its final ELK layout (`studio.laidOut`)
// "cold" loads use a fresh browser context each time (empty storage and cache) against a fresh
// server; "warm" loads reload the same page (layouts in the browser's storage).
'use strict';

const {chromium} = require('playwright-core');
const {spawn} = require('child_process');
const path = require('path');

const ROOT = path.resolve(__dirname, '../../..');
const BIN = process.env.STATECHECK_BIN;
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
const MODEL = process.argv[2] || 'examples/fam/fam_system5.sc';
const N = Math.max(1, Math.min(50, +process.argv[3] || 7));
if (!BIN) { console.error('set STATECHECK_BIN to the statecheck binary'); process.exit(2); }

function serve() {
  const p = spawn(BIN, ['serve', MODEL, '--port', '0'], {cwd: ROOT, stdio: ['ignore', 'pipe', 'pipe']});
  return new Promise((resolve, reject) => {
    let out = '';
    const timer = setTimeout(() => reject(new Error('server did not start: ' + out)), 30000);
    p.stdout.on('data', d => {
      out += d;
      const m = out.match(/(http:\/\/\S+)/);
      if (m) { clearTimeout(timer); resolve({url: m[1], proc: p}); }
    });
    p.stderr.on('data', d => { out += d; });
  });
}

async function marks(page) {
  // (Pages before the marks existed: the time the page was first seen ready.)
  const seen = await page.waitForFunction(() => window.studio && window.studio.ready && window.studio.run && window.studio.laidOut !== false && performance.now(), null, {timeout: 60000, polling: 'raf'});
  const fallback = await seen.jsonValue();
  return page.evaluate(fallback => {
    const at = name => { const m = performance.getEntriesByName(name); return m.length ? m[m.length - 1].startTime : fallback; };
    const i = at('studio-interactive');
    return {interactive: i, laidOut: Math.max(i, at('studio-laid-out')),
      connect: at('studio-connect'), model: at('studio-model'), charts: at('studio-charts')};
  }, fallback);
}

const median = a => { const s = [...a].sort((x, y) => x - y); return s[Math.floor(s.length / 2)]; };
const fmt = a => `median ${Math.round(median(a))} ms, min ${Math.round(Math.min(...a))}, max ${Math.round(Math.max(...a))}`;

(async () => {
  const browser = await chromium.launch({executablePath: CHROMIUM, args: ['--no-sandbox', '--disable-gpu']});
  const cold = {interactive: [], laidOut: []}, warm = {interactive: [], laidOut: []};
  for (let i = 0; i < N; i++) {
    const {url, proc} = await serve();
    const ctx = await browser.newContext({viewport: {width: 1920, height: 1200}});
    const page = await ctx.newPage();
    await page.goto(url);
    const c = await marks(page);
    cold.interactive.push(c.interactive); cold.laidOut.push(c.laidOut);
    for (const k of ['connect', 'model', 'charts']) (cold[k] = cold[k] || []).push(c[k]);
    await page.reload();
    const w = await marks(page);
    warm.interactive.push(w.interactive); warm.laidOut.push(w.laidOut);
    await ctx.close();
    proc.kill();
  }
  await browser.close();
  console.log(`page load of ${MODEL}, ${N} loads each`);
  console.log(`cold (fresh browser context): interactive ${fmt(cold.interactive)}; laid out ${fmt(cold.laidOut)}`);
  console.log(`cold, on the way (medians): scripts run at ${Math.round(median(cold.connect))} ms, model received ${Math.round(median(cold.model))} ms, charts built ${Math.round(median(cold.charts))} ms`);
  console.log(`warm (reload):                interactive ${fmt(warm.interactive)}; laid out ${fmt(warm.laidOut)}`);
})().catch(e => { console.error(e); process.exit(1); });
