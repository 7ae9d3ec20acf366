// strew studio front end: the scene canvas, the tools, the websocket and the status bar.
// Everything here only draws and sends JSON data; the server does the synthesis.

import { View, Elements, Library, drawElements, drawPolyline, drawArrows } from "./render.js";
import { PaletteEditor } from "./palette.js";

const $ = (id) => document.getElementById(id);
const canvas = $("scene");
const ctx = canvas.getContext("2d");

const studio = {
  lib: new Library(),
  scene: new Elements(),
  view: new View(),
  tool: "brush",
  strokes: { flow: [], boundary: [], arrows: [], arrow_length: 10, region: [] },
  palette: { exemplars: [], selection: [] },
  layers: [],          // [{name, count, hidden, locked}] in drawing order
  files: { files: [], examples: [] },
  live: null,          // the stroke being drawn: {tool, points}
  cursor: null,        // world position of the pointer
  errors: [],          // error messages received (for tests)
  messages: [],        // status messages received
  counts: [],          // element counts of the status messages received (tests: the count never goes back)
  frames: 0,
  stats: { strokeStart: null, countAtStart: 0, firstFrame: null, lastFrame: null, added: 0, rate: null },
  connected: false,
  pending: new Map(),
  repeat: null,        // the repeat view's tile [x0, y0, W, H] (issue 18.4), or null
  copiesDrawn: 0,      // tile copies drawn in the last full redraw (1, or 9 in the repeat view)
};
window.studio = studio;

// ------------------------------------------------------------------ websocket
let ws = null;
let nextId = 1;
function connect() {
  const proto = location.protocol === "https:" ? "wss:" : "ws:";
  ws = new WebSocket(`${proto}//${location.host}/ws`);
  ws.onopen = () => { studio.connected = true; setConn("connected", "ok"); send({ type: "hello" }); };
  ws.onclose = () => { studio.connected = false; setConn("disconnected", "bad"); };
  ws.onmessage = (ev) => { let m; try { m = JSON.parse(ev.data); } catch { return; } onMessage(m); };
}
function send(msg) {
  if (!ws || ws.readyState !== 1) return null;
  const id = nextId++;
  ws.send(JSON.stringify({ ...msg, id }));
  return id;
}
// Send and resolve when the server says the message is done (or failed).
function request(msg) {
  return new Promise((resolve) => {
    const id = send(msg);
    if (id === null) { resolve({ type: "error", message: "not connected" }); return; }
    studio.pending.set(id, resolve);
  });
}
studio.send = send;
studio.request = request;
function setConn(text, cls) { const el = $("st-conn"); el.textContent = text; el.className = "conn " + cls; }

function onMessage(m) {
  switch (m.type) {
    case "shapes": studio.lib.set(m); paletteEditor.libraryChanged(); invalidate(); break;
    case "scene": onScene(m); break;
    case "palette": studio.palette = m; renderPaletteList(); paletteEditor.update(m); break;
    case "strokes": studio.strokes = m; invalidate(); break;
    case "controls": buildControls(m.controls); break;
    case "files": studio.files = m; renderFiles(); break;
    case "layers": studio.layers = m.layers; renderLayers(); invalidate(); break;
    case "status": onStatus(m); break;
    case "error":
      studio.errors.push(m.message); showMessage(m.message, true);
      if (m.ref === "stroke_start") { studio.live = null; studio.stats.tracking = false; buffer = []; dirty(); }
      resolvePending(m.id, m); break;
    case "done":
      if (m.ref === "stroke_end") { studio.stats.tracking = false; if (studio.status) showRate(studio.status.rate); }
      // elements that streamed in were drawn on top; redraw in layer order
      if ((m.ref === "stroke_end" || m.ref === "fill") && studio.layers.length) invalidate();
      resolvePending(m.id, m); break;
    case "exported": studio.lastExport = m; break;
    case "saved": studio.lastSave = m; break;
    default: break;
  }
}
function resolvePending(id, m) {
  if (id !== null && id !== undefined && studio.pending.has(id)) {
    const f = studio.pending.get(id); studio.pending.delete(id); f(m);
  }
}

