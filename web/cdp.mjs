// cdp.mjs — the part of playwright-core's API that test_web.mjs uses, over the Chrome
// DevTools Protocol with Debian's node-ws: no npm registry is needed, so the web suite runs
// on a bare Debian 12 from apt alone (issue 37). Chromium is Debian's /usr/bin/chromium.
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { createRequire } from 'node:module';

const require = createRequire(import.meta.url);
function loadWs() { // Debian's node-ws lives in /usr/share/nodejs, which a non-Debian node does not search
  try { return require('ws'); } catch { return require('/usr/share/nodejs/ws'); }
}
const WebSocket = loadWs();

class Session {
  constructor(ws) {
    this.ws = ws;
    this.id = 0;
    this.pending = new Map();
    this.handlers = new Map();
    ws.on('message', (data) => {
      const m = JSON.parse(data.toString());
      if (m.id !== undefined && this.pending.has(m.id)) {
        const { resolve, reject, method } = this.pending.get(m.id);
        this.pending.delete(m.id);
        if (m.error) reject(new Error(method + ': ' + m.error.message));
        else resolve(m.result);
      } else if (m.method) {
        for (const h of this.handlers.get(m.method) || []) h(m.params, m.sessionId);
      }
    });
    ws.on('close', () => {
      for (const { reject, method } of this.pending.values()) reject(new Error(method + ': the browser closed'));
      this.pending.clear();
    });
  }
  send(method, params = {}, sessionId) {
    const id = ++this.id;
    const msg = { id, method, params };
    if (sessionId) msg.sessionId = sessionId;
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject, method });
      this.ws.send(JSON.stringify(msg));
    });
  }
  on(method, fn) {
    if (!this.handlers.has(method)) this.handlers.set(method, []);
    this.handlers.get(method).push(fn);
  }
  once(method, pred = () => true) {
    return new Promise((resolve) => {
      const fn = (p, s) => {
        if (!pred(p, s)) return;
        this.handlers.set(method, this.handlers.get(method).filter((h) => h !== fn));
        resolve(p);
      };
      this.on(method, fn);
    });
  }
}

const q = (sel) => `document.querySelector(${JSON.stringify(sel)})`;

class Locator {
  constructor(page, sel) { this.page = page; this.sel = sel; }
  async boundingBox() {
    return this.page._value(`(() => { const r = ${q(this.sel)}.getBoundingClientRect();
      return { x: r.x, y: r.y, width: r.width, height: r.height }; })()`);
  }
  innerText() { return this.page._value(`${q(this.sel)}.innerText`); }
  allInnerTexts() {
    return this.page._value(`Array.from(document.querySelectorAll(${JSON.stringify(this.sel)}), (e) => e.innerText)`);
  }
}

