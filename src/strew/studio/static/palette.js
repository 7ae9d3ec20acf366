// The exemplar editor of the palette panel: shows one exemplar with its per-element radii
// and connectivity edges, and edits it by hand (place, move, delete, radius, flip an edge)
// or paints the selected texture into it (Davison §5.5).

import { View, Elements, drawElements } from "./render.js";

export class PaletteEditor {
  constructor(canvas, studio, send, ui) {
    this.canvas = canvas; this.ctx = canvas.getContext("2d");
    this.studio = studio; this.send = send; this.ui = ui;
    this.view = new View(); this.els = new Elements();
    this.active = null; this.ex = null; this.tool = "move";
    this.drag = null; this.paint = null;
    for (const b of ui.tools) b.addEventListener("click", () => this.setTool(b.dataset.etool));
    ui.showEdges.addEventListener("change", () => this.draw());
    canvas.addEventListener("pointerdown", (e) => this.down(e));
    canvas.addEventListener("pointermove", (e) => this.move(e));
    canvas.addEventListener("pointerup", (e) => this.up(e));
    this.setTool("move");
  }
  setTool(t) { this.tool = t; for (const b of this.ui.tools) b.classList.toggle("active", b.dataset.etool === t); }
  libraryChanged() {
    const sel = this.ui.kind, keep = sel.value; sel.innerHTML = "";
    for (const k of this.studio.lib.kinds) { const o = document.createElement("option"); o.value = o.textContent = k; sel.appendChild(o); }
    if (keep) sel.value = keep;
    this.draw();
  }
  setActive(name) { this.active = name; this.update(this.studio.palette, true); }
  update(pal, refit = false) {
    const names = pal.exemplars.map((e) => e.name);
    if (!names.includes(this.active)) { this.active = names.length ? names[names.length - 1] : null; refit = true; }
    this.ex = pal.exemplars.find((e) => e.name === this.active) || null;
    this.ui.title.textContent = this.ex ? `Exemplar: ${this.ex.name} (${this.ex.n} elements)` : "Exemplar";
    this.ui.note.textContent = this.ex && this.ex.note ? this.ex.note : "";
    if (this.ex) this.els.fromColumns(this.ex); else this.els.replace({ k: [], x: [], y: [], r: [], s: [] });
    if (refit || !this._fitted) this.fit();
    this.draw();
  }
  fit() {
    const b = this.els.bounds(this.studio.lib.radius);
    this.view.fit(b || [0, 0, 100, 100], this.canvas.width, this.canvas.height, 12);
    this._fitted = !!b;
  }
  world(ev) { const r = this.canvas.getBoundingClientRect(); return this.view.toWorld((ev.clientX - r.left) * this.canvas.width / r.width, (ev.clientY - r.top) * this.canvas.height / r.height); }
  pick(p) {
    if (!this.ex) return -1;
    let best = -1, bd = Infinity;
    for (let i = 0; i < this.ex.n; i++) {
      const d = Math.hypot(this.ex.x[i] - p[0], this.ex.y[i] - p[1]);
      const r = this.ex.radius[i] || this.studio.lib.radius[this.ex.k[i]] || 1;
      if (d < r && d < bd) { bd = d; best = i; }
    }
    return best;
  }
  pickEdge(p) {
    if (!this.ex) return null;
    let best = null, bd = Infinity;
    for (const [i, j] of this.ex.edges) {
      const ax = this.ex.x[i], ay = this.ex.y[i], bx = this.ex.x[j], by = this.ex.y[j];
      const dx = bx - ax, dy = by - ay, L = dx * dx + dy * dy || 1;
      const t = Math.max(0, Math.min(1, ((p[0] - ax) * dx + (p[1] - ay) * dy) / L));
      const d = Math.hypot(ax + t * dx - p[0], ay + t * dy - p[1]);
      if (d < bd) { bd = d; best = [i, j]; }
    }
    return bd * this.view.zoom < 8 ? best : null;
  }
  down(ev) {
    if (!this.active) return;
    const p = this.world(ev);
    const name = this.active;
    if (this.tool === "place") this.send({ type: "palette_edit", exemplar: name, op: "place", kind: this.ui.kind.value, x: p[0], y: p[1] });
    else if (this.tool === "delete") { const i = this.pick(p); if (i >= 0) this.send({ type: "palette_edit", exemplar: name, op: "delete", index: i }); }
    else if (this.tool === "radius") { const i = this.pick(p); if (i >= 0) this.send({ type: "palette_edit", exemplar: name, op: "radius", index: i, field: this.ui.radiusField.value, value: +this.ui.radiusValue.value }); }
    else if (this.tool === "flip") { const e = this.pickEdge(p); if (e) this.send({ type: "palette_flip", exemplar: name, i: e[0], j: e[1] }); }
    else if (this.tool === "move") { const i = this.pick(p); if (i >= 0) { this.drag = { i, p }; this.canvas.setPointerCapture(ev.pointerId); } }
    else if (this.tool === "paint") {
      this.paint = [p]; this.canvas.setPointerCapture(ev.pointerId);
      this.send({ type: "stroke_start", tool: "brush", target: "palette", exemplar: name, radius: this.ui.brushRadius(), points: [p] });
    }
  }
  move(ev) {
    const p = this.world(ev);
    if (this.drag) { this.drag.p = p; this.els.x[this.drag.i] = p[0]; this.els.y[this.drag.i] = p[1]; this.draw(); }
    if (this.paint) { this.paint.push(p); this.send({ type: "stroke_move", points: [p] }); this.draw(); }
  }
  up(ev) {
    if (this.drag) { const { i, p } = this.drag; this.drag = null; this.send({ type: "palette_edit", exemplar: this.active, op: "move", index: i, x: p[0], y: p[1] }); }
    if (this.paint) { this.paint = null; this.send({ type: "stroke_end" }); }
  }
  draw() {
    const ctx = this.ctx, w = this.canvas.width, h = this.canvas.height, v = this.view;
    ctx.setTransform(1, 0, 0, 1, 0, 0); ctx.fillStyle = "#fff"; ctx.fillRect(0, 0, w, h);
    if (!this.ex) return;
    drawElements(ctx, this.studio.lib, this.els, v, w, h, 1);
    // per-element bounding radii
    ctx.strokeStyle = "rgba(0,0,0,.18)"; ctx.lineWidth = 1;
    for (let i = 0; i < this.ex.n; i++) {
      const r = this.ex.radius[i]; if (!r) continue;
      const [sx, sy] = v.toScreen(this.els.x[i], this.els.y[i]);
      ctx.beginPath(); ctx.arc(sx, sy, r * v.zoom, 0, 2 * Math.PI); ctx.stroke();
    }
    if (this.ui.showEdges.checked) {
      ctx.strokeStyle = "rgba(220,60,40,.8)"; ctx.lineWidth = 1; ctx.beginPath();
      for (const [i, j] of this.ex.edges) {
        const [ax, ay] = v.toScreen(this.els.x[i], this.els.y[i]), [bx, by] = v.toScreen(this.els.x[j], this.els.y[j]);
        ctx.moveTo(ax, ay); ctx.lineTo(bx, by);
      }
      ctx.stroke();
    }
    if (this.paint && this.paint.length > 1) {
      ctx.strokeStyle = "rgba(60,120,220,.6)"; ctx.lineWidth = 2; ctx.beginPath();
      this.paint.forEach((q, i) => { const [sx, sy] = v.toScreen(q[0], q[1]); i ? ctx.lineTo(sx, sy) : ctx.moveTo(sx, sy); });
      ctx.stroke();
    }
  }
}