function onScene(m) {
  const before = studio.scene.n;
  if (m.op === "replace") { studio.scene.replace(m); cache.valid = false; }
  else {
    if (m.update.index.length) { studio.scene.update(m.update); cache.valid = false; }
    if (m.append.k.length) studio.scene.append(m.append);
  }
  const grew = studio.scene.n > before;
  if (studio.stats.tracking && grew) studio.stats.pendingArrival = true;
  dirty();
}

function onStatus(m) {
  $("st-count").textContent = `${m.count} elements`;
  studio.counts.push(m.count);
  // elements/s of the last fill or stroke, as the server measured it (a live figure while painting)
  if (!studio.stats.tracking) showRate(m.rate);
  showFidelity(m.fidelity);
  setRepeat(m.repeat || null);
  const clip = $("clip");
  clip.hidden = !(m.outside > 0);
  clip.textContent = `Clip ${m.outside} outside`;
  $("undo").disabled = !m.undo; $("redo").disabled = !m.redo;
  if (m.message) { studio.messages.push(m.message); showMessage(m.message, false); }
  studio.status = m;
}
function showRate(rate) { $("st-rate").textContent = rate === null || rate === undefined ? "– el/s" : `${Math.round(rate)} el/s`; }
// The fidelity verdict (strew.metrics.fidelity) of the last fill or stroke, or nothing.
function showFidelity(f) {
  const el = $("st-fid");
  if (!f) { el.textContent = ""; el.className = ""; el.title = "no fidelity verdict (several exemplars selected, or too small an area)"; return; }
  if (f.faithful) { el.textContent = `faithful to ${f.exemplar}`; el.className = "ok"; el.title = `strew.metrics.fidelity: every metric passed (${f.count} elements)`; return; }
  const shown = f.failures.slice(0, 3).join(", ") + (f.failures.length > 3 ? `, +${f.failures.length - 3}` : "");
  el.textContent = `not faithful to ${f.exemplar}: ${shown}`; el.className = "bad";
  el.title = "strew.metrics.fidelity failed: " + f.failures.join(", ");
}
function showMessage(text, isError) {
  const el = $("st-msg"); el.textContent = text; el.className = isError ? "error" : "";
}

// ------------------------------------------------------------------ drawing
let needsDraw = true;
function dirty() { if (!needsDraw) { needsDraw = true; requestAnimationFrame(draw); } }
function resize() {
  const dpr = window.devicePixelRatio || 1;
  const r = canvas.getBoundingClientRect();
  canvas.width = Math.max(1, Math.round(r.width * dpr));
  canvas.height = Math.max(1, Math.round(r.height * dpr));
  needsDraw = false; invalidate();
}
function regionBounds() {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const ring of studio.strokes.region) for (const [x, y] of ring) { x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y); }
  return isFinite(x0) ? [x0, y0, x1, y1] : [0, 0, 800, 600];
}
function fit() {
  const r = canvas.getBoundingClientRect();
  let b = regionBounds();
  const t = studio.repeat;
  if (t) b = [t[0] - t[2], t[1] - t[3], t[0] + 2 * t[2], t[1] + 2 * t[3]];  // the 3 x 3 block
  studio.view.fit(b, r.width, r.height); invalidate();
}
// The repeat view: the canvas tiled 3 x 3, the centre tile live and its copies around it
// (the server wraps the strokes; here it is only drawing).
function setRepeat(tile) {
  const was = studio.repeat;
  studio.repeat = tile;
  $("repeat").classList.toggle("active", !!tile);
  $("repeat").setAttribute("aria-pressed", tile ? "true" : "false");
  canvas.dataset.repeat = tile ? "3x3" : "off";
  if (JSON.stringify(was) !== JSON.stringify(tile)) fit();
}
// world offsets of the tile copies to draw: the centre last (on top)
function tileOffsets() {
  const t = studio.repeat;
  if (!t) return [[0, 0]];
  const out = [];
  for (let j = -1; j <= 1; j++) for (let i = -1; i <= 1; i++) if (i || j) out.push([i * t[2], j * t[3]]);
  out.push([0, 0]);
  return out;
}
const COPY_ALPHA = 0.55;
function shifted(view, dx, dy) { return { zoom: view.zoom, ox: view.ox + view.zoom * dx, oy: view.oy + view.zoom * dy, toScreen: (x, y) => view.toScreen(x + dx, y + dy) }; }
let shownZoom = null;
function showZoom() {
  const z = studio.view.zoom;
  if (z === shownZoom) return;
  shownZoom = z;
  $("st-zoom").textContent = `zoom ${z >= 10 ? Math.round(z * 100) : +(z * 100).toPrecision(3)}%`;
}
studio.fit = fit;
// draw one frame now; returns its duration in ms (benchmarks)
// (reading a pixel makes the browser rasterise the recorded drawing, so that it is timed too)
studio.drawNow = (full = false) => {
  if (full) cache.valid = false;
  const t = performance.now(); draw(t); ctx.getImageData(0, 0, 1, 1);
  return performance.now() - t;
};

