// app.js — the page: controls, drawing and read-outs around librelcol in WebAssembly
// (relcol_web.js / relcol_web.wasm, glue web/relcol_web.c). No physics here: every number
// drawn or shown comes from the library through the glue; this file only maps controls to
// calls, display time to the engine's time, and numbers to pixels.
'use strict';

(function () {
  // per-ball values of web_update / web_balls (relcol_web.c, enum WB_*)
  const WB = { X: 0, Y: 1, PX: 2, PY: 3, R: 4, M: 5, TAU: 6, GAMMA: 7, SPEED: 8, A: 9, B: 10,
               ANGLE: 11, N: 12 };
  // read-outs of web_update (enum WD_*)
  const WD = { TIME: 0, COLL: 1, ENERGY: 2, EERR: 3, PERR: 4, OVERLAPS: 5, OVSHARE: 6,
               MEANG: 7, VMAX: 8, C: 9, KINETIC: 10, HEAT: 11, GROUPSEQ: 12, MAXGROUP: 13,
               N: 14, BOXX: 15, BOXY: 16, PCLASS: 17, EPS: 18, FRAME: 19, LAW: 20,
               CONTRACTED: 21, GROUPS: 22, VERDICT: 23, PMODEL: 24, FIELD: 25, G: 26,
               COUPLING: 27, COUNT: 28 };
  // web_profile's columns of PROF_BINS slabs, then its tail (relcol_web.c, enum WP_*)
  const PROF_BINS = 12, PROF_COLS = 5;
  const PT = { FIT: 0, H: 1, G: 2, COUPLING: 3, M: 4, N: 5, COUNT: 6 };
  const G_POS_MAX = 1000;  // the g slider: 0 .. gMax linearly in G_POS_MAX steps
  // the page's third scenario: data/scenarios/atmosphere.json (its outputs block dropped)
  const ATMOSPHERE = JSON.stringify({ relcol: 1, dim: 2, c: 1, t_end: 2000, seed: 1,
    boundary: ['periodic', 'walls'], gravity: { g: 0.002, coupling: 'equivalence' },
    generate: { kind: 'gas', n: 400, radius: 1, packing: 0.05, v_rms: 0.5 } });
  // rc_sim_verdict (relcol/validity.h)
  const VERDICTS = ['defined', 'outside (p_model > 1e-3: depends on the model’s rules)',
                    'non-covariant model (counted, not bounded)'];
  const C_DECADES = 3;   // the c slider spans c_min .. c_min 10^3, then its last notch is inf
  const C_POS_MAX = 1000;
  const HIST_BINS = 32;
  // the gas's colours: gamma - 1 on a log scale from 10^G_LOG_MIN to 10^G_LOG_MAX, in
  // G_STEPS steps (the colour key draws the same steps)
  const G_LOG_MIN = -4, G_LOG_MAX = 0, G_STEPS = 16;

  const $ = (id) => document.getElementById(id);
  const ui = {
    status: $('status'), scenario: $('scenario'), file: $('file'), play: $('play'),
    step: $('step'), reset: $('reset'), speed: $('speed'), speedOut: $('speed-out'),
    split: $('split'), c: $('c'), cOut: $('c-out'), eps: $('eps'), epsOut: $('eps-out'),
    frame: $('frame'), law: $('law'), groups: $('groups'), viewRef: $('view-ref'), capMain: $('cap-main'),
    canvasRef: $('canvas-ref'), canvasMain: $('canvas-main'), hist: $('hist'),
    theta: $('theta'), tip: $('tip'), capRef: $('cap-ref'), keyText: $('colour-key-text'),
    keyScale: $('colour-key-scale'), keyBar: $('colour-key-bar'), keyTicks: $('colour-key-ticks'),
    g: $('g'), gOut: $('g-out'), gValue: $('g-value'), coupling: $('coupling'), gMsg: $('g-msg'),
    profile: $('profile'), profileCap: $('profile-cap'),
  };

  let M = null;      // the wasm module
  let api = null;    // its exported functions
  const app = {
    source: { builtin: 'rack', text: null, name: 'rack' },
    main: null,      // { w, diag, balls } the world at the chosen c
    ref: null,       // the same break at c = inf (split view)
    playing: false,
    split: false,
    t: 0,            // display time = the engine time both worlds are brought to
    speed: 1,        // time units per second of page time
    cMin: 1,         // lowest c of the slider: just above the fastest ball (followSlider)
    dragging: false,
    c: Infinity,
    fps: 0,
    frames: 0,
    workMs: 0,
    lastNow: null,
    error: null,
    g: 0,            // the field now (0: none) and its coupling (index into the library's)
    coupling: 0,
    gMax: 1,         // the g slider's top (set at each load from the gas's kT: gasGMax)
    prof: null,      // the profile averaged over engine time (sampleProfile)
    profAxes: null,
  };

  function fmt(x, digits) {
    if (!isFinite(x)) return x > 0 ? '∞' : String(x);
    const a = Math.abs(x);
    if (a !== 0 && (a < 1e-3 || a >= 1e5)) return x.toExponential(digits === undefined ? 2 : digits);
    return x.toFixed(digits === undefined ? 4 : digits);
  }

  function setStatus(msg, isError) {
    ui.status.textContent = msg;
    ui.status.classList.toggle('error', !!isError);
  }

  function fail(where) {
    const msg = where + ': ' + M.UTF8ToString(api.error());
    app.error = msg;
    setStatus(msg, true);
    return msg;
  }

  function bind() {
    const f = (name, ret, args) => M.cwrap(name, ret, args);
    api = {
      error: f('web_error', 'number', []),
      create: f('web_create', 'number', ['string', 'number']),
      free: f('web_free', null, ['number']),
      reset: f('web_reset', 'number', ['number']),
      setC: f('web_set_c', 'number', ['number', 'number']),
      setModel: f('web_set_model', 'number', ['number', 'number', 'number', 'number', 'number']),
      advance: f('web_advance', 'number', ['number', 'number']),
      stepEvent: f('web_step_event', 'number', ['number']),
      time: f('web_time', 'number', ['number']),
      count: f('web_count', 'number', ['number']),
      update: f('web_update', 'number', ['number']),
      balls: f('web_balls', 'number', ['number']),
      histogram: f('web_histogram', 'number', ['number', 'number', 'number']),
      frameCount: f('web_frame_count', 'number', []),
      frameName: f('web_frame_name', 'string', ['number']),
      frameContracted: f('web_frame_contracted', 'number', ['number']),
      lawCount: f('web_law_count', 'number', []),
      lawName: f('web_law_name', 'string', ['number']),
      lawSummary: f('web_law_summary', 'string', ['number']),
      lawGroup: f('web_law_group', 'number', ['number']),
      groupCount: f('web_group_count', 'number', []),
      groupName: f('web_group_name', 'string', ['number']),
      groupSummary: f('web_group_summary', 'string', ['number']),
      benchSetup: f('web_bench_setup', 'number', ['number', 'number', 'number', 'number',
                                                  'number', 'number']),
      benchRun: f('web_bench_run', 'number', ['number', 'number']),
      benchFree: f('web_bench_free', null, ['number']),
      setGravity: f('web_set_gravity', 'number', ['number', 'number', 'number']),
      couplingCount: f('web_coupling_count', 'number', []),
      couplingName: f('web_coupling_name', 'string', ['number']),
      couplingSummary: f('web_coupling_summary', 'string', ['number']),
      profile: f('web_profile', 'number', ['number', 'number']),
    };
  }

  // ---- worlds -------------------------------------------------------------------------

  function readWorld(v) {
    const dp = api.update(v.w) >> 3;
    v.diag = Array.from(M.HEAPF64.subarray(dp, dp + WD.COUNT));
    const n = v.diag[WD.N];
    const bp = api.balls(v.w) >> 3;
    v.balls = M.HEAPF64.slice(bp, bp + n * WB.N);
  }

  function makeWorld() {
    const s = app.source;
    const w = s.text !== null ? api.create(s.text, 0) : api.create(s.builtin, 1);
    if (!w) return null;
    const v = { w: w, diag: null, balls: null };
    readWorld(v);
    return v;
  }

  function freeWorlds() {
    for (const k of ['main', 'ref']) {
      if (app[k]) api.free(app[k].w);
      app[k] = null;
    }
  }

  // Load the current source into fresh worlds: the main one (the chosen c) and, in split
  // view, the same break at c = inf.
  // keepC: a reset keeps the chosen c (the break replayed at it); a new scenario starts
  // at its own c.
  function load(keepC) {
    const chosen = app.c;
    freeWorlds();
    app.error = null;
    const main = makeWorld();
    if (!main) { fail('scenario ' + app.source.name); return false; }
    app.main = main;
    app.t = main.diag[WD.TIME];
    const c0 = main.diag[WD.C];
    app.c = c0;
    if (keepC && chosen !== c0 && api.setC(main.w, chosen) === 0) {
      app.c = chosen;
      readWorld(main);
    }
    app.speed = Math.max(1, main.diag[WD.BOXX] / (2 * Math.max(main.diag[WD.VMAX], 1e-300)));
    ui.speed.value = String(Math.log10(app.speed));
    ui.eps.value = String(main.diag[WD.EPS]);
    ui.frame.value = String(main.diag[WD.FRAME]);
    ui.law.value = String(main.diag[WD.LAW]);
    ui.groups.value = String(main.diag[WD.GROUPS]);
    // the field: the scenario's own, or (a reset) the one chosen before
    const g0 = app.g, cp0 = app.coupling;
    app.g = main.diag[WD.G];
    if (main.diag[WD.COUPLING] >= 0) app.coupling = main.diag[WD.COUPLING];
    app.gMax = gasGMax(main);
    if (keepC && (g0 !== app.g || (g0 > 0 && cp0 !== app.coupling))) {
      if (api.setGravity(main.w, g0, cp0) === 0) { app.g = g0; app.coupling = cp0; readWorld(main); }
    }
    if (app.g > app.gMax) app.gMax = niceUp(2 * app.g);
    app.prof = null;
    showField();
    if (app.split && !makeRef()) return false;
    sizeCanvases();
    showControls();
    setStatus('ready: ' + app.source.name + ' (' + main.diag[WD.N] + ' balls)');
    return true;
  }

  function makeRef() {
    const ref = makeWorld();
    if (!ref) { fail('split view'); return false; }
    if (isFinite(ref.diag[WD.C]) && api.setC(ref.w, Infinity) !== 0) { fail('split view c = ∞'); return false; }
    // the same break: the chosen model, at the main world's time
    const md = app.main.diag;
    if (ref.diag[WD.EPS] !== md[WD.EPS] || ref.diag[WD.FRAME] !== md[WD.FRAME] ||
        ref.diag[WD.LAW] !== md[WD.LAW] || ref.diag[WD.GROUPS] !== md[WD.GROUPS]) {
      if (api.setModel(ref.w, md[WD.EPS], md[WD.FRAME], md[WD.LAW], md[WD.GROUPS]) !== 0) { fail('split view'); return false; }
    }
    // the field, from the reference's start (its history differs from the main world's
    // when the field was switched on later there: the caption says so)
    if ((ref.diag[WD.G] !== app.g || ref.diag[WD.COUPLING] !== (app.g > 0 ? app.coupling : -1)) &&
        api.setGravity(ref.w, app.g, app.coupling) !== 0) { fail('split view'); return false; }
    if (api.advance(ref.w, app.t) !== 0) { fail('split view'); return false; }
    readWorld(ref);
    app.ref = ref;
    return true;
  }

  function worlds() { return app.ref ? [app.main, app.ref] : [app.main]; }

  function advanceTo(t) {
    for (const v of worlds()) {
      if (api.advance(v.w, t) !== 0) { pause(); fail('engine'); return false; }
    }
    app.t = t;
    for (const v of worlds()) readWorld(v);
    return true;
  }

  // ---- controls -----------------------------------------------------------------------

  function sliderFor(c) {
    if (!isFinite(c)) return C_POS_MAX;
    const pos = (C_POS_MAX - 1) * Math.log10(c / app.cMin) / C_DECADES;
    return Math.min(C_POS_MAX - 1, Math.max(0, pos));
  }

  function cFor(pos) {
    if (pos >= C_POS_MAX) return Infinity;
    return app.cMin * Math.pow(10, C_DECADES * pos / (C_POS_MAX - 1));
  }

  function setC(c) {
    if (!app.main) return false;
    if (api.setC(app.main.w, c) !== 0) { fail('c'); return false; }
    app.c = c;
    readWorld(app.main);
    app.prof = null;
    showControls();
    draw();
    return true;
  }

  // ---- the field ------------------------------------------------------------------------

  // 1, 2 or 5 times a power of ten, >= x
  function niceUp(x) {
    if (!(x > 0) || !isFinite(x)) return 1;
    const p = Math.pow(10, Math.floor(Math.log10(x)));
    return [1, 2, 5, 10].map((k) => k * p).find((v) => v >= x * (1 - 1e-12));
  }

  // The slider's top: the g at which m g H = 5 kT for this gas (kT = <p.v>/d from the
  // library's profile), so that the slider spans from no field to a dense floor layer.
  function gasGMax(v) {
    const t = readProfile(v);
    const kT = t.tail[PT.FIT], m = t.tail[PT.M], H = t.tail[PT.H];
    return niceUp(kT > 0 && m > 0 && H > 0 ? 5 * kT / (m * H) : 1);
  }

  function gFor(pos) { return app.gMax * Math.min(G_POS_MAX, Math.max(0, pos)) / G_POS_MAX; }
  function sliderForG(g) { return Math.min(G_POS_MAX, Math.max(0, Math.round(G_POS_MAX * g / app.gMax))); }

  function fieldMessage(msg) {
    ui.gMsg.textContent = msg || '';
    ui.gMsg.hidden = !msg;
  }

  // The field on every world: g >= 0 (0: none) with the chosen coupling. The glue refuses
  // a bad g (negative, not finite) or a scenario that cannot have a field, naming why; the
  // run then goes on as it was, and the message shows beside the slider and in the status.
  function setGravity(g, coupling) {
    if (!app.main) return false;
    for (const v of worlds()) {
      if (api.setGravity(v.w, g, coupling) !== 0) {
        // (a refused input is no failure of the run: it goes on, app.error stays clear)
        const msg = 'field: ' + M.UTF8ToString(api.error());
        setStatus(msg, true);
        fieldMessage(msg);
        showField();
        return false;
      }
      readWorld(v);
    }
    app.g = g;
    app.coupling = coupling;
    app.prof = null;
    fieldMessage('');
    setStatus('field: ' + (g > 0 ? 'g = ' + fmt(g, 4) + ', ' + api.couplingName(coupling) +
              ' coupling (contact frame ' + ui.frame.options[app.main.diag[WD.FRAME]].textContent + ')' : 'off'));
    ui.frame.value = String(app.main.diag[WD.FRAME]);
    showField();
    draw();
    return true;
  }

  // g as typed: a number (the glue judges its value), else refused here by what was typed
  function takeTypedG() {
    const txt = ui.gValue.value.trim();
    const g = txt === '' ? NaN : Number(txt);
    if (txt === '' || (Number.isNaN(g) && !/^[-+]?nan$/i.test(txt))) {
      const msg = 'field: g = "' + txt + '": not a number (type g >= 0; 0 switches the field off)';
      setStatus(msg, true);
      fieldMessage(msg);
      showField();
      return false;
    }
    return setGravity(g, Number(ui.coupling.value));
  }

  function showField() {
    if (app.g > app.gMax) app.gMax = niceUp(2 * app.g);
    ui.g.value = String(sliderForG(app.g));
    ui.gOut.textContent = app.g > 0 ? fmt(app.g, 4) : 'off';
    // (a refused g stays in the box beside its message)
    if (ui.gMsg.hidden && document.activeElement !== ui.gValue) ui.gValue.value = String(app.g);
    ui.coupling.value = String(app.coupling);
  }

  function setModel() {
    const eps = Number(ui.eps.value), frame = Number(ui.frame.value), law = Number(ui.law.value);
    const groups = Number(ui.groups.value);
    for (const v of worlds()) {
      if (api.setModel(v.w, eps, frame, law, groups) !== 0) { fail('model'); break; }
      readWorld(v);
    }
    showControls();
    draw();
  }

  function play() { app.playing = true; app.lastNow = null; ui.play.textContent = 'pause'; }
  function pause() { app.playing = false; ui.play.textContent = 'play'; }

  function stepEvent() {
    pause();
    if (api.stepEvent(app.main.w) !== 0) { fail('single event'); return; }
    const t = api.time(app.main.w);
    if (app.ref && api.advance(app.ref.w, t) !== 0) { fail('split view'); return; }
    app.t = t;
    for (const v of worlds()) readWorld(v);
    draw();
  }

  function setSplit(on) {
    app.split = on;
    ui.split.checked = on;
    ui.viewRef.hidden = !on;
    if (on && !app.ref) makeRef();
    if (!on && app.ref) { api.free(app.ref.w); app.ref = null; }
    sizeCanvases();
    draw();
  }

  function showControls() {
    ui.gOut.textContent = app.g > 0 ? fmt(app.g, 4) : 'off';
    ui.cOut.textContent = isFinite(app.c) ? fmt(app.c, 4) : '∞';
    ui.epsOut.textContent = Number(ui.eps.value).toFixed(2);
    ui.speedOut.textContent = fmt(app.speed, 3) + ' / s';
  }

  function fillTables() {
    ui.frame.innerHTML = '';
    for (let i = 0; i < api.frameCount(); i++) {
      const o = document.createElement('option');
      o.value = String(i);
      o.textContent = api.frameName(i) + (api.frameContracted(i) ? ' (contracted shapes)' : ' (spheres)');
      ui.frame.appendChild(o);
    }
    ui.law.innerHTML = '';
    for (let i = 0; i < api.lawCount(); i++) {
      const o = document.createElement('option');
      o.value = String(i);
      o.textContent = api.lawName(i) + (api.lawGroup(i) ? '' : ' (no group solver: contacts one by one)');
      o.title = api.lawSummary(i);
      ui.law.appendChild(o);
    }
    ui.coupling.innerHTML = '';
    for (let i = 0; i < api.couplingCount(); i++) {
      const o = document.createElement('option');
      o.value = String(i);
      o.textContent = api.couplingName(i);
      o.title = api.couplingSummary(i);
      ui.coupling.appendChild(o);
    }
    ui.groups.innerHTML = '';
    for (let i = 0; i < api.groupCount(); i++) {
      const o = document.createElement('option');
      o.value = String(i);
      o.textContent = api.groupName(i);
      o.title = api.groupSummary(i);
      ui.groups.appendChild(o);
    }
  }

  function wire() {
    ui.scenario.addEventListener('change', () => {
      app.source = ui.scenario.value === 'atmosphere'
        ? { builtin: null, text: ATMOSPHERE, name: 'atmosphere' }
        : { builtin: ui.scenario.value, text: null, name: ui.scenario.value };
      pause();
      load();
      draw();
    });
    const takeFile = (file) => {
      file.text().then((text) => {
        const prev = app.source;
        app.source = { builtin: null, text: text, name: file.name };
        pause();
        if (!load()) { const msg = app.error; app.source = prev; load(); setStatus(msg, true); }
        draw();
      });
    };
    ui.file.addEventListener('change', () => { if (ui.file.files[0]) takeFile(ui.file.files[0]); });
    document.body.addEventListener('dragover', (e) => { e.preventDefault(); document.body.classList.add('dragging'); });
    document.body.addEventListener('dragleave', () => document.body.classList.remove('dragging'));
    document.body.addEventListener('drop', (e) => {
      e.preventDefault();
      document.body.classList.remove('dragging');
      if (e.dataTransfer.files[0]) takeFile(e.dataTransfer.files[0]);
    });
    ui.play.addEventListener('click', () => (app.playing ? pause() : play()));
    ui.step.addEventListener('click', stepEvent);
    ui.reset.addEventListener('click', () => { pause(); load(true); draw(); });
    ui.speed.addEventListener('input', () => { app.speed = Math.pow(10, Number(ui.speed.value)); showControls(); });
    ui.split.addEventListener('change', () => setSplit(ui.split.checked));
    ui.c.addEventListener('input', () => setC(cFor(Number(ui.c.value))));
    ui.c.addEventListener('pointerdown', () => { app.dragging = true; });
    window.addEventListener('pointerup', () => { app.dragging = false; });
    ui.eps.addEventListener('input', () => { ui.epsOut.textContent = Number(ui.eps.value).toFixed(2); });
    ui.eps.addEventListener('change', setModel);
    ui.frame.addEventListener('change', setModel);
    ui.law.addEventListener('change', setModel);
    ui.groups.addEventListener('change', setModel);
    ui.g.addEventListener('input', () => { const g = gFor(Number(ui.g.value)); ui.gValue.value = String(g); setGravity(g, Number(ui.coupling.value)); });
    ui.gValue.addEventListener('change', takeTypedG);
    ui.coupling.addEventListener('change', () => { if (app.g > 0) setGravity(app.g, Number(ui.coupling.value)); else app.coupling = Number(ui.coupling.value); });
    for (const cv of [ui.canvasMain, ui.canvasRef]) {
      cv.addEventListener('mousemove', (e) => hover(e, cv));
      cv.addEventListener('mouseleave', () => { ui.tip.hidden = true; });
    }
    window.addEventListener('resize', () => { sizeCanvases(); draw(); });
  }

  // ---- drawing ------------------------------------------------------------------------

  function sizeCanvases() {
    if (!app.main) return;
    const bx = app.main.diag[WD.BOXX], by = app.main.diag[WD.BOXY];
    const dpr = window.devicePixelRatio || 1;
    for (const cv of [ui.canvasMain, ui.canvasRef]) {
      // as wide as its column, but no taller than 60 % of the window (a square gas box)
      const col = cv.parentElement.clientWidth || 640;
      cv.style.width = Math.max(200, Math.min(col, 0.6 * window.innerHeight * bx / by)) + 'px';
      const w = Math.max(200, Math.round((cv.clientWidth || 640) * dpr));
      cv.width = w;
      cv.height = Math.max(50, Math.round(w * by / bx));
    }
    const hw = Math.max(200, Math.round((ui.hist.clientWidth || 640) * dpr));
    ui.hist.width = hw;
    // (short enough that the table, its colour key and the histogram's axis fit a window)
    ui.hist.height = Math.round(Math.min(0.22 * hw, 0.26 * window.innerHeight * dpr));
    ui.profile.width = hw;
    ui.profile.height = Math.round(Math.min(0.3 * hw, 0.34 * window.innerHeight * dpr));
  }

  function ballColour(i, n, gamma, isRack) {
    if (isRack) {
      if (i === 0) return '#f6f3e8';
      const palette = ['#f2c100', '#1f4fb4', '#d2261f', '#5b2a86', '#ef7d00', '#1a7f3c', '#7b1e1e', '#111'];
      return palette[(i - 1) % palette.length];
    }
    // hotter balls redder: gamma - 1 on a log scale, in G_STEPS steps
    const lg = Math.log10(Math.max(gamma - 1, 1e-300));
    return stepColour(Math.round(G_STEPS * Math.min(1, Math.max(0, (lg - G_LOG_MIN) / (G_LOG_MAX - G_LOG_MIN)))) / G_STEPS);
  }

  function stepColour(u) {
    const r = Math.round(80 + 175 * u), b = Math.round(230 - 180 * u);
    return 'rgb(' + r + ',' + Math.round(140 + 40 * (1 - u)) + ',' + b + ')';
  }

  // The key to the balls' colours, beside the table: the rack's billiard set by ball
  // number, or the gas's gamma - 1 steps drawn with ballColour's own mapping.
  let keyShown = null;
  function drawColourKey() {
    const isRack = app.source.builtin === 'rack';
    const infinite = !isFinite(app.c);
    const want = isRack ? 'rack' : 'gamma' + (infinite ? ' inf' : '');
    if (want === keyShown) return;
    keyShown = want;
    if (isRack) {
      ui.keyText.textContent = 'ball colours: a billiard set by ball number (ball 0, the cue ball, white)';
      ui.keyScale.hidden = true;
      return;
    }
    ui.keyText.textContent = 'ball colour: γ − 1 (log scale)' +
      (infinite ? ' — at c = ∞ every γ is 1: one colour' : '');
    ui.keyScale.hidden = false;
    const cv = ui.keyBar, ctx = cv.getContext('2d');
    const n = G_STEPS + 1;
    for (let k = 0; k < n; k++) {
      ctx.fillStyle = ballColour(1, 2, 1 + Math.pow(10, G_LOG_MIN + (G_LOG_MAX - G_LOG_MIN) * k / G_STEPS), false);
      ctx.fillRect(Math.floor(k * cv.width / n), 0, Math.ceil(cv.width / n), cv.height);
    }
    ui.keyTicks.innerHTML = '';
    for (let e = G_LOG_MIN; e <= G_LOG_MAX; e++) {
      const t = document.createElement('span');
      t.textContent = e === 0 ? '1' : e === G_LOG_MIN ? '≤ 10' + sup(e) : '10' + sup(e);
      ui.keyTicks.appendChild(t);
    }
  }

  function sup(e) {
    const d = { '-': '⁻', 0: '⁰', 1: '¹', 2: '²', 3: '³', 4: '⁴', 5: '⁵', 6: '⁶', 7: '⁷', 8: '⁸', 9: '⁹' };
    return String(e).split('').map((ch) => d[ch]).join('');
  }

  function drawWorld(v, cv) {
    const ctx = cv.getContext('2d');
    const bx = v.diag[WD.BOXX], by = v.diag[WD.BOXY], n = v.diag[WD.N];
    const s = cv.width / bx;
    const isRack = app.source.builtin === 'rack';
    ctx.fillStyle = isRack ? '#1d5c3a' : '#15222e';
    ctx.fillRect(0, 0, cv.width, cv.height);
    const b = v.balls;
    // one path per colour: a few fills a frame however many balls
    const paths = new Map();
    for (let i = 0; i < n; i++) {
      const o = i * WB.N;
      const x = b[o + WB.X] * s, y = cv.height - b[o + WB.Y] * s;
      const a = Math.max(b[o + WB.A] * s, 0.5), bb = Math.max(b[o + WB.B] * s, 0.5);
      const colour = ballColour(i, n, b[o + WB.GAMMA], isRack);
      let p = paths.get(colour);
      if (!p) { p = new Path2D(); paths.set(colour, p); }
      // the contracted shape: semi-axis a along the velocity (canvas y points down)
      p.moveTo(x + a * Math.cos(b[o + WB.ANGLE]), y - a * Math.sin(b[o + WB.ANGLE]));
      p.ellipse(x, y, a, bb, -b[o + WB.ANGLE], 0, 2 * Math.PI);
    }
    for (const [colour, p] of paths) {
      ctx.fillStyle = colour;
      ctx.fill(p);
      if (n <= 64) { ctx.lineWidth = 1; ctx.strokeStyle = 'rgba(0,0,0,0.5)'; ctx.stroke(p); }
    }
    // (the time is in the figure's caption, where no ball covers it)
  }

  // Ticks at 1, 2 or 5 times a power of ten over [0, top]: at least three.
  function niceTicks(top) {
    if (!(top > 0) || !isFinite(top)) return [0];
    const raw = top / 5, p = Math.pow(10, Math.floor(Math.log10(raw)));
    const step = [1, 2, 5, 10].map((m) => m * p).find((st) => st >= raw) || 10 * p;
    const ticks = [];
    for (let k = 0; k * step <= top * (1 + 1e-12); k++) ticks.push(k * step);
    return ticks;
  }

  function tickText(x, step) {
    if (x === 0) return '0';
    const digits = Math.max(0, -Math.floor(Math.log10(step) + 1e-9));
    return Math.abs(x) >= 1e5 || Math.abs(x) < 1e-3 ? x.toExponential(1) : x.toFixed(digits);
  }

  // The balls' speed histogram (a density: share of balls per unit speed) against the
  // Jüttner and Maxwell–Boltzmann densities, with both axes ticked and labelled: speed in
  // units of c at finite c, in the scenario's units at c = inf.
  function drawHistogram() {
    const v = app.main;
    const cv = ui.hist, ctx = cv.getContext('2d');
    ctx.clearRect(0, 0, cv.width, cv.height);
    const c = v.diag[WD.C];
    const vtop = isFinite(c) ? c : 1.25 * Math.max(v.diag[WD.VMAX], 1e-300);
    const hp = api.histogram(v.w, HIST_BINS, vtop) >> 3;
    const h = M.HEAPF64.slice(hp, hp + 3 * HIST_BINS + 2);
    app.hist = h;
    let top = 0;
    for (let k = 0; k < 3 * HIST_BINS; k++) if (isFinite(h[k])) top = Math.max(top, h[k]);
    if (!(top > 0)) { app.histAxes = null; return; }
    const dpr = window.devicePixelRatio || 1, fs = Math.round(11 * dpr);
    const mL = Math.round(62 * dpr), mR = Math.round(26 * dpr), mT = Math.round(8 * dpr),
          mB = Math.round(40 * dpr);
    const W = cv.width - mL - mR, H = cv.height - mT - mB, bw = W / HIST_BINS;
    // x in units of c at finite c, and y then per unit of v/c (the library's density is
    // per unit speed: times c); y up to the next tick above the tallest
    const xu = isFinite(c) ? c : 1, xTicks = niceTicks(vtop / xu);
    top *= xu;
    const yStep0 = niceTicks(top);
    const yStep = yStep0.length > 1 ? yStep0[1] : top;
    const yTop = Math.ceil(top / yStep - 1e-9) * yStep;
    const yTicks = [];
    for (let k = 0; k * yStep <= yTop * (1 + 1e-12); k++) yTicks.push(k * yStep);
    const X = (speed) => mL + W * speed / vtop, Y = (f) => mT + H - H * f * xu / yTop;
    // the grid and the axes with their values
    ctx.font = fs + 'px system-ui, sans-serif';
    ctx.lineWidth = 1;
    ctx.strokeStyle = '#e4e4e4';
    ctx.fillStyle = '#444';
    ctx.textAlign = 'right';
    ctx.textBaseline = 'middle';
    for (const f of yTicks) {
      const y = Math.round(mT + H - H * f / yTop) + 0.5;
      ctx.beginPath(); ctx.moveTo(mL, y); ctx.lineTo(mL + W, y); ctx.stroke();
      ctx.fillText(tickText(f, yStep), mL - 5 * dpr, y);
    }
    ctx.textAlign = 'center';
    ctx.textBaseline = 'top';
    const xStep = xTicks.length > 1 ? xTicks[1] : 1;
    for (const t of xTicks) {
      const x = Math.round(X(t * xu)) + 0.5;
      ctx.strokeStyle = '#888';
      ctx.beginPath(); ctx.moveTo(x, mT + H); ctx.lineTo(x, mT + H + 4 * dpr); ctx.stroke();
      ctx.fillText(tickText(t, xStep) + (isFinite(c) && t !== 0 ? ' c' : ''), x, mT + H + 6 * dpr);
    }
    const xLabel = isFinite(c) ? 'speed |v| (in units of c)' : 'speed |v| (the scenario’s units)';
    const yLabel = isFinite(c) ? 'share per unit of |v|/c' : 'share per unit speed';
    ctx.fillText(xLabel, mL + W / 2, mT + H + 6 * dpr + fs + 2 * dpr);
    ctx.save();
    ctx.translate(12 * dpr, mT + H / 2);
    ctx.rotate(-Math.PI / 2);
    ctx.textBaseline = 'middle';
    ctx.fillText(yLabel, 0, 0);
    ctx.restore();
    ctx.strokeStyle = '#666';
    ctx.beginPath(); ctx.moveTo(mL + 0.5, mT); ctx.lineTo(mL + 0.5, mT + H + 0.5); ctx.lineTo(mL + W, mT + H + 0.5); ctx.stroke();
    app.histAxes = { xLabel: xLabel, yLabel: yLabel, xUnit: isFinite(c) ? 'c' : '',
                     xTicks: xTicks.map((t) => t * xu), yTicks: yTicks, vtop: vtop, yTop: yTop };
    ctx.fillStyle = '#9fb8d8';
    for (let k = 0; k < HIST_BINS; k++) {
      const hh = H * h[k] * xu / yTop;
      ctx.fillRect(mL + k * bw + 1, mT + H - hh, bw - 2, hh);
    }
    const curve = (off, colour, dash) => {
      ctx.beginPath();
      ctx.setLineDash(dash);
      for (let k = 0; k < HIST_BINS; k++) {
        const x = mL + (k + 0.5) * bw, y = Y(h[off + k]);
        if (k === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
      }
      ctx.strokeStyle = colour;
      ctx.lineWidth = 2;
      ctx.stroke();
      ctx.setLineDash([]);
    };
    curve(HIST_BINS, '#c0392b', []);
    curve(2 * HIST_BINS, '#2c3e50', [6, 4]);
    const theta = h[3 * HIST_BINS];
    ui.theta.textContent = '(speeds 0 … ' + (isFinite(c) ? 'c' : fmt(vtop, 3)) + ')' +
      (isFinite(theta) ? ', θ = kT/mc² = ' + fmt(theta, 4) : '');
  }

  // ---- the profile along the field ------------------------------------------------------

  // The library's profile of the balls as web_update last read them (web_profile)
  function readProfile(v) {
    const pp = api.profile(v.w, PROF_BINS) >> 3;
    const a = M.HEAPF64.slice(pp, pp + PROF_COLS * PROF_BINS + PT.COUNT);
    const col = (k) => Array.from(a.subarray(k * PROF_BINS, (k + 1) * PROF_BINS));
    return { density: col(0), kT: col(1), kTerr: col(2), theoryDensity: col(3), theoryKT: col(4),
             tail: Array.from(a.subarray(PROF_COLS * PROF_BINS)), raw: a };
  }

  // Averaged over engine time with weight 1 - exp(-dt/tau), tau the time the fastest ball
  // takes to cross the box's height: one snapshot of 400 balls in 12 slabs is noisy. Reset
  // at every change of the model (app.prof = null).
  function sampleProfile() {
    const v = app.main, t = v.diag[WD.TIME];
    if (app.prof && app.prof.t === t) return;
    const now = readProfile(v);
    const tau = Math.max(now.tail[PT.H] / Math.max(v.diag[WD.VMAX], 1e-300), 1e-300);
    if (!app.prof) {
      app.prof = { t: t, t0: t, avg: Float64Array.from(now.raw), now: now };
      return;
    }
    const w = 1 - Math.exp(-(t - app.prof.t) / tau), avg = app.prof.avg;
    for (let k = 0; k < avg.length; k++) {
      const x = now.raw[k];
      if (!isFinite(avg[k])) avg[k] = x;
      else if (isFinite(x)) avg[k] += w * (x - avg[k]);
    }
    app.prof.t = t;
    app.prof.now = now;
    app.prof.tau = tau;
  }

  function profileState() {
    if (!app.prof) return null;
    const a = app.prof.avg, col = (k) => Array.from(a.subarray(k * PROF_BINS, (k + 1) * PROF_BINS));
    const tail = Array.from(a.subarray(PROF_COLS * PROF_BINS));
    return { bins: PROF_BINS, density: col(0), kT: col(1), kTerr: col(2), theoryDensity: col(3),
             theoryKT: col(4), kTfit: tail[PT.FIT], height: tail[PT.H], g: tail[PT.G],
             coupling: tail[PT.COUPLING] >= 0 ? api.couplingName(tail[PT.COUPLING]) : null,
             mass: tail[PT.M], since: app.prof.t0, tau: app.prof.tau || null,
             now: { density: app.prof.now.density, kT: app.prof.now.kT } };
  }

  // Two panels, height y up: the balls' density (bars, per slab) against the dilute gas's
  // equilibrium, and kT per slab (points, one snapshot's standard error) against the
  // coupling's kT(y); axes ticked and labelled, a legend in each.
  function drawProfile() {
    const cv = ui.profile, ctx = cv.getContext('2d');
    ctx.clearRect(0, 0, cv.width, cv.height);
    const P = profileState();
    if (!P) return;
    const c = app.main.diag[WD.C], field = P.g > 0;
    const equiv = field && P.coupling === 'equivalence';
    const dpr = window.devicePixelRatio || 1, fs = Math.round(11 * dpr);
    const mL = Math.round(56 * dpr), mR = Math.round(12 * dpr), mT = Math.round(10 * dpr),
          mB = Math.round(40 * dpr), gap = Math.round(60 * dpr);
    const W = (cv.width - mL - gap - mR) / 2, H = cv.height - mT - mB;
    const panels = [
      { x0: mL, label: 'density (share of balls per unit height)', bars: P.density, curve: P.theoryDensity },
      { x0: mL + W + gap, label: 'kT in the slab (' + (isFinite(c) ? '= θ mc²' : 'c = ∞') + ')', pts: P.kT, err: P.kTerr, curve: P.theoryKT },
    ];
    const yOf = (z) => mT + H - H * z / P.height;
    ctx.font = fs + 'px system-ui, sans-serif';
    const axes = [];
    for (const pn of panels) {
      const vals = (pn.bars || pn.pts).concat(pn.curve).filter(isFinite);
      if (pn.err) pn.pts.forEach((x, k) => { if (isFinite(x) && isFinite(pn.err[k])) vals.push(x + pn.err[k]); });
      let top = Math.max(...vals, 0);
      if (!(top > 0)) top = 1;
      const xt = niceTicks(top), xs = xt.length > 1 ? xt[1] : top;
      const xTop = Math.ceil(top / xs - 1e-9) * xs;
      const ticks = [];
      for (let k = 0; k * xs <= xTop * (1 + 1e-12); k++) ticks.push(k * xs);
      const X = (x) => pn.x0 + W * x / xTop;
      // grid, ticks and labels
      ctx.lineWidth = 1;
      ctx.fillStyle = '#444';
      ctx.textAlign = 'center';
      ctx.textBaseline = 'top';
      for (const t of ticks) {
        const x = Math.round(X(t)) + 0.5;
        ctx.strokeStyle = '#e4e4e4';
        ctx.beginPath(); ctx.moveTo(x, mT); ctx.lineTo(x, mT + H); ctx.stroke();
        ctx.fillText(tickText(t, xs), x, mT + H + 4 * dpr);
      }
      ctx.fillText(pn.label, pn.x0 + W / 2, mT + H + 6 * dpr + fs);
      const zt = niceTicks(P.height), zs = zt.length > 1 ? zt[1] : P.height;
      ctx.textAlign = 'right';
      ctx.textBaseline = 'middle';
      for (const z of zt) ctx.fillText(tickText(z, zs), pn.x0 - 4 * dpr, yOf(z));
      ctx.save();
      ctx.translate(pn.x0 - 40 * dpr, mT + H / 2);
      ctx.rotate(-Math.PI / 2);
      ctx.textAlign = 'center';
      ctx.fillText('height y (floor 0)', 0, 0);
      ctx.restore();
      ctx.strokeStyle = '#666';
      ctx.beginPath(); ctx.moveTo(pn.x0 + 0.5, mT); ctx.lineTo(pn.x0 + 0.5, mT + H + 0.5); ctx.lineTo(pn.x0 + W, mT + H + 0.5); ctx.stroke();
      const dz = P.height / P.bins;
      if (pn.bars) {
        ctx.fillStyle = '#9fb8d8';
        pn.bars.forEach((x, k) => {
          if (!isFinite(x)) return;
          const y1 = yOf(k * dz), y0 = yOf((k + 1) * dz);
          ctx.fillRect(pn.x0 + 1, y0 + 1, X(x) - pn.x0, y1 - y0 - 2);
        });
      } else {
        ctx.strokeStyle = '#1f4fb4';
        ctx.fillStyle = '#1f4fb4';
        pn.pts.forEach((x, k) => {
          if (!isFinite(x)) return;
          const y = yOf((k + 0.5) * dz), e = pn.err[k];
          if (isFinite(e)) { ctx.beginPath(); ctx.moveTo(X(x - e), y); ctx.lineTo(X(x + e), y); ctx.stroke(); }
          ctx.beginPath(); ctx.arc(X(x), y, 2.5 * dpr, 0, 2 * Math.PI); ctx.fill();
        });
      }
      ctx.beginPath();
      pn.curve.forEach((x, k) => {
        const px = X(x), py = yOf((k + 0.5) * dz);
        if (k === 0) ctx.moveTo(px, py); else ctx.lineTo(px, py);
      });
      ctx.strokeStyle = '#c0392b';
      ctx.lineWidth = 2;
      ctx.stroke();
      axes.push({ xLabel: pn.label, yLabel: 'height y (floor 0)', xTicks: ticks, xTop: xTop });
    }
    // legends (top right of each panel)
    const theoryN = !field ? 'no field: uniform' : equiv
      ? (isFinite(c) ? 'local Jüttner at kT₀/(1 + gy/c²)' : 'barometric e^(−mgy/kT)')
      : 'barometric e^(−mgy/kT)';
    const theoryT = !field ? 'uniform kT' : equiv && isFinite(c) ? 'Tolman kT₀/(1 + gy/c²)' : 'uniform kT';
    const legends = [
      [['bars', '#9fb8d8', 'balls (this run)'], ['line', '#c0392b', 'theory: ' + theoryN]],
      [['dot', '#1f4fb4', 'balls ± 1 snapshot’s s.e.'], ['line', '#c0392b', 'theory: ' + theoryT]],
    ];
    ctx.textAlign = 'right';
    ctx.textBaseline = 'middle';
    legends.forEach((lg, i) => {
      const right = panels[i].x0 + W - 4 * dpr;
      lg.forEach(([kind, colour, text], j) => {
        const y = mT + (8 + 15 * j) * dpr;
        ctx.fillStyle = '#333';
        ctx.fillText(text, right - 26 * dpr, y);
        ctx.fillStyle = colour;
        ctx.strokeStyle = colour;
        if (kind === 'bars') ctx.fillRect(right - 20 * dpr, y - 4 * dpr, 20 * dpr, 8 * dpr);
        else if (kind === 'dot') { ctx.beginPath(); ctx.arc(right - 10 * dpr, y, 2.5 * dpr, 0, 2 * Math.PI); ctx.fill(); }
        else { ctx.lineWidth = 2; ctx.beginPath(); ctx.moveTo(right - 20 * dpr, y); ctx.lineTo(right, y); ctx.stroke(); }
      });
    });
    app.profAxes = { panels: axes, legends: legends.map((lg) => lg.map((e) => e[2])) };
    ui.profileCap.textContent = 'profile along the field (' + P.bins + ' slabs of the height): ' +
      (field ? P.coupling + ' coupling, g = ' + fmt(P.g, 4) : 'no field') + ', c = ' +
      (isFinite(c) ? fmt(c, 4) : '∞') + '; fitted ' + (equiv ? 'kT₀ = ' : 'kT = ') + fmt(P.kTfit, 4) +
      '; averaged over engine time (weight e^(−Δt/τ), τ = ' + fmt(P.tau || 0, 3) + ') since t = ' +
      P.since.toFixed(1) + '; theory for the dilute gas of one mass';
  }

  function showReadouts() {
    const d = app.main.diag;
    $('r-time').textContent = d[WD.TIME].toFixed(4);
    $('r-coll').textContent = String(d[WD.COLL]);
    $('r-eerr').textContent = d[WD.EERR].toExponential(2);
    $('r-perr').textContent = d[WD.PERR].toExponential(2);
    $('r-ov').textContent = (100 * d[WD.OVSHARE]).toFixed(3) + ' % (' + d[WD.OVERLAPS] + ')';
    $('r-verdict').textContent = (VERDICTS[d[WD.VERDICT]] || '?') +
      (d[WD.VERDICT] === 1 || d[WD.PMODEL] > 0 ? ', p_model ' + d[WD.PMODEL].toPrecision(3) : '');
    $('r-gamma').textContent = d[WD.MEANG].toFixed(6);
    $('r-vmax').textContent = fmt(d[WD.VMAX], 4) + (isFinite(d[WD.C]) ? ' = ' + (d[WD.VMAX] / d[WD.C]).toFixed(4) + ' c' : '');
    $('r-fps').textContent = app.fps.toFixed(0);
    ui.capMain.textContent = 'c = ' + (isFinite(app.c) ? fmt(app.c, 4) : '∞') +
      ' (fastest ball ' + fmt(d[WD.VMAX], 4) + ') · t = ' + d[WD.TIME].toFixed(3);
    if (app.ref) ui.capRef.textContent = 'c = ∞ · t = ' + app.ref.diag[WD.TIME].toFixed(3);
  }

  // The slider's floor follows the fastest ball (its speed at c = inf, |p|/m, which every
  // c keeps it below); the thumb follows c, except while it is being dragged.
  function followSlider() {
    app.cMin = 1.01 * Math.max(app.main.diag[WD.PCLASS], 1e-300);
    if (!app.dragging) ui.c.value = String(sliderFor(app.c));
  }

  function draw() {
    if (!app.main) return;
    followSlider();
    drawWorld(app.main, ui.canvasMain);
    if (app.ref) drawWorld(app.ref, ui.canvasRef);
    drawHistogram();
    sampleProfile();
    drawProfile();
    drawColourKey();
    showReadouts();
  }

  function hover(e, cv) {
    const v = cv === ui.canvasRef ? app.ref : app.main;
    if (!v) return;
    const r = cv.getBoundingClientRect();
    const bx = v.diag[WD.BOXX], by = v.diag[WD.BOXY];
    const x = (e.clientX - r.left) / r.width * bx, y = (1 - (e.clientY - r.top) / r.height) * by;
    const b = v.balls;
    let best = -1, bestD = Infinity;
    for (let i = 0; i < v.diag[WD.N]; i++) {
      const o = i * WB.N, dx = b[o + WB.X] - x, dy = b[o + WB.Y] - y;
      const d2 = dx * dx + dy * dy;
      if (d2 < bestD && d2 <= b[o + WB.R] * b[o + WB.R] * 1.5) { bestD = d2; best = i; }
    }
    if (best < 0) { ui.tip.hidden = true; return; }
    const o = best * WB.N;
    ui.tip.textContent = 'ball ' + best + '\nproper time τ = ' + b[o + WB.TAU].toFixed(6) +
      '\nγ = ' + b[o + WB.GAMMA].toFixed(6) + '\nspeed ' + fmt(b[o + WB.SPEED], 4);
    ui.tip.style.left = (e.clientX + 14) + 'px';
    ui.tip.style.top = (e.clientY + 10) + 'px';
    ui.tip.hidden = false;
  }

  // ---- the loop: the engine brings every ball to the display time -----------------------

  let fpsT0 = null, fpsN = 0;
  function frame(now) {
    const w0 = performance.now();
    if (app.playing && app.main && !app.error) {
      const dt = app.lastNow === null ? 0 : Math.min(0.1, (now - app.lastNow) / 1000);
      advanceTo(app.t + dt * app.speed);
    }
    app.lastNow = now;
    if (fpsT0 === null) fpsT0 = now;
    fpsN++;
    if (now - fpsT0 >= 500) { app.fps = 1000 * fpsN / (now - fpsT0); fpsT0 = now; fpsN = 0; }
    app.frames++;
    draw();
    // the page's own work a frame (engine, read-outs, drawing), averaged
    app.workMs = 0.95 * app.workMs + 0.05 * (performance.now() - w0);
    requestAnimationFrame(frame);
  }

  // ---- what tests and scripts read (window.relcol) --------------------------------------

  function worldState(v) {
    const d = v.diag, b = v.balls, balls = [];
    for (let i = 0; i < d[WD.N]; i++) {
      const o = i * WB.N;
      balls.push({ x: b[o + WB.X], y: b[o + WB.Y], px: b[o + WB.PX], py: b[o + WB.PY],
                   r: b[o + WB.R], m: b[o + WB.M], tau: b[o + WB.TAU], gamma: b[o + WB.GAMMA],
                   speed: b[o + WB.SPEED], a: b[o + WB.A], b: b[o + WB.B], angle: b[o + WB.ANGLE] });
    }
    const named = {};
    for (const k of Object.keys(WD)) if (k !== 'COUNT') named[k.toLowerCase()] = d[WD[k]];
    named.c = isFinite(named.c) ? named.c : 'inf';
    return { diag: named, balls: balls };
  }

  window.relcol = {
    ready: false,
    state: () => ({
      t: app.t, playing: app.playing, split: app.split, speed: app.speed, cMin: app.cMin,
      fps: app.fps, frames: app.frames, workMs: app.workMs, error: app.error, scenario: app.source.name,
      main: worldState(app.main), ref: app.ref ? worldState(app.ref) : null,
      hist: app.hist ? Array.from(app.hist) : null, histAxes: app.histAxes || null,
      profile: profileState(), profileAxes: app.profAxes || null,
      field: { g: app.g, coupling: api.couplingName(app.coupling), gMax: app.gMax,
               message: ui.gMsg.hidden ? '' : ui.gMsg.textContent },
      colourKey: ui.keyText.textContent, colourKeyScale: !ui.keyScale.hidden,
    }),
    sliderFor: sliderFor,
    cFor: cFor,
    sliderForG: (g) => sliderForG(g),
    advanceTo: (t) => { const ok = advanceTo(t); draw(); return ok; },
    // bench_engine's set-up in the page: benchSetup makes and melts it (a handle), benchRun
    // times the measured part (wall clock; the caller may read CPU time around it)
    benchSetup: (dim, n, packing, c, frameName, melt) => {
      let frame = -1;
      for (let i = 0; i < api.frameCount(); i++) if (api.frameName(i) === frameName) frame = i;
      return api.benchSetup(dim, n, packing, c, frame, melt);
    },
    benchRun: (h, measure) => {
      const t0 = performance.now();
      const collisions = api.benchRun(h, measure);
      return { collisions: collisions, wall: (performance.now() - t0) / 1000 };
    },
    benchFree: (h) => api.benchFree(h),
  };

  setStatus('loading the library…');
  createRelcol().then((mod) => {
    M = mod;
    bind();
    fillTables();
    wire();
    load();
    showControls();
    draw();
    window.relcol.ready = true;
    requestAnimationFrame(frame);
  }, (err) => setStatus('cannot load the library: ' + err, true));
})();
