// Canvas drawing of arrangements: each kind's paths become a Path2D once, and every
// element is stamped with setTransform (translate(x y) rotate(t) scale(s), the strew
// transform convention), so thousands of elements stay smooth while panning and zooming.

export class View {
  // World -> screen: screen = zoom * world + (ox, oy), in CSS pixels.
  constructor() { this.zoom = 1; this.ox = 0; this.oy = 0; }
  toScreen(x, y) { return [this.zoom * x + this.ox, this.zoom * y + this.oy]; }
  toWorld(sx, sy) { return [(sx - this.ox) / this.zoom, (sy - this.oy) / this.zoom]; }
  fit(bounds, width, height, margin = 20) {
    const [x0, y0, x1, y1] = bounds;
    const w = Math.max(x1 - x0, 1e-9), h = Math.max(y1 - y0, 1e-9);
    this.zoom = Math.min((width - 2 * margin) / w, (height - 2 * margin) / h);
    if (!(this.zoom > 0) || !isFinite(this.zoom)) this.zoom = 1;
    this.ox = (width - this.zoom * (x0 + x1)) / 2;
    this.oy = (height - this.zoom * (y0 + y1)) / 2;
  }
  zoomAt(sx, sy, factor) {
    const [wx, wy] = this.toWorld(sx, sy);
    this.zoom = Math.min(Math.max(this.zoom * factor, 1e-4), 1e4);
    this.ox = sx - this.zoom * wx;
    this.oy = sy - this.zoom * wy;
  }
}

// Element columns in growable typed arrays: kind index, x, y, rotation, scale.
export class Elements {
  constructor() { this.n = 0; this._alloc(1024); this.version = 0; }
  _alloc(cap) {
    const grow = (old, T) => { const a = new T(cap); if (old) a.set(old.subarray(0, this.n)); return a; };
    this.k = grow(this.k, Int32Array); this.x = grow(this.x, Float64Array); this.y = grow(this.y, Float64Array);
    this.r = grow(this.r, Float64Array); this.s = grow(this.s, Float64Array); this.cap = cap;
  }
  replace(m) { this.n = 0; this.append(m); }
  append(m) {
    const add = m.k.length;
    if (this.n + add > this.cap) this._alloc(Math.max(this.cap * 2, this.n + add));
    for (let i = 0; i < add; i++) {
      const j = this.n + i;
      this.k[j] = m.k[i]; this.x[j] = m.x[i]; this.y[j] = m.y[i]; this.r[j] = m.r[i]; this.s[j] = m.s[i];
    }
    this.n += add; this.version++;
  }
  update(m) {
    for (let a = 0; a < m.index.length; a++) {
      const j = m.index[a];
      if (j >= this.n) continue;
      this.k[j] = m.k[a]; this.x[j] = m.x[a]; this.y[j] = m.y[a]; this.r[j] = m.r[a]; this.s[j] = m.s[a];
    }
    this.version++;
  }
  fromColumns(c) { this.replace({ k: c.k, x: c.x, y: c.y, r: c.r, s: c.s }); }
  bounds(radii) {
    if (!this.n) return null;
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (let i = 0; i < this.n; i++) {
      const rr = (radii ? radii[this.k[i]] || 0 : 0) * Math.abs(this.s[i]);
      x0 = Math.min(x0, this.x[i] - rr); y0 = Math.min(y0, this.y[i] - rr);
      x1 = Math.max(x1, this.x[i] + rr); y1 = Math.max(y1, this.y[i] + rr);
    }
    return [x0, y0, x1, y1];
  }
}