// The region, the flow arrows and the elements are drawn into an offscreen layer at one
// view. Panning only moves the layer (redrawn once the pan rests); elements that stream in
// are drawn onto it without redrawing the others; anything else redraws it.
const layer = document.createElement("canvas");
const lctx = layer.getContext("2d");
const cache = { valid: false, zoom: 0, ox: 0, oy: 0, n: 0, w: 0, h: 0 };
function invalidate() { cache.valid = false; dirty(); }
studio.invalidate = invalidate;

function drawLayer(view, w, h, dpr) {
  if (layer.width !== canvas.width || layer.height !== canvas.height) { layer.width = canvas.width; layer.height = canvas.height; }
  const g = lctx;
  g.setTransform(dpr, 0, 0, dpr, 0, 0);
  g.clearRect(0, 0, w, h);
  const offsets = tileOffsets();
  // region: white inside, dashed outline (each copy of the tile in the repeat view)
  g.fillStyle = "#fff"; g.beginPath();
  for (const [dx, dy] of offsets) {
    for (const ring of studio.strokes.region) {
      ring.forEach(([x, y], i) => { const [sx, sy] = view.toScreen(x + dx, y + dy); i ? g.lineTo(sx, sy) : g.moveTo(sx, sy); });
      g.closePath();
    }
  }
  g.fill(offsets.length > 1 ? "nonzero" : "evenodd");
  g.setLineDash([5, 4]); g.strokeStyle = "#999"; g.lineWidth = 1;
  for (const [dx, dy] of offsets) for (const ring of studio.strokes.region) drawPolyline(g, shifted(view, dx, dy), ring, true);
  g.setLineDash([]);
  // flow field arrows under the elements
  if (studio.strokes.arrows.length) { g.strokeStyle = "rgba(40,110,200,.45)"; g.lineWidth = 1; drawArrows(g, view, studio.strokes.arrows, studio.strokes.arrow_length); }
  for (const [dx, dy] of offsets) {
    const copy = dx !== 0 || dy !== 0;
    drawElements(g, studio.lib, studio.scene, shifted(view, dx, dy), w, h, dpr, copy ? { ...layerOpts(), alpha: COPY_ALPHA } : layerOpts());
  }
  studio.copiesDrawn = offsets.length;
  Object.assign(cache, { valid: true, zoom: view.zoom, ox: view.ox, oy: view.oy, n: studio.scene.n, w: canvas.width, h: canvas.height });
}

