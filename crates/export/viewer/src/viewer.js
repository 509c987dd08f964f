// The viewer of `locus view`: an orbit view of the graph's glTF, a panel of outputs and
// branches with toggles, the address and value of a clicked object, and the messages per node.
// The page embeds everything it shows (no network): the glTF as base64 in
// <script id="locus-glb">, the outputs and messages as JSON in <script id="locus-data">.
// A live page (`locus view --serve`, its data has `live`) asks the server for the generation of
// its evaluation twice a second, reloads when the graph was evaluated again, and keeps the
// camera across reloads.

import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

// The page's state, read by the end-to-end test (crates/export/e2e/viewer.mjs): whether the
// scene is loaded, how many item objects it holds, errors, the selected item's extras,
// `probes()`, a point on screen for each item in view, `camera()`, its position and target, and
// on a live page the generation shown.
const state = { ready: false, objectCount: 0, errors: [], selected: null, probes: () => [], camera: () => null, generation: null };
window.locusViewer = state;

function base64ToBuffer(text) {
  const binary = atob(text.trim());
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i += 1) bytes[i] = binary.charCodeAt(i);
  return bytes.buffer;
}

function el(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === 'class') node.className = v; else node.setAttribute(k, v);
  }
  for (const c of children) node.append(c);
  return node;
}

function start() {
  const data = JSON.parse(document.getElementById('locus-data').textContent);
  const viewport = document.getElementById('viewport');
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio);
  renderer.setClearColor(0xf4f4f4);
  viewport.append(renderer.domElement);
  const scene = new THREE.Scene();
  scene.add(new THREE.HemisphereLight(0xffffff, 0x888888, 2.0));
  const sun = new THREE.DirectionalLight(0xffffff, 1.5);
  scene.add(sun);
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.enableDamping = false;

  function resize() {
    const { clientWidth: w, clientHeight: h } = viewport;
    renderer.setSize(w, h, false);
    camera.aspect = w / Math.max(h, 1);
    camera.updateProjectionMatrix();
    draw();
  }
  function draw() {
    sun.position.copy(camera.position);
    renderer.render(scene, camera);
  }
  controls.addEventListener('change', draw);
  window.addEventListener('resize', resize);
  if (data.live) {
    controls.addEventListener('change', () => saveCamera(cameraKey(data), camera, controls));
    watchGeneration(data.live.generation);
  }

  const loader = new GLTFLoader();
  loader.parse(base64ToBuffer(document.getElementById('locus-glb').textContent), '', (gltf) => {
    const root = gltf.scene;
    scene.add(root);
    // Points and lines get visible sizes.
    root.traverse((o) => {
      if (o.isPoints) o.material.size = 6, o.material.sizeAttenuation = false;
    });
    const box = new THREE.Box3().setFromObject(root);
    const size = box.getSize(new THREE.Vector3()).length() || 1;
    const centre = box.getCenter(new THREE.Vector3());
    camera.near = size / 1000;
    camera.far = size * 100;
    camera.position.copy(centre).add(new THREE.Vector3(1, 0.8, 1).normalize().multiplyScalar(size * 1.3));
    controls.target.copy(centre);
    if (data.live) restoreCamera(cameraKey(data), camera, controls);
    controls.update();
    buildPanel(root, data, draw);
    state.objectCount = countItems(root);
    state.probes = () => probes(root, camera, renderer.domElement);
    state.camera = () => ({ position: camera.position.toArray(), target: controls.target.toArray() });
    resize();
    state.ready = true;
    document.body.dataset.ready = 'true';
  }, (error) => {
    state.errors.push(String(error));
    document.getElementById('selection').textContent = `cannot load the scene: ${error}`;
  });

  // A click selects the nearest object under the pointer and shows its address and value.
  const raycaster = new THREE.Raycaster();
  raycaster.params.Points.threshold = 0.01;
  raycaster.params.Line.threshold = 0.01;
  renderer.domElement.addEventListener('click', (event) => {
    const rect = renderer.domElement.getBoundingClientRect();
    const pointer = new THREE.Vector2(
      ((event.clientX - rect.left) / rect.width) * 2 - 1,
      -((event.clientY - rect.top) / rect.height) * 2 + 1,
    );
    raycaster.setFromCamera(pointer, camera);
    const hit = raycaster.intersectObjects(scene.children, true).find((h) => h.object.visible);
    let item = hit ? hit.object : null;
    while (item && !(item.userData && item.userData.output !== undefined && item.userData.index !== undefined)) item = item.parent;
    select(item ? item.userData : null);
  });
}

// The camera of a live page is kept per graph for the browser tab (sessionStorage).
function cameraKey(data) {
  return `locus-camera:${data.title}`;
}

function saveCamera(key, camera, controls) {
  try {
    sessionStorage.setItem(key, JSON.stringify({ position: camera.position.toArray(), target: controls.target.toArray() }));
  } catch (_) { /* storage may be disabled: the camera is then fitted on each reload */ }
}

