// The studio's 3D view (issue 20.7): a mesh with orbit, pan and zoom; the brush picks
// points on it by raycasting and sends them; the server paints (strew.surface). This
// file only draws and sends JSON: elements arrive as positions, normals, tangents,
// scales, bounding radii and kinds, drawn as instanced discs in their tangent frames.
import * as THREE from "three";
import { OrbitControls } from "/static/vendor/three/OrbitControls.js";

const canvas = document.getElementById("view");
const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio || 1);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x1e1f22);
const camera = new THREE.PerspectiveCamera(45, 1, 0.01, 1000);
camera.position.set(0, 0, 3);
const controls = new OrbitControls(camera, canvas);
scene.add(new THREE.HemisphereLight(0xffffff, 0x444455, 1.6));
const sun = new THREE.DirectionalLight(0xffffff, 1.2);
sun.position.set(1, 2, 3);
camera.add(sun);
scene.add(camera);

const PALETTE = [0xe07a5f, 0x81b29a, 0xf2cc8f, 0x3d85c6, 0xc27ba0, 0x9fc5e8, 0xb6d7a8, 0xffd966];
const state = { camera, sent: 0, replies: 0, mesh: null, discs: null, radius: 1, count: 0, painting: false, stroke: [] };
window.strew3d = state; // read by the browser tests

function resize() {
  const w = window.innerWidth, h = window.innerHeight;
  renderer.setSize(w, h, false);
  camera.aspect = w / h;
  camera.updateProjectionMatrix();
}
window.addEventListener("resize", resize);
resize();

let ws = null;
function send(msg) { if (ws && ws.readyState === 1) ws.send(JSON.stringify(msg)); }
function connect() {
  const proto = location.protocol === "https:" ? "wss:" : "ws:";
  ws = new WebSocket(`${proto}//${location.host}/ws`);
  ws.onopen = () => {
    send({ type: "hello" });
    const q = new URLSearchParams(location.search).get("mesh");
    if (q) { document.getElementById("mesh-path").value = q; send({ type: "load_mesh", path: q }); }
  };
  ws.onmessage = (ev) => { const m = JSON.parse(ev.data); if (handlers[m.type]) handlers[m.type](m); };
  ws.onclose = () => setStatus("disconnected");
}

function setStatus(text) { document.getElementById("status").textContent = text; }

const handlers = {
  mesh(m) {
    if (state.mesh) { scene.remove(state.mesh); state.mesh.geometry.dispose(); }
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.Float32BufferAttribute(m.vertices, 3));
    g.setIndex(m.faces);
    g.computeVertexNormals();
    state.mesh = new THREE.Mesh(g, new THREE.MeshStandardMaterial({ color: 0x8a8f98, roughness: 0.85 }));
    scene.add(state.mesh);
    state.radius = m.radius;
    const c = new THREE.Vector3(...m.centre);
    controls.target.copy(c);
    camera.position.copy(c).add(new THREE.Vector3(0, 0, 3 * m.radius));
    camera.near = m.radius / 100; camera.far = m.radius * 100;
    camera.updateProjectionMatrix();
    controls.update();
    state.loaded = true;
  },
  elements3d(m) {
    if (state.discs) { scene.remove(state.discs); state.discs.geometry.dispose(); state.discs = null; }
    state.count = m.count;
    state.replies += 1;
    if (!m.count) return;
    // a unit disc in the xy plane, drawn a little above the surface along its normal
    const geo = new THREE.CylinderGeometry(1, 1, 0.15, 16).rotateX(Math.PI / 2).translate(0, 0, 0.1);
    const mat = new THREE.MeshStandardMaterial({ roughness: 0.6 });
    const inst = new THREE.InstancedMesh(geo, mat, m.count);
    const M = new THREE.Matrix4(), t = new THREE.Vector3(), n = new THREE.Vector3(), b = new THREE.Vector3();
    const col = new THREE.Color();
    for (let i = 0; i < m.count; i++) {
      const s = m.radii[i], j = 3 * i; // a disc of the element's bounding radius
      t.fromArray(m.tangents, j); n.fromArray(m.normals, j); b.crossVectors(n, t);
      M.makeBasis(t.multiplyScalar(s), b.multiplyScalar(s), n.multiplyScalar(s));
      M.setPosition(m.positions[j], m.positions[j + 1], m.positions[j + 2]);
      inst.setMatrixAt(i, M);
      inst.setColorAt(i, col.setHex(PALETTE[m.kinds[i] % PALETTE.length]));
    }
    state.discs = inst;
    scene.add(inst);
  },
  status(m) { if (m.message) setStatus(m.message); },
  error(m) { setStatus("error: " + m.message); },
};

// the brush: shift-drag, or any left drag while "paint" is on
const ray = new THREE.Raycaster(), ndc = new THREE.Vector2();
function pick(ev) {
  if (!state.mesh) return null;
  const r = canvas.getBoundingClientRect();
  ndc.set(((ev.clientX - r.left) / r.width) * 2 - 1, -((ev.clientY - r.top) / r.height) * 2 + 1);
  ray.setFromCamera(ndc, camera);
  const hit = ray.intersectObject(state.mesh, false)[0];
  return hit ? [hit.point.x, hit.point.y, hit.point.z] : null;
}
function brushRadius() { return Number(document.getElementById("radius").value) * state.radius; }
function flush() {
  if (state.stroke.length) { send({ type: "brush3d", points: state.stroke, radius: brushRadius() }); state.sent += 1; }
  state.stroke = state.stroke.slice(-1);
}
canvas.addEventListener("pointerdown", (ev) => {
  if (ev.button !== 0 || !(ev.shiftKey || document.getElementById("paint").checked)) return;
  const p = pick(ev);
  if (!p) return;
  ev.stopImmediatePropagation();
  state.painting = true; controls.enabled = false; state.stroke = [p];
  canvas.setPointerCapture(ev.pointerId);
}, true);
canvas.addEventListener("pointermove", (ev) => {
  if (!state.painting) return;
  const p = pick(ev);
  if (p) state.stroke.push(p);
  if (state.stroke.length >= 8) flush();
});
canvas.addEventListener("pointerup", () => {
  if (!state.painting) return;
  state.painting = false; controls.enabled = true;
  flush(); state.stroke = [];
});
document.getElementById("load").onclick = () => send({ type: "load_mesh", path: document.getElementById("mesh-path").value });
document.getElementById("clear").onclick = () => send({ type: "clear3d" });

renderer.setAnimationLoop(() => { controls.update(); renderer.render(scene, camera); });
connect();