function draw(t) {
  needsDraw = false;
  const dpr = window.devicePixelRatio || 1;
  const w = canvas.width / dpr, h = canvas.height / dpr;
  const view = studio.view;
  const sameView = cache.valid && cache.zoom === view.zoom && cache.w === canvas.width && cache.h === canvas.height;
  if (!sameView || studio.scene.n < cache.n) drawLayer(view, w, h, dpr);
  else if (studio.scene.n > cache.n) {
    const at = { zoom: cache.zoom, ox: cache.ox, oy: cache.oy, toScreen: (x, y) => [cache.zoom * x + cache.ox, cache.zoom * y + cache.oy] };
    for (const [dx, dy] of tileOffsets()) {
      const copy = dx !== 0 || dy !== 0;
      drawElements(lctx, studio.lib, studio.scene, shifted(at, dx, dy), w, h, dpr, { ...layerOpts(), from: cache.n, ...(copy ? { alpha: COPY_ALPHA } : {}) });
    }
    cache.n = studio.scene.n;
  }
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.fillStyle = "#eceae4"; ctx.fillRect(0, 0, canvas.width, canvas.height);
  ctx.drawImage(layer, Math.round((view.ox - cache.ox) * dpr), Math.round((view.oy - cache.oy) * dpr));
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  // flow and boundary strokes
  ctx.lineWidth = 2; ctx.strokeStyle = "rgba(40,110,200,.9)";
  for (const s of studio.strokes.flow) drawPolyline(ctx, view, s);
  ctx.strokeStyle = "rgba(200,40,40,.9)"; ctx.lineWidth = 3;
  for (const s of studio.strokes.boundary) drawPolyline(ctx, view, s);
  // the stroke being drawn and the brush outline
  if (studio.live) {
    const colors = { brush: "rgba(60,120,220,.5)", spray: "rgba(60,160,90,.5)", erase: "rgba(220,60,60,.5)", flow: "rgba(40,110,200,.9)", boundary: "rgba(200,40,40,.9)", region: "rgba(80,80,80,.9)" };
    ctx.strokeStyle = colors[studio.live.tool] || "#333"; ctx.lineWidth = 1.5;
    drawPolyline(ctx, view, studio.live.points, studio.live.tool === "region");
  }
  if (studio.cursor && ["brush", "spray", "erase"].includes(studio.tool)) {
    const [sx, sy] = view.toScreen(studio.cursor[0], studio.cursor[1]);
    ctx.strokeStyle = "rgba(0,0,0,.35)"; ctx.lineWidth = 1; ctx.beginPath();
    ctx.arc(sx, sy, radius() * view.zoom, 0, 2 * Math.PI); ctx.stroke();
  }
  studio.frames++;
  showZoom();
  // the first frame that shows elements of a stroke: latency and rate (status bar)
  const st = studio.stats;
  if (st.pendingArrival) {
    st.pendingArrival = false;
    const now = performance.now();
    if (st.firstFrame === null) st.firstFrame = now;
    st.lastFrame = now;
    st.added = studio.scene.n - st.countAtStart;
    const dt = (now - st.strokeStart) / 1000;
    if (dt > 0 && st.added > 0) { st.rate = st.added / dt; $("st-rate").textContent = `${Math.round(st.rate)} el/s`; }
  }
}

