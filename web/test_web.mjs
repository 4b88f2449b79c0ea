// test_web.mjs — the page in a real browser (Debian's chromium, driven by web/cdp.mjs):
//   node test_web.mjs SITE_DIR RELCOL_SIM OUT_DIR            the checks (web/test.sh)
//   node test_web.mjs SITE_DIR BENCH_ENGINE OUT_DIR --bench  frame rate and engine speed
// The page is served from SITE_DIR by a static server in this process (loopback only).
// Checks: the page loads with no console error; the rack runs 5 s of page time with
// energy error < 1e-12; the c slider at 1.5 x the fastest speed gives every ball the
// semi-axes r/gamma (along v) and r (across), gamma from its momentum at that c; the
// split view's c = inf side equals `relcol-sim --builtin rack` at t = 4 to round-off; a
// dropped scenario file runs and a bad one is refused with the reader's message; a
// screenshot (OUT_DIR/web-screenshot.png) is not blank; the speed histogram has ticked,
// labelled axes, the balls' colours a key (the rack's set, the gas's gamma - 1 scale), and
// the time shows in each table's caption, not on the table under the balls; the field
// (fieldChecks): the g slider, the profile, the field's energy, bad g refused.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { chromium } from './cdp.mjs';

const [site, tool, out] = process.argv.slice(2, 5);
const clockTicks = Number(execFileSync('getconf', ['CLK_TCK'], { encoding: 'utf8' })) || 100;
const benchMode = process.argv.includes('--bench');
if (!site || !tool || !out) {
  console.error('usage: node test_web.mjs SITE_DIR RELCOL_SIM|BENCH_ENGINE OUT_DIR [--bench]');
  process.exit(2);
}
fs.mkdirSync(out, { recursive: true });

let failures = 0, checks = 0;
function check(ok, what, detail) {
  checks++;
  if (!ok) failures++;
  console.log((ok ? 'ok   ' : 'FAIL ') + what + (detail !== undefined ? ': ' + detail : ''));
}

// ---- a static server for the site -----------------------------------------------------
const types = { '.html': 'text/html; charset=utf-8', '.js': 'text/javascript',
                '.css': 'text/css', '.wasm': 'application/wasm', '.json': 'application/json' };
const server = http.createServer((req, res) => {
  const rel = decodeURIComponent(new URL(req.url, 'http://x').pathname);
  const file = path.join(site, rel === '/' ? 'index.html' : rel);
  if (!file.startsWith(path.resolve(site)) || !fs.existsSync(file) || fs.statSync(file).isDirectory()) {
    res.writeHead(404);
    res.end();
    return;
  }
  res.writeHead(200, { 'Content-Type': types[path.extname(file)] || 'application/octet-stream' });
  fs.createReadStream(file).pipe(res);
});
await new Promise((r) => server.listen(0, '127.0.0.1', r));
const url = 'http://127.0.0.1:' + server.address().port + '/';