function restoreCamera(key, camera, controls) {
  let saved = null;
  try { saved = JSON.parse(sessionStorage.getItem(key)); } catch (_) { saved = null; }
  const finite = (a) => Array.isArray(a) && a.length === 3 && a.every(Number.isFinite);
  if (!saved || !finite(saved.position) || !finite(saved.target)) return;
  camera.position.fromArray(saved.position);
  controls.target.fromArray(saved.target);
}

// How often a live page asks whether the graph was evaluated again, in milliseconds.
const LIVE_POLL_MS = 500;

// Reloads the page when the server's generation differs from the one the page shows. A server
// that stopped answering is shown in the panel, and the page keeps asking.
function watchGeneration(generation) {
  const status = el('p', { id: 'live-status' }, 'Live: evaluated again when the graph file changes.');
  document.getElementById('panel').prepend(status);
  state.generation = generation;
  setInterval(() => {
    fetch('generation', { cache: 'no-store' })
      .then((r) => (r.ok ? r.text() : Promise.reject(new Error(`HTTP ${r.status}`))))
      .then((text) => {
        status.textContent = 'Live: evaluated again when the graph file changes.';
        if (Number(text) !== generation) window.location.reload();
      })
      .catch(() => { status.textContent = 'Live: the server does not answer.'; });
  }, LIVE_POLL_MS);
}

function countItems(root) {
  let n = 0;
  root.traverse((o) => { if (o.userData && o.userData.index !== undefined) n += 1; });
  return n;
}

// For each item in view, a point in client pixels that lies on it: the centroid of its first
// triangle, the midpoint of its first line segment, or its first point, whichever it has first.
function probes(root, camera, canvas) {
  const rect = canvas.getBoundingClientRect();
  const res = [];
  root.updateMatrixWorld(true);
  root.traverse((o) => {
    if (!(o.userData && o.userData.index !== undefined)) return;
    let p = null;
    o.traverse((g) => {
      if (p || !g.geometry || !g.geometry.attributes.position) return;
      const pos = g.geometry.attributes.position;
      const index = g.geometry.index;
      const at = (i) => new THREE.Vector3().fromBufferAttribute(pos, index ? index.getX(i) : i);
      if (g.isMesh && (index ? index.count : pos.count) >= 3) p = at(0).add(at(1)).add(at(2)).divideScalar(3);
      else if (g.isLine && pos.count >= 2) p = at(0).add(at(1)).multiplyScalar(0.5);
      else if (g.isPoints && pos.count >= 1) p = at(0);
      if (p) p.applyMatrix4(g.matrixWorld);
    });
    if (!p) return;
    const ndc = p.project(camera);
    if (Math.abs(ndc.x) > 1 || Math.abs(ndc.y) > 1 || Math.abs(ndc.z) > 1) return;
    res.push({
      x: rect.left + ((ndc.x + 1) / 2) * rect.width,
      y: rect.top + ((1 - ndc.y) / 2) * rect.height,
      output: o.userData.output,
      path: o.userData.path,
      index: o.userData.index,
    });
  });
  return res;
}

function select(info) {
  state.selected = info;
  const box = document.getElementById('selection');
  box.textContent = info ? `${info.output} ${info.path}[${info.index}]: ${info.value}` : 'Click an object to see its output, path, index and value.';
}

// The panel: one toggle per output and per branch, then the messages per node.
function buildPanel(root, data, draw) {
  const panel = document.getElementById('outputs');
  // The root node is `locus-root`; the scene itself is named `locus` (crates/export/src/gltf.rs).
  const top = root.getObjectByName('locus-root') || root;
  for (const output of top.children) {
    const toggle = el('input', { type: 'checkbox', checked: '' });
    toggle.checked = true;
    toggle.addEventListener('change', () => { output.visible = toggle.checked; draw(); });
    const list = el('ul');
    for (const branch of output.children) {
      const t = el('input', { type: 'checkbox' });
      t.checked = true;
      t.addEventListener('change', () => { branch.visible = t.checked; draw(); });
      list.append(el('li', {}, el('label', {}, t, ` ${branch.name} (${branch.children.length})`)));
    }
    panel.append(el('li', { class: 'output' }, el('label', {}, toggle, ` ${output.name}`), list));
  }
  const messages = document.getElementById('messages');
  if (!data.messages.length) messages.append(el('li', {}, 'No messages.'));
  for (const m of data.messages) {
    messages.append(el('li', { class: m.level }, `${m.level} · ${m.node}${m.path ? ' ' + m.path : ''}${m.index !== undefined && m.index !== null ? '[' + m.index + ']' : ''}: ${m.text}`));
  }
  select(null);
}

window.addEventListener('error', (e) => state.errors.push(String(e.message)));
if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start); else start();