// ------------------------------------------------------------------ tools
function radius() { return +$("radius").value; }
// layers: drawing order and hidden kinds, as library indices
function layerOpts() {
  const index = new Map(studio.lib.kinds.map((k, i) => [k, i]));
  const order = studio.layers.map((l) => index.get(l.name)).filter((i) => i !== undefined);
  for (let i = 0; i < studio.lib.kinds.length; i++) if (!order.includes(i)) order.push(i);
  return { order, hidden: new Set(studio.layers.filter((l) => l.hidden).map((l) => index.get(l.name))) };
}
function sendLayers(layers) {
  send({ type: "layers", order: layers.map((l) => l.name), hidden: layers.filter((l) => l.hidden).map((l) => l.name), locked: layers.filter((l) => l.locked).map((l) => l.name) });
}
function renderLayers() {
  const ul = $("layers"); ul.innerHTML = "";
  studio.layers.forEach((layer, i) => {
    const li = document.createElement("li"); li.dataset.name = layer.name; li.classList.toggle("hidden", layer.hidden);
    const vis = document.createElement("input"); vis.type = "checkbox"; vis.checked = !layer.hidden; vis.title = "show"; vis.className = "show";
    const lock = document.createElement("input"); lock.type = "checkbox"; lock.checked = layer.locked; lock.title = "lock: the eraser and Clip keep it"; lock.className = "lock";
    const name = document.createElement("span"); name.className = "name"; name.textContent = layer.name;
    const count = document.createElement("span"); count.className = "count"; count.textContent = layer.count;
    const up = document.createElement("button"); up.textContent = "▲"; up.title = "draw earlier (below)"; up.className = "up"; up.disabled = i === 0;
    const down = document.createElement("button"); down.textContent = "▼"; down.title = "draw later (on top)"; down.className = "down"; down.disabled = i === studio.layers.length - 1;
    const change = (f) => { const ls = studio.layers.map((l) => ({ ...l })); f(ls); sendLayers(ls); };
    vis.addEventListener("change", () => change((ls) => { ls[i].hidden = !vis.checked; }));
    lock.addEventListener("change", () => change((ls) => { ls[i].locked = lock.checked; }));
    up.addEventListener("click", () => change((ls) => { [ls[i - 1], ls[i]] = [ls[i], ls[i - 1]]; }));
    down.addEventListener("click", () => change((ls) => { [ls[i + 1], ls[i]] = [ls[i], ls[i + 1]]; }));
    li.append(vis, lock, name, count, up, down);
    ul.appendChild(li);
  });
}
function toggleHelp(show) { const h = $("help"); h.hidden = show === undefined ? !h.hidden : !show; }
studio.toggleHelp = toggleHelp;
function setTool(t) {
  studio.tool = t;
  for (const b of document.querySelectorAll("#tools button")) b.classList.toggle("active", b.dataset.tool === t);
  dirty();
}
studio.setTool = setTool;
for (const b of document.querySelectorAll("#tools button")) b.addEventListener("click", () => setTool(b.dataset.tool));
$("radius").addEventListener("input", () => { $("radius-out").textContent = $("radius").value; dirty(); });
$("density").addEventListener("input", () => { $("density-out").textContent = `${Math.round(+$("density").value * 100)}%`; });
$("density").addEventListener("change", () => send({ type: "settings", brush_density: +$("density").value }));
$("clip").addEventListener("click", () => send({ type: "clip" }));
$("help-button").addEventListener("click", () => toggleHelp());
$("help").addEventListener("click", (ev) => { if (ev.target === $("help")) toggleHelp(false); });
// Parameter controls come from the methods' specs (the "controls" message): one input per
// control, drawn once; an input already in the page (the density slider) only takes the
// declared bounds and help.
function buildControls(list) {
  const box = $("method-controls");
  for (const c of list) {
    const title = [c.help, c.unit, c.section].filter(Boolean).join("; ");
    let el = $(c.id);
    if (el) {
      if (c.low !== null) el.min = c.low;
      if (c.high !== null) el.max = c.high;
      el.title = title;
      continue;
    }
    if (c.choices) {
      el = document.createElement("select");
      for (const v of c.choices) { const o = document.createElement("option"); o.textContent = v; el.appendChild(o); }
      el.value = c.default;
    } else {
      el = document.createElement("input");
      el.type = "number";
      el.size = 3;
      if (c.low !== null) el.min = c.low;
      if (c.high !== null) el.max = c.high;
      el.step = c.unit === "degrees" ? 5 : (c.type === "int" ? 1 : 0.05);
      el.value = c.default ?? "";
    }
    el.id = c.id;
    el.title = title;
    el.dataset.key = c.key;
    el.addEventListener("change", () => send({ type: "settings", [c.key]: c.choices ? el.value : (+el.value || 0) }));
    const label = document.createElement("label");
    label.textContent = `${c.method} ${c.name.replace(/_/g, " ")}${c.unit === "degrees" ? " °" : ""} `;
    label.title = title;
    label.appendChild(el);
    box.appendChild(label);
  }
}
$("undo").addEventListener("click", () => send({ type: "undo" }));
$("redo").addEventListener("click", () => send({ type: "redo" }));
$("stop").addEventListener("click", () => send({ type: "stop" }));
$("fit").addEventListener("click", fit);
function toggleRepeat() { send({ type: "settings", repeat: !studio.repeat }); }
studio.toggleRepeat = toggleRepeat;
$("repeat").addEventListener("click", toggleRepeat);
$("clear").addEventListener("change", () => { const v = $("clear").value; if (v) send({ type: "clear", what: v }); $("clear").value = ""; });
$("save").addEventListener("click", () => send({ type: "save" }));
$("load").addEventListener("click", () => send({ type: "load_project" }));
$("export").addEventListener("click", () => send({ type: "export", path: $("export-name").value.trim() }));