class Page {
  constructor(cdp, sessionId, viewport) {
    this.cdp = cdp;
    this.sid = sessionId;
    this.viewport = viewport;
    this.listeners = { console: [], pageerror: [], requestfailed: [] };
    this.requests = new Map();
    this.mouse = { move: (x, y) => this._send('Input.dispatchMouseEvent', { type: 'mouseMoved', x, y }) };
    const mine = (f) => (p, s) => { if (s === this.sid) f(p); };
    cdp.on('Runtime.consoleAPICalled', mine((p) => {
      const text = p.args.map((a) => (a.value !== undefined ? String(a.value) : a.description || '')).join(' ');
      const type = p.type === 'warning' ? 'warning' : p.type;
      for (const f of this.listeners.console) f({ type: () => type, text: () => text });
    }));
    cdp.on('Runtime.exceptionThrown', mine((p) => {
      const d = p.exceptionDetails;
      const message = (d.exception && d.exception.description) || d.text;
      for (const f of this.listeners.pageerror) f({ message });
    }));
    cdp.on('Log.entryAdded', mine((p) => { // the browser's own messages (a failed load, a blocked script)
      if (p.entry.level !== 'error') return;
      for (const f of this.listeners.console) f({ type: () => 'error', text: () => p.entry.text });
    }));
    cdp.on('Network.requestWillBeSent', mine((p) => this.requests.set(p.requestId, p.request.url)));
    cdp.on('Network.loadingFailed', mine((p) => {
      const u = this.requests.get(p.requestId) || '?';
      for (const f of this.listeners.requestfailed) f({ url: () => u });
    }));
  }
  _send(method, params) { return this.cdp.send(method, params, this.sid); }
  async _init() {
    await this._send('Page.enable');
    await this._send('Runtime.enable');
    await this._send('Network.enable');
    await this._send('DOM.enable');
    await this._send('Log.enable');
    await this._send('Emulation.setDeviceMetricsOverride', {
      width: this.viewport.width, height: this.viewport.height, deviceScaleFactor: 1, mobile: false });
  }
  on(ev, f) { this.listeners[ev].push(f); }
  async _value(expression) {
    const r = await this._send('Runtime.evaluate', { expression, awaitPromise: true, returnByValue: true });
    if (r.exceptionDetails) {
      const d = r.exceptionDetails;
      throw new Error((d.exception && d.exception.description) || d.text);
    }
    return r.result.value;
  }
  evaluate(fn, arg) {
    return this._value(`(${fn.toString()})(${arg === undefined ? '' : JSON.stringify(arg)})`);
  }
  async goto(url) {
    const loaded = this.cdp.once('Page.loadEventFired', (p, s) => s === this.sid);
    const r = await this._send('Page.navigate', { url });
    if (r.errorText) throw new Error('goto ' + url + ': ' + r.errorText);
    await loaded;
  }
  async _el(sel, body) {
    return this._value(`(() => { const el = ${q(sel)};
      if (!el) throw new Error('no element ' + ${JSON.stringify(sel)}); ${body} })()`);
  }
  click(sel) { return this._el(sel, 'el.scrollIntoView({ block: "nearest" }); el.click();'); }
  check(sel) { return this._el(sel, 'if (!el.checked) el.click();'); }
  uncheck(sel) { return this._el(sel, 'if (el.checked) el.click();'); }
  textContent(sel) { return this._el(sel, 'return el.textContent;'); }
  locator(sel) { return new Locator(this, sel); }
  selectOption(sel, want) {
    const w = typeof want === 'string' ? { value: want } : want;
    return this._el(sel, `const w = ${JSON.stringify(w)};
      const o = Array.from(el.options).find((o) => (w.label !== undefined ? o.label === w.label : o.value === w.value));
      if (!o) throw new Error('no option ' + JSON.stringify(w) + ' in ' + ${JSON.stringify(sel)});
      el.value = o.value;
      el.dispatchEvent(new Event('input', { bubbles: true }));
      el.dispatchEvent(new Event('change', { bubbles: true }));`);
  }
  async setInputFiles(sel, file) {
    const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'relcol-upload-'));
    const p = path.join(dir, file.name);
    fs.writeFileSync(p, file.buffer);
    const { root } = await this._send('DOM.getDocument', { depth: 0 });
    const { nodeId } = await this._send('DOM.querySelector', { nodeId: root.nodeId, selector: sel });
    if (!nodeId) throw new Error('no element ' + sel);
    await this._send('DOM.setFileInputFiles', { nodeId, files: [p] });
  }
  waitForTimeout(ms) { return new Promise((r) => setTimeout(r, ms)); }
  async screenshot({ path: file }) {
    const r = await this._send('Page.captureScreenshot', { format: 'png' });
    const tmp = file + '.part';
    fs.writeFileSync(tmp, Buffer.from(r.data, 'base64'));
    fs.renameSync(tmp, file);
  }
}

class Context {
  constructor(proc, cdp, viewport) { this.proc = proc; this.cdp = cdp; this.viewport = viewport; this.list = []; }
  pages() { return this.list; }
  async _attach(targetId) {
    const { sessionId } = await this.cdp.send('Target.attachToTarget', { targetId, flatten: true });
    const p = new Page(this.cdp, sessionId, this.viewport);
    await p._init();
    this.list.push(p);
    return p;
  }
  async newPage() {
    const { targetId } = await this.cdp.send('Target.createTarget', { url: 'about:blank' });
    return this._attach(targetId);
  }
  async close() {
    try { await this.cdp.send('Browser.close'); } catch { /* already gone */ }
    await new Promise((r) => {
      if (this.proc.exitCode !== null) return r();
      const t = setTimeout(() => { this.proc.kill('SIGKILL'); r(); }, 5000);
      this.proc.on('exit', () => { clearTimeout(t); r(); });
    });
  }
}

async function launchPersistentContext(profile, opts) {
  const args = [...(opts.args || []), `--user-data-dir=${profile}`, '--remote-debugging-port=0',
                `--window-size=${opts.viewport.width},${opts.viewport.height}`, 'about:blank'];
  if (opts.headless !== false) args.unshift('--headless=new');
  const proc = spawn(opts.executablePath, args, { stdio: ['ignore', 'ignore', 'pipe'] });
  const wsUrl = await new Promise((resolve, reject) => {
    let err = '';
    const t = setTimeout(() => reject(new Error('chromium did not start in 60 s: ' + err.slice(-500))), 60000);
    proc.stderr.on('data', (d) => {
      err += d.toString();
      const m = err.match(/DevTools listening on (ws:\/\/\S+)/);
      if (m) { clearTimeout(t); resolve(m[1]); }
    });
    proc.on('exit', (c) => { clearTimeout(t); reject(new Error('chromium exited (' + c + '): ' + err.slice(-500))); });
  });
  proc.stderr.resume();
  const ws = new WebSocket(wsUrl, { perMessageDeflate: false, maxPayload: 1 << 30 });
  await new Promise((resolve, reject) => { ws.once('open', resolve); ws.once('error', reject); });
  const cdp = new Session(ws);
  const ctx = new Context(proc, cdp, opts.viewport || { width: 1280, height: 720 });
  const { targetInfos } = await cdp.send('Target.getTargets');
  const first = targetInfos.find((t) => t.type === 'page');
  if (first) await ctx._attach(first.targetId);
  return ctx;
}

export const chromium = { launchPersistentContext };