// ---- the browser (flags: .library machines note; a fresh profile each run) --------------
const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'relcol-chromium-'));
const context = await chromium.launchPersistentContext(profile, {
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  headless: true,
  viewport: { width: 1280, height: 860 },
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
         '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});
const page = context.pages()[0] || await context.newPage();
const consoleErrors = [];
page.on('console', (m) => { if (m.type() === 'error') consoleErrors.push(m.text()); });
page.on('pageerror', (e) => consoleErrors.push('page error: ' + e.message));
page.on('requestfailed', (r) => consoleErrors.push('request failed: ' + r.url()));

const state = () => page.evaluate(() => window.relcol.state());
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

async function waitFor(fn, ms, what) {
  const t0 = Date.now();
  for (;;) {
    const v = await fn();
    if (v) return v;
    if (Date.now() - t0 > ms) throw new Error('timed out waiting for ' + what);
    await sleep(50);
  }
}

// a PNG's pixels read back through the browser: distinct colours and the share of pixels
// unlike the top-left one (a blank or single-colour image has 1 colour and share 0)
async function pngStats(file) {
  const b64 = fs.readFileSync(file).toString('base64');
  return page.evaluate(async (data) => {
    const img = new Image();
    img.src = 'data:image/png;base64,' + data;
    await img.decode();
    const cv = document.createElement('canvas');
    cv.width = img.width;
    cv.height = img.height;
    const ctx = cv.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const px = ctx.getImageData(0, 0, cv.width, cv.height).data;
    const seen = new Set();
    let differ = 0;
    for (let i = 0; i < px.length; i += 4) {
      const key = (px[i] << 16) | (px[i + 1] << 8) | px[i + 2];
      if (seen.size < 5000) seen.add(key);
      if (px[i] !== px[0] || px[i + 1] !== px[1] || px[i + 2] !== px[2]) differ++;
    }
    return { width: cv.width, height: cv.height, colours: seen.size, share: differ / (px.length / 4) };
  }, b64);
}

function csvRows(file) {
  const lines = fs.readFileSync(file, 'utf8').split('\n').filter((l) => l && !l.startsWith('#'));
  const head = lines[0].split(',');
  return lines.slice(1).map((l) => {
    const v = l.split(',');
    const o = {};
    head.forEach((h, i) => { o[h] = Number(v[i]); });
    return o;
  });
}

async function setSlider(id, value) {
  await page.evaluate(([id, v]) => {
    const el = document.getElementById(id);
    el.value = String(v);
    el.dispatchEvent(new Event('input', { bubbles: true }));
    el.dispatchEvent(new Event('change', { bubbles: true }));
  }, [id, value]);
}

try {
  await page.goto(url);
  await waitFor(() => page.evaluate(() => window.relcol && window.relcol.ready), 30000, 'the page');
  if (benchMode) {
    await bench();
  } else {
    await checksRun();
  }
} catch (e) {
  check(false, 'the run', e.stack || String(e));
} finally {
  await context.close();
  server.close();
  fs.rmSync(profile, { recursive: true, force: true });
}
console.log(checks + ' checks, ' + failures + ' failed');
process.exit(failures === 0 && checks > 0 ? 0 : 1);

async function checksRun() {
  let s = await state();
  check(s.scenario === 'rack' && s.main.balls.length === 16, 'the rack loads', s.main.balls.length + ' balls');
  check(consoleErrors.length === 0, 'no console error on load', consoleErrors.join(' | '));

  // 5 s of page time: play at the rack's own speed of time (1 time unit a second)
  check(s.speed === 1, 'rack plays in real time', s.speed);
  await page.click('#play');
  await waitFor(async () => (await state()).t >= 5, 20000, '5 s of page time');
  await page.click('#play');
  s = await state();
  const d = s.main.diag;
  check(d.eerr < 1e-12, 'energy error after 5 s < 1e-12', d.eerr.toExponential(3) + ' at t = ' + s.t.toFixed(3) + ', ' + d.coll + ' collisions');
  check(d.perr < 1e-12, 'momentum (balls + walls) error < 1e-12', d.perr.toExponential(3));
  check(d.coll > 20, 'the break happened', d.coll + ' collisions');
  check(s.frames > 100, 'frames drawn', s.frames + ' frames, ' + s.fps.toFixed(1) + ' fps');
  // the figure explains itself (issue 38): the histogram's axes, the colour key, the time
  const ax = s.histAxes;
  check(ax && ax.xTicks.length >= 3 && ax.yTicks.length >= 2 && ax.xTicks[0] === 0 &&
        ax.xTicks[ax.xTicks.length - 1] <= ax.vtop * (1 + 1e-12) && /speed/.test(ax.xLabel) &&
        /^share per unit/.test(ax.yLabel) &&
        ax.yTop >= Math.max(...s.hist.slice(0, 96).filter(isFinite)) * (ax.xUnit === 'c' ? s.main.diag.c : 1),
        'the speed histogram has ticked, labelled axes over its bars and curves',
        ax ? ax.xLabel + ': ' + ax.xTicks.map((t) => t.toPrecision(3)).join(' ') + ' | ' + ax.yLabel + ': ' +
             ax.yTicks.map((t) => t.toPrecision(3)).join(' ') : 'none');
  check(/billiard set by ball number/.test(s.colourKey) && !s.colourKeyScale, 'the rack\'s colours have a key', s.colourKey);
  const cap = await page.textContent('#cap-main');
  check(cap.includes('t = ' + s.main.diag.time.toFixed(3)), 'the time shows in the caption', cap);
  const verdict = await page.textContent('#r-verdict');
  check(verdict.startsWith('defined'), 'the page shows the model verdict (classical rack: defined)', verdict);

  // the c slider at 1.5 x the fastest ball (its speed at c = inf, |p|/m: with momenta
  // kept every speed falls below it): contracted semi-axes from the page's state
  const vfast = Math.max(...s.main.balls.map((b) => b.speed));
  check(Math.abs(s.cMin / (1.01 * vfast) - 1) < 1e-12, 'the slider reaches down to just above the fastest ball', 'floor ' + s.cMin);
  const cWant = 1.5 * vfast;
  const pos = await page.evaluate((c) => window.relcol.sliderFor(c), cWant);
  await setSlider('c', pos);
  s = await state();
  const c = s.main.diag.c;
  check(Math.abs(c / cWant - 1) < 1e-12, 'slider gives c = 1.5 x fastest', 'c = ' + c + ', wanted ' + cWant);
  let worstA = 0, worstB = 0, gmax = 1;
  for (const b of s.main.balls) {
    const u = Math.hypot(b.px, b.py) / (b.m * c);
    const gamma = Math.sqrt(1 + u * u);
    gmax = Math.max(gmax, gamma);
    // r/gamma by two roundings of the library's support function: relative 1e-14
    worstA = Math.max(worstA, Math.abs(b.a - b.r / gamma) / b.r);
    worstB = Math.max(worstB, Math.abs(b.b - b.r) / b.r);
  }
  check(worstA < 1e-14 && worstB === 0, 'semi-axes r/gamma along v and r across',
        'largest |a - r/gamma|/r = ' + worstA.toExponential(2) + ', gamma up to ' + gmax.toFixed(6));
  // the fastest ball: p/(m c) = 1/1.5, gamma = sqrt(1 + 1/1.5^2)
  check(Math.abs(gmax - Math.sqrt(1 + 1 / 2.25)) < 1e-12, 'the fastest ball contracted by gamma = sqrt(1 + 1/1.5^2)', 'gamma ' + gmax.toFixed(12));
  check(Math.max(...s.main.balls.map((b) => b.speed)) < c, 'every ball below c');
  const shot = path.join(out, 'web-screenshot.png');
  // hover a ball: its proper time shows
  await page.click('#play');
  await sleep(700);
  await page.click('#play');
  s = await state();
  const box = await page.locator('#canvas-main').boundingBox();
  const b0 = s.main.balls[0];
  await page.mouse.move(box.x + b0.x / s.main.diag.boxx * box.width, box.y + (1 - b0.y / s.main.diag.boxy) * box.height);
  const tip = await page.locator('#tip').innerText();
  check(/proper time/.test(tip) && tip.includes(b0.tau.toFixed(6)), 'proper time on hover', tip.replace(/\n/g, '; '));
  await page.screenshot({ path: shot });
  const st = await pngStats(shot);
  check(st.colours > 20 && st.share > 0.2, 'screenshot not blank', shot + ': ' + st.width + 'x' + st.height + ', ' + st.colours + ' colours, ' + (100 * st.share).toFixed(1) + ' % unlike the corner');

  // split view: c = inf beside the chosen c, both from the start; the c = inf side against
  // the native relcol-sim at t = 4 (the engine's run in pieces has the bits of one go)
  await page.click('#reset');
  await page.check('#split');
  const T = 4;
  await page.evaluate((t) => window.relcol.advanceTo(t), T);
  s = await state();
  check(s.split && s.ref && s.ref.diag.c === 'inf' && s.main.diag.c !== 'inf', 'split view: c = inf beside the chosen c', 'main c = ' + s.main.diag.c);
  const work = fs.mkdtempSync(path.join(os.tmpdir(), 'relcol-web-sim-'));
  execFileSync(tool, ['--builtin', 'rack', '--t-end', String(T), '--out', path.join(work, 'rack'), '--no-plots'], { stdio: 'ignore' });
  // (the snapshot whose time is T: the built-in's snapshots come every 1 up to its t_end)
  const snapDir = path.join(work, 'rack', 'snapshots');
  const snap = fs.readdirSync(snapDir).map((f) => path.join(snapDir, f))
    .find((f) => csvRows(f)[0].t === T);
  const rows = snap ? csvRows(snap) : [];
  fs.rmSync(work, { recursive: true, force: true });
  let dx = 0, dp = 0, pscale = 0;
  for (const r of rows) pscale = Math.max(pscale, Math.hypot(r.px, r.py));
  rows.forEach((r, i) => {
    const b = s.ref.balls[i];
    dx = Math.max(dx, Math.abs(b.x - r.x), Math.abs(b.y - r.y));
    dp = Math.max(dp, Math.abs(b.px - r.px), Math.abs(b.py - r.py));
  });
  // round-off: the CSV's %.17g reads back exactly, so only the two builds' arithmetic could
  // differ; 1e-12 of the table (2.54) and of the largest momentum
  check(rows.length === 16 && rows[0].t === T && dx <= 1e-12 * 2.54 && dp <= 1e-12 * pscale,
        'split view c = inf side equals relcol-sim --builtin rack at t = 4',
        'max |dx| = ' + dx.toExponential(2) + ', max |dp| = ' + dp.toExponential(2) + ' (of ' + pscale.toExponential(3) + ')');
  const capRef = await page.textContent('#cap-ref');
  check(capRef.includes('t = ' + s.ref.diag.time.toFixed(3)), 'the c = inf side shows its time', capRef);
  await page.screenshot({ path: path.join(out, 'web-split.png') });

  // a dropped scenario file runs (the same reader as relcol-sim); a bad one is refused
  await page.uncheck('#split');
  const good = JSON.stringify({ relcol: 1, dim: 2, box: [4, 2], c: 3, restitution: { ball: 1, wall: 1 },
    contact_frame: 'table', t_end: 10,
    balls: [{ x: [1, 1], v: [2, 0.1], r: 0.2 }, { x: [3, 1], v: [-1, 0], r: 0.2 }, { x: [2, 1.6], v: [0, -1.5], r: 0.1 }] });
  await page.setInputFiles('#file', { name: 'three.json', mimeType: 'application/json', buffer: Buffer.from(good) });
  await waitFor(async () => (await state()).scenario === 'three.json', 5000, 'the dropped file');
  await page.evaluate(() => window.relcol.advanceTo(5));
  s = await state();
  check(s.main.balls.length === 3 && s.main.diag.c === 3 && s.main.diag.coll > 0 && s.main.diag.eerr < 1e-12,
        'a scenario file runs', s.main.diag.coll + ' collisions, energy error ' + s.main.diag.eerr.toExponential(2));
  const bad = good.replace('"r":0.1', '"r":-1');
  await page.setInputFiles('#file', { name: 'bad.json', mimeType: 'application/json', buffer: Buffer.from(bad) });
  // (the status said "ready: three.json (3 balls)" before: wait for the refusal itself)
  await waitFor(async () => /bad\.json/.test(await page.locator('#status').innerText()), 10000, 'the refusal');
  const msg = await page.locator('#status').innerText();
  s = await state();
  check(/balls\[2\]\.r/.test(msg) && s.scenario === 'three.json', 'a bad file is refused by the reader', msg);

  // the tables by name: every frame and law the library lists is offered
  const frames = await page.locator('#frame option').allInnerTexts();
  const laws = await page.locator('#law option').allInnerTexts();
  check(frames.length >= 3 && frames.some((f) => f.startsWith('zmf')) && laws.length >= 2, 'frames and laws from the library', frames.join(', ') + ' | ' + laws.join(', '));
  // the rules for simultaneous contacts by name, and the run going on under another one
  const rules = await page.locator('#groups option').allInnerTexts();
  check(rules.join(',') === 'simultaneous,sequential,drop', 'group rules from the library', rules.join(', '));
  await page.selectOption('#groups', { label: 'sequential' });
  await waitFor(async () => (await state()).main.diag.groups === 1, 5000, 'the sequential rule').catch(() => {});
  s = await state();
  check(s.main.diag.groups === 1 && !s.error, 'the sequential rule applied', 'groups ' + s.main.diag.groups + (s.error ? ', ' + s.error : ''));

  // the gas: its colours keyed by gamma - 1 (the key drawn with the balls' own colours), the
  // histogram's speeds in units of c up to c
  await page.selectOption('#scenario', 'gas');
  await waitFor(async () => (await state()).scenario === 'gas', 5000, 'the gas');
  await page.evaluate(() => window.relcol.advanceTo(2));
  s = await state();
  const ticks = await page.locator('#colour-key-ticks span').allInnerTexts();
  check(/γ − 1 \(log scale\)/.test(s.colourKey) && s.colourKeyScale && ticks.length === 5 && ticks[4] === '1',
        'the gas\'s colours have a key (gamma - 1, log scale)', s.colourKey + ' [' + ticks.join(' ') + ']');
  const gax = s.histAxes;
  check(gax && gax.xUnit === 'c' && Math.abs(gax.vtop / s.main.diag.c - 1) < 1e-12 && /units of c/.test(gax.xLabel),
        'the gas\'s histogram: speeds in units of c, 0 to c', gax ? gax.xLabel + ', top ' + gax.vtop : 'none');
  await page.screenshot({ path: path.join(out, 'web-gas-key.png') });
  await fieldChecks();
  check(consoleErrors.length === 0, 'no console error in the whole run', consoleErrors.join(' | '));
}

// The field (issue 41 item 4): the g slider and the coupling beside the c slider; switched
// on in the gas, the floor's density grows over the ceiling's as the gas settles, the
// energy read-out (the field's conserved H minus what contacts booked) stays at round-off,
// and a bad g is refused with a visible message while the run goes on as it was.
async function fieldChecks() {
  const dom = await page.evaluate(() => {
    const g = document.getElementById('g'), c = document.getElementById('c');
    return { range: g && g.type === 'range', typed: !!document.getElementById('g-value'),
             beside: !!g && g.closest('fieldset') === c.closest('fieldset'),
             couplings: Array.from(document.querySelectorAll('#coupling option')).map((o) => o.textContent) };
  });
  check(dom.range && dom.typed && dom.beside && dom.couplings.join(',') === 'newtonian,equivalence',
        'the g slider, a typed g and the coupling beside the c slider', JSON.stringify(dom));
  // the gas afresh (its contracted shapes may come closer than two rest radii, which the
  // field's uncontracted spheres refuse), in the sphere frame the field takes
  await page.click('#reset');
  await page.selectOption('#frame', { label: 'sphere (spheres)' });
  let s = await state();
  check(!s.error && s.main.diag.time === 0, 'the gas reset in the sphere frame', s.error || '');
  const relax = async (span, steps) => {
    const t0 = (await state()).t;
    for (let k = 1; k <= steps; k++) await page.evaluate((t) => window.relcol.advanceTo(t), t0 + span * k / steps);
    return state();
  };
  // the gas (c = 1) without a field: nearly uniform along y
  s = await relax(200, 10);
  const p0 = s.profile;
  // (centres lie in [r, H - r]: the end slabs hold less; the inner ones 1/(H - 2r) each)
  check(p0 && p0.g === 0 && p0.density.length === p0.bins &&
        p0.theoryDensity.slice(1, -1).every((x) => Math.abs(x * p0.height - 1) < 0.05),
        'no field: the profile\'s theory is uniform', p0 ? 'floor ' + p0.density[0].toFixed(5) + ', top ' + p0.density[p0.bins - 1].toFixed(5) : 'none');
  const ratio0 = p0.density[0] / p0.density[p0.bins - 1];
  // the slider's top: m g H = 5 kT (newtonian, the gas's c = 1)
  await page.selectOption('#coupling', { label: 'newtonian' });
  await setSlider('g', 1000);
  s = await state();
  const frameName = (await page.locator('#frame option').allInnerTexts())[s.main.diag.frame];
  check(s.field.g === s.field.gMax && s.main.diag.g === s.field.g && s.field.coupling === 'newtonian' &&
        /^sphere/.test(frameName) && !s.error, 'the g slider switches the field on (contact frame sphere)',
        'g ' + s.field.g + ' (top ' + s.field.gMax + '), frame ' + frameName + (s.error ? ', ' + s.error : '') +
        '; status: ' + (await page.locator('#status').innerText()));
  // (the fall takes sqrt(2 H/g) ~ 150 time units; 3000 is some 20 falls and 10^5 collisions)
  s = await relax(3000, 30);
  const p1 = s.profile, nb = p1.bins;
  check(p1.g === s.field.g && p1.density[0] > 3 * p1.density[nb - 1] && p1.density[0] / p1.density[nb - 1] > 3 * ratio0 &&
        p1.theoryDensity[0] > 10 * p1.theoryDensity[nb - 1],
        'switching g on changes the profile: the floor\'s density exceeds the top\'s',
        'floor/top ' + (p1.density[0] / p1.density[nb - 1]).toFixed(2) + ' (no field ' + ratio0.toFixed(2) +
        '; dilute theory ' + (p1.theoryDensity[0] / p1.theoryDensity[nb - 1]).toFixed(1) + '), ' + s.main.diag.coll + ' collisions');
  // 1e-10: H - booked is conserved to round-off by every contact (papers/gravity.md s. 4)
  check(s.main.diag.eerr < 1e-10 && s.main.diag.coll > 1e4, 'newtonian field: the energy read-out (H minus booked) stays conserved',
        s.main.diag.eerr.toExponential(2) + ' over ' + s.main.diag.coll + ' collisions');
  const eread = await page.textContent('#r-eerr');
  check(eread === s.main.diag.eerr.toExponential(2), 'the page shows that energy error', eread);
  const pax = s.profileAxes;
  check(pax && pax.panels.length === 2 && /density/.test(pax.panels[0].xLabel) && /kT/.test(pax.panels[1].xLabel) &&
        pax.panels.every((a) => /height/.test(a.yLabel) && a.xTicks.length >= 2) &&
        /barometric/.test(pax.legends[0][1]) && /balls/.test(pax.legends[0][0]),
        'the profile has labelled axes and a legend', pax ? JSON.stringify(pax.legends) : 'none');
  await page.selectOption('#coupling', { label: 'equivalence' });
  s = await relax(500, 5);
  check(s.main.diag.coupling === 1 && s.field.coupling === 'equivalence' && s.main.diag.eerr < 1e-10 &&
        s.profile.theoryKT[0] > s.profile.theoryKT[nb - 1],
        'equivalence: H conserved, the theory\'s kT falls with height (Tolman)',
        'energy error ' + s.main.diag.eerr.toExponential(2) + ', theory kT ' + s.profile.theoryKT[0].toFixed(4) + ' .. ' +
        s.profile.theoryKT[nb - 1].toFixed(4));
  const shotF = path.join(out, 'web-field.png');
  await page.screenshot({ path: shotF });
  const stF = await pngStats(shotF);
  check(stF.colours > 20, 'field screenshot not blank', shotF + ': ' + stF.colours + ' colours');
  await page.evaluate(() => document.getElementById('profile-fig').scrollIntoView());
  await page.screenshot({ path: path.join(out, 'web-profile.png') });
  await page.evaluate(() => window.scrollTo(0, 0));
  // bad g, typed: refused by name, visible, and the field as it was
  const gNow = s.field.g;
  for (const [typed, want] of [['-1', /g = -1: must be >= 0/], ['abc', /not a number/], ['Infinity', /g = inf: must be a finite number/],
                               ['nan', /g = nan: must be a finite number/]]) {
    await page.evaluate((v) => {
      const el = document.getElementById('g-value');
      el.value = v;
      el.dispatchEvent(new Event('change', { bubbles: true }));
    }, typed);
    const msg = await page.evaluate(() => { const m = document.getElementById('g-msg'); return m.hidden ? '' : m.innerText; });
    const status = await page.locator('#status').innerText();
    s = await state();
    check(want.test(msg) && want.test(status) && s.field.g === gNow && s.main.diag.g === gNow && !s.error,
          'a bad g (' + typed + ') is refused with a visible message', msg);
  }
  await page.evaluate(() => window.relcol.advanceTo(window.relcol.state().t + 10));
  s = await state();
  check(s.main.diag.time > 0 && !s.error, 'the run goes on after a refused g', 't = ' + s.main.diag.time.toFixed(1));
  // off again: the frame chosen before the field (sphere) stays
  await setSlider('g', 0);
  s = await state();
  const frameOff = (await page.locator('#frame option').allInnerTexts())[s.main.diag.frame];
  check(s.field.g === 0 && s.main.diag.g === 0 && /^sphere/.test(frameOff) && (await page.evaluate(() => document.getElementById('g-msg').hidden)),
        'g = 0 switches the field off (the frame chosen before stays)', frameOff);
  // the atmosphere scenario: its own field (equivalence, c = 1), Tolman's kT in the theory
  await page.selectOption('#scenario', 'atmosphere');
  await waitFor(async () => (await state()).scenario === 'atmosphere', 5000, 'the atmosphere');
  s = await relax(400, 4);
  check(s.field.g === 0.002 && s.field.coupling === 'equivalence' && s.main.diag.eerr < 1e-10 &&
        s.profile.theoryKT[0] / s.profile.theoryKT[nb - 1] > 1.2,
        'the atmosphere scenario runs in its field', 'g ' + s.field.g + ', energy error ' + s.main.diag.eerr.toExponential(2) +
        ', theory kT floor/top ' + (s.profile.theoryKT[0] / s.profile.theoryKT[nb - 1]).toFixed(3));
}

async function bench() {
  // 400 discs of the gas scenario, played at its own speed of time for 5 s
  await page.selectOption('#scenario', 'gas');
  await waitFor(async () => (await state()).scenario === 'gas', 5000, 'the gas');
  let s = await state();
  const f0 = s.frames, t0 = Date.now(), sim0 = s.t;
  await page.click('#play');
  await sleep(5000);
  await page.click('#play');
  s = await state();
  const fps = (s.frames - f0) / ((Date.now() - t0) / 1000);
  console.log('gas: ' + s.main.balls.length + ' discs, ' + fps.toFixed(1) + ' frames/s over 5 s of page time ' +
              '(speed of time ' + s.speed.toFixed(2) + ', simulated ' + (s.t - sim0).toFixed(1) + ', ' + s.main.diag.coll + ' collisions)');
  check(s.main.balls.length === 400 && fps >= 55, '400 discs at 60 frames/s', fps.toFixed(1));
  await page.screenshot({ path: path.join(out, 'web-gas.png') });
  check(s.workMs < 1000 / 60, "the page's work a frame fits in a 60 Hz frame", s.workMs.toFixed(2) + ' ms');
  // engine speed: bench_engine's 2d:10000 (discs at packing 0.7, classical) in the page and
  // natively. bench_engine counts CPU time; the page's is read as the CPU time of the
  // browser's processes (this process's descendants, /proc) over the timed call, so that a
  // loaded machine does not count against either. Wall-clock rates are printed too.
  const cases = [
    { label: '2d:10000 (discs, packing 0.7, c = inf)', page: [2, 10000, 0.7, Infinity, '', 5], measure: 20, native: ['2d:10000', '20'] },
    { label: 'rel:10000 (3-D, 0.45, c = 2, table frame)', page: [3, 10000, 0.45, 2, 'table', 2], measure: 5, native: ['rel:10000', '5'] },
  ];
  for (const k of cases) {
    const h = await page.evaluate((a) => window.relcol.benchSetup(...a), k.page);
    const cpu0 = browserCpu();
    const r = await page.evaluate(([h, m]) => window.relcol.benchRun(h, m), [h, k.measure]);
    const cpu = browserCpu() - cpu0;
    await page.evaluate((h) => window.relcol.benchFree(h), h);
    const rate = r.collisions / cpu, wallRate = r.collisions / r.wall;
    const rateOf = (env) => {
      const m = /([0-9.]+) collisions\/s/.exec(execFileSync(tool, k.native, { encoding: 'utf8', env: { ...process.env, ...env } }));
      return m ? Number(m[1]) : NaN;
    };
    const native = rateOf({}), nativeScalar = rateOf({ RELCOL_SIMD: 'scalar' });
    console.log(k.label + ': page ' + rate.toFixed(0) + ' collisions per CPU second (' + r.collisions + ' in ' +
                cpu.toFixed(2) + ' s CPU, ' + r.wall.toFixed(2) + ' s wall: ' + wallRate.toFixed(0) + '/s), native ' +
                native.toFixed(0) + ' (scalar lanes ' + nativeScalar.toFixed(0) + '): ratio ' + (rate / native).toFixed(3) +
                ' (' + (rate / nativeScalar).toFixed(3) + ' to the scalar lanes)');
    check(rate > 0 && isFinite(native), 'engine speed measured: ' + k.label, 'ratio ' + (rate / native).toFixed(3));
  }
}

// CPU seconds of this process's descendants (the browser's processes) so far
function browserCpu() {
  const parent = new Map(), cpu = new Map();
  for (const d of fs.readdirSync('/proc')) {
    if (!/^[0-9]+$/.test(d)) continue;
    let st;
    try { st = fs.readFileSync('/proc/' + d + '/stat', 'utf8'); } catch { continue; }
    const f = st.slice(st.lastIndexOf(')') + 2).split(' ');
    parent.set(Number(d), Number(f[1]));
    cpu.set(Number(d), Number(f[11]) + Number(f[12]));
  }
  let ticks = 0;
  for (const [pid, t] of cpu) {
    for (let p = parent.get(pid); p; p = parent.get(p)) {
      if (p === process.pid) { ticks += t; break; }
    }
  }
  return ticks / clockTicks;
}