let panning = null;
let panTimer = 0;
// pointer capture keeps a stroke going outside the canvas (synthetic events have no capture)
function capture(ev) { try { canvas.setPointerCapture(ev.pointerId); } catch { /* not an active pointer */ } }
let buffer = [];      // stroke points not sent yet
let flushQueued = false;
function eventWorld(ev) { const r = canvas.getBoundingClientRect(); return studio.view.toWorld(ev.clientX - r.left, ev.clientY - r.top); }
const r3 = (p) => [Math.round(p[0] * 1000) / 1000, Math.round(p[1] * 1000) / 1000];

function flush() {
  flushQueued = false;
  if (!studio.live || !buffer.length) return;
  const msg = { type: "stroke_move", points: buffer };
  if (penPressure !== null) msg.pressure = penPressure;  // a pen scales the brush density
  send(msg); buffer = [];
}
let penPressure = null;  // the pen's pressure during a stroke (null for a mouse or touch)
canvas.addEventListener("pointerdown", (ev) => {
  canvas.focus();
  const p = r3(eventWorld(ev));
  if (ev.button === 1 || studio.tool === "pan" || spaceDown) {
    panning = { x: ev.clientX, y: ev.clientY, ox: studio.view.ox, oy: studio.view.oy };
    capture(ev); return;
  }
  if (ev.button !== 0) return;
  if (studio.tool === "fill") { send({ type: "fill", point: [p] }); return; }
  capture(ev);
  studio.live = { tool: studio.tool, points: [p] };
  const st = studio.stats;
  Object.assign(st, { strokeStart: performance.now(), countAtStart: studio.scene.n, firstFrame: null, lastFrame: null, added: 0, rate: null, pendingArrival: false, tracking: true });
  buffer = [];
  penPressure = ev.pointerType === "pen" ? Math.min(1, Math.max(0, ev.pressure)) : null;
  const start = { type: "stroke_start", tool: studio.tool, radius: radius(), points: [p] };
  if (penPressure !== null) start.pressure = penPressure;
  send(start);
  dirty();
});
canvas.addEventListener("pointermove", (ev) => {
  studio.cursor = eventWorld(ev);
  if (panning) {
    studio.view.ox = panning.ox + ev.clientX - panning.x; studio.view.oy = panning.oy + ev.clientY - panning.y;
    clearTimeout(panTimer); panTimer = setTimeout(invalidate, 120);
    dirty(); return;
  }
  if (studio.live) {
    if (penPressure !== null) penPressure = Math.min(1, Math.max(0, ev.pressure));
    const p = r3(studio.cursor);
    const last = studio.live.points[studio.live.points.length - 1];
    if (Math.hypot(p[0] - last[0], p[1] - last[1]) * studio.view.zoom < 2) { dirty(); return; }
    studio.live.points.push(p); buffer.push(p);
    // one segment per animation frame at most; the server merges segments it cannot keep up with
    if (!flushQueued) { flushQueued = true; requestAnimationFrame(flush); }
  }
  dirty();
});
function endStroke(ev) {
  if (panning) { panning = null; return; }
  if (!studio.live) return;
  send({ type: "stroke_end", points: buffer }); buffer = [];
  studio.live = null; dirty();
}
canvas.addEventListener("pointerup", endStroke);
canvas.addEventListener("pointercancel", endStroke);
canvas.addEventListener("pointerleave", () => { studio.cursor = null; dirty(); });
canvas.addEventListener("wheel", (ev) => {
  ev.preventDefault();
  const r = canvas.getBoundingClientRect();
  studio.view.zoomAt(ev.clientX - r.left, ev.clientY - r.top, Math.exp(-ev.deltaY * 0.0015));
  dirty();
}, { passive: false });