// Shape library: a fill Path2D (closed sub-paths, even-odd) and a stroke Path2D per kind.
export class Library {
  constructor() { this.kinds = []; this.fill = []; this.line = []; this.style = []; this.radius = []; }
  set(msg) {
    this.kinds = msg.kinds;
    this.fill = []; this.line = []; this.style = []; this.radius = [];
    for (const name of msg.kinds) {
      const sh = msg.shapes[name];
      const f = new Path2D(), l = new Path2D();
      let anyClosed = false;
      for (const p of sh.paths) {
        const pts = p.points;
        if (!pts.length) continue;
        for (const target of p.closed ? [f, l] : [l]) {
          target.moveTo(pts[0][0], pts[0][1]);
          for (let i = 1; i < pts.length; i++) target.lineTo(pts[i][0], pts[i][1]);
          if (p.closed) target.closePath();
        }
        anyClosed = anyClosed || p.closed;
      }
      const st = sh.style || {};
      this.fill.push(anyClosed ? f : null);
      this.line.push(l);
      this.radius.push(sh.radius || 1);
      this.style.push({
        fill: st.fill && st.fill !== "none" ? st.fill : (anyClosed && !st.stroke ? "#888" : null),
        stroke: st.stroke && st.stroke !== "none" ? st.stroke : (anyClosed ? null : "#222"),
        width: +(st.stroke_width || 1),
        opacity: st.opacity !== undefined ? +st.opacity : 1,
      });
    }
  }
}

// Draw elements (from index opts.from on) with culling; returns the number drawn.
// opts.order: kind indices in drawing order (layers, first drawn first); opts.hidden: a Set
// of kind indices not drawn.
export function drawElements(ctx, lib, els, view, width, height, dpr, opts = {}) {
  const z = view.zoom;
  const from = opts.from || 0;
  let drawn = 0;
  const nk = lib.kinds.length;
  const order = opts.order && opts.order.length ? opts.order : [...Array(nk).keys()];
  for (const kind of order) {
    if (kind < 0 || kind >= nk || (opts.hidden && opts.hidden.has(kind))) continue;
    const st = lib.style[kind], fill = lib.fill[kind], line = lib.line[kind];
    const rad = lib.radius[kind];
    if (!st) continue;
    ctx.globalAlpha = opts.alpha !== undefined ? opts.alpha : st.opacity;
    if (st.fill) ctx.fillStyle = st.fill;
    if (st.stroke) { ctx.strokeStyle = st.stroke; }
    const strokeIt = st.stroke && (st.width * z > 0.15);
    for (let i = from; i < els.n; i++) {
      if (els.k[i] !== kind) continue;
      const s = els.s[i], x = els.x[i], y = els.y[i];
      const sx = z * x + view.ox, sy = z * y + view.oy, rr = z * rad * Math.abs(s);
      if (sx + rr < 0 || sy + rr < 0 || sx - rr > width || sy - rr > height) continue;
      const c = Math.cos(els.r[i]) * s * z * dpr, sn = Math.sin(els.r[i]) * s * z * dpr;
      ctx.setTransform(c, sn, -sn, c, sx * dpr, sy * dpr);
      if (st.fill && fill) ctx.fill(fill, "evenodd");
      if (strokeIt) { ctx.lineWidth = st.width; ctx.stroke(line); }
      drawn++;
    }
  }
  ctx.globalAlpha = 1;
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  return drawn;
}

// A polyline in world coordinates, drawn in screen space.
export function drawPolyline(ctx, view, pts, closed = false) {
  if (!pts.length) return;
  ctx.beginPath();
  const [x0, y0] = view.toScreen(pts[0][0], pts[0][1]);
  ctx.moveTo(x0, y0);
  for (let i = 1; i < pts.length; i++) { const [x, y] = view.toScreen(pts[i][0], pts[i][1]); ctx.lineTo(x, y); }
  if (closed) ctx.closePath();
  ctx.stroke();
}

// Flow-field arrows: [x, y, angle] in world coordinates, length in world units.
export function drawArrows(ctx, view, arrows, length) {
  const L = length * view.zoom;
  ctx.beginPath();
  for (const [x, y, a] of arrows) {
    const [sx, sy] = view.toScreen(x, y);
    const dx = Math.cos(a) * L / 2, dy = Math.sin(a) * L / 2;
    const hx = sx + dx, hy = sy + dy;
    ctx.moveTo(sx - dx, sy - dy); ctx.lineTo(hx, hy);
    const h = L * 0.3, a1 = a + Math.PI * 0.85, a2 = a - Math.PI * 0.85;
    ctx.moveTo(hx, hy); ctx.lineTo(hx + Math.cos(a1) * h, hy + Math.sin(a1) * h);
    ctx.moveTo(hx, hy); ctx.lineTo(hx + Math.cos(a2) * h, hy + Math.sin(a2) * h);
  }
  ctx.stroke();
}