let spaceDown = false;
const keys = { b: "brush", s: "spray", f: "fill", e: "erase", w: "flow", o: "boundary", r: "region" };
window.addEventListener("keydown", (ev) => {
  if (ev.target.tagName === "INPUT" || ev.target.tagName === "SELECT") return;
  if (ev.key === "?") { toggleHelp(); ev.preventDefault(); return; }
  if (ev.key === "Escape") { toggleHelp(false); return; }
  if ((ev.ctrlKey || ev.metaKey) && ev.key.toLowerCase() === "z") { send({ type: ev.shiftKey ? "redo" : "undo" }); ev.preventDefault(); return; }
  if ((ev.ctrlKey || ev.metaKey) && ev.key.toLowerCase() === "y") { send({ type: "redo" }); ev.preventDefault(); return; }
  if (ev.key === " ") { spaceDown = true; ev.preventDefault(); return; }
  if (!ev.ctrlKey && !ev.metaKey && ev.key === "t") { toggleRepeat(); return; }
  if (!ev.ctrlKey && !ev.metaKey && keys[ev.key]) setTool(keys[ev.key]);
});
window.addEventListener("keyup", (ev) => { if (ev.key === " ") spaceDown = false; });

// ------------------------------------------------------------------ palette list and files
function renderFiles() {
  const sel = $("files"); const keep = sel.value; sel.innerHTML = "";
  for (const f of studio.files.examples) { const o = document.createElement("option"); o.value = "example:" + f; o.textContent = "example: " + f; sel.appendChild(o); }
  for (const f of studio.files.files) { const o = document.createElement("option"); o.value = "file:" + f; o.textContent = f; sel.appendChild(o); }
  if (keep) sel.value = keep;
}
$("load-exemplar").addEventListener("click", () => {
  const v = $("files").value; if (!v) return;
  const [kind, ...rest] = v.split(":"); const name = rest.join(":");
  send(kind === "example" ? { type: "load_exemplar", example: name } : { type: "load_exemplar", path: name });
});
function renderPaletteList() {
  const ul = $("exemplars"); ul.innerHTML = "";
  for (const ex of studio.palette.exemplars) {
    const li = document.createElement("li");
    li.dataset.name = ex.name;
    li.classList.toggle("active", ex.name === paletteEditor.active);
    const cb = document.createElement("input"); cb.type = "checkbox"; cb.checked = ex.selected; cb.title = "use in synthesis (select one or several)";
    cb.addEventListener("click", (e) => {
      e.stopPropagation();
      const names = studio.palette.exemplars.filter((x) => (x.name === ex.name ? cb.checked : x.selected)).map((x) => x.name);
      send({ type: "select", names });
    });
    const label = document.createElement("span"); label.textContent = ex.name;
    const count = document.createElement("span"); count.className = "count"; count.textContent = ex.n;
    li.append(cb, label, count);
    li.addEventListener("click", () => { paletteEditor.setActive(ex.name); renderPaletteList(); });
    ul.appendChild(li);
  }
}
$("new-exemplar").addEventListener("click", () => send({ type: "palette_new", name: "exemplar" }));
$("from-scene").addEventListener("click", () => send({ type: "palette_from_scene", name: "painted" }));
$("remove-exemplar").addEventListener("click", () => { if (paletteEditor.active) send({ type: "palette_remove", exemplar: paletteEditor.active }); });

const paletteEditor = new PaletteEditor($("palette-canvas"), studio, send, {
  title: $("editor-title"), note: $("palette-note"), kind: $("place-kind"), radiusField: $("radius-field"),
  radiusValue: $("radius-value"), showEdges: $("show-edges"), tools: document.querySelectorAll("#edit-tools button"), brushRadius: radius,
});
studio.paletteEditor = paletteEditor;

// ------------------------------------------------------------------ start
window.addEventListener("resize", () => { resize(); });
setTool("brush");
resize();
let fitted = false;
connect();
// fit the view to the region once the first strokes message arrived
const fitTimer = setInterval(() => { if (studio.strokes.region.length && !fitted) { fitted = true; fit(); clearInterval(fitTimer); } }, 30);
