// Draws a model (protocol.js topology + frame) with three.js: particles by
// vertex state, beams and cables as lines (slack cables dashed), patches as
// surfaces, edges coloured by a result field with a legend; an orbit camera.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { EDGE_BEAM, EDGE_CABLE, STATE_COLOURS } from './protocol.js';

const BEAM = new THREE.Color(0x1f3a93), CABLE = new THREE.Color(0x555555), PATCH = new THREE.Color(0x8a8a8a);

// Diverging: blue (compression, negative) - light grey - red (tension).
// One sign: blue - green - yellow - red. legendGradient() draws the same stops.
const DIVERGING = [[0, 0.25, 0.85], [0.82, 0.82, 0.82], [0.9, 0.05, 0.05]];
const SEQUENTIAL = [[0.15, 0.25, 0.85], [0.1, 0.7, 0.3], [0.95, 0.8, 0.1], [0.9, 0.05, 0.05]];
function colourOf(t, diverging, out) {
  const stops = diverging ? DIVERGING : SEQUENTIAL;
  const a = Math.max(0, Math.min(1, diverging ? (t + 1) / 2 : t)) * (stops.length - 1);
  const i = Math.min(stops.length - 2, Math.floor(a)), f = a - i;
  const [p, q] = [stops[i], stops[i + 1]];
  return out.setRGB(p[0] + f * (q[0] - p[0]), p[1] + f * (q[1] - p[1]), p[2] + f * (q[2] - p[2]));
}

export class View3D {
  constructor(container) {
    this.container = container;
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(1);
    this.renderer.setClearColor(0xffffff);
    container.appendChild(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(45, 1, 0.01, 1e5);
    this.camera.up.set(0, 0, 1);
    this.camera.position.set(8, -10, 6);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.scene.add(new THREE.AmbientLight(0xffffff, 0.7));
    const sun = new THREE.DirectionalLight(0xffffff, 0.8);
    sun.position.set(3, -5, 10);
    this.scene.add(sun);
    this.pointSize = 6;
    this.topology = null;
    this.frame = null;
    this.field = null;
    this.fitted = false;
    this.selected = new Set();
    this.resize();
    window.addEventListener('resize', () => this.resize());
  }

  resize() {
    const w = this.container.clientWidth || window.innerWidth, h = this.container.clientHeight || window.innerHeight;
    this.renderer.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
  }

  setBackground(dark) { this.renderer.setClearColor(dark ? 0x000000 : 0xffffff); this.changed = true; }

  clear() {
    for (const o of [this.points, this.lines, this.dashed, this.mesh]) {
      if (!o) continue;
      this.scene.remove(o);
      o.geometry.dispose();
    }
    this.points = this.lines = this.dashed = this.mesh = null;
  }

  setTopology(t) {
    this.clear();
    this.topology = t;
    this.frame = null;
    const n = t.count;
    this.positions = new Float32Array(3 * n);
    const pg = new THREE.BufferGeometry();
    pg.setAttribute('position', new THREE.BufferAttribute(this.positions, 3));
    this.pointColours = new Float32Array(3 * n);
    pg.setAttribute('color', new THREE.BufferAttribute(this.pointColours, 3));
    // On top of everything: transparent, so drawn after the patches.
    this.points = new THREE.Points(pg, new THREE.PointsMaterial({ size: this.pointSize, sizeAttenuation: false, vertexColors: true, depthTest: false, transparent: true }));
    this.points.renderOrder = 2;
    this.paintStates();
    this.changed = true;
    const ne = t.edgeKind.length;
    this.edgePositions = new Float32Array(6 * ne);
    this.edgeColours = new Float32Array(6 * ne);
    const lg = new THREE.BufferGeometry();
    lg.setAttribute('position', new THREE.BufferAttribute(this.edgePositions, 3));
    lg.setAttribute('color', new THREE.BufferAttribute(this.edgeColours, 3));
    this.lines = new THREE.LineSegments(lg, new THREE.LineBasicMaterial({ vertexColors: true }));
    this.slackPositions = new Float32Array(6 * ne);
    const dg = new THREE.BufferGeometry();
    dg.setAttribute('position', new THREE.BufferAttribute(this.slackPositions, 3));
    this.slackDistances = new Float32Array(2 * ne);
    dg.setAttribute('lineDistance', new THREE.BufferAttribute(this.slackDistances, 1));
    this.dashed = new THREE.LineSegments(dg, new THREE.LineDashedMaterial({ color: 0x777777, dashSize: 0.05, gapSize: 0.04 }));
    this.scene.add(this.lines, this.dashed, this.points);
    if (t.triangles.length) {
      const mg = new THREE.BufferGeometry();
      mg.setAttribute('position', new THREE.BufferAttribute(this.positions, 3));
      mg.setIndex(new THREE.BufferAttribute(t.triangles, 1));
      this.mesh = new THREE.Mesh(mg, new THREE.MeshLambertMaterial({ color: PATCH, side: THREE.DoubleSide, transparent: true, opacity: 0.55, depthWrite: false }));
      this.scene.add(this.mesh);
    }
  }

  paintStates() {
    const t = this.topology, c = new THREE.Color();
    for (let k = 0; k < t.count; ++k) {
      c.setHex(this.selected.has(t.ids[k]) ? 0xff00ff : STATE_COLOURS[t.states[k]] ?? 0);
      this.pointColours.set([c.r, c.g, c.b], 3 * k);
    }
    if (this.points) this.points.geometry.attributes.color.needsUpdate = true;
    this.changed = true;
  }

  setField(field) { this.field = field; }  // {name, unit} or null

  setFrame(f) {
    const t = this.topology;
    if (!t || f.revision !== t.revision || f.count !== t.count) return false;
    this.frame = f;
    this.positions.set(f.positions);
    this.points.geometry.attributes.position.needsUpdate = true;
    this.points.geometry.computeBoundingSphere();
    const p = f.positions, ne = t.edgeKind.length, c = new THREE.Color();
    let range = 0, lo = Infinity, hi = -Infinity;
    const values = this.field && f.field && f.field.length === ne ? f.field : null;
    if (values) {
      for (let e = 0; e < ne; ++e) if (Number.isFinite(values[e])) { lo = Math.min(lo, values[e]); hi = Math.max(hi, values[e]); }
      if (lo > hi) lo = hi = 0;
      range = Math.max(Math.abs(lo), Math.abs(hi)) || 1;
    }
    const diverging = values && lo < 0 && hi > 0;
    let solid = 0, slack = 0;
    for (let e = 0; e < ne; ++e) {
      const a = 3 * t.edges[2 * e], b = 3 * t.edges[2 * e + 1];
      const dx = p[b] - p[a], dy = p[b + 1] - p[a + 1], dz = p[b + 2] - p[a + 2];
      const len = Math.hypot(dx, dy, dz);
      if (t.edgeKind[e] === EDGE_CABLE && len < t.restLength[e] * (1 - 1e-6) && !values) {
        this.slackPositions.set([p[a], p[a + 1], p[a + 2], p[b], p[b + 1], p[b + 2]], 6 * slack);
        this.slackDistances[2 * slack] = 0;
        this.slackDistances[2 * slack + 1] = len;
        ++slack;
        continue;
      }
      this.edgePositions.set([p[a], p[a + 1], p[a + 2], p[b], p[b + 1], p[b + 2]], 6 * solid);
      if (values && Number.isFinite(values[e])) colourOf(diverging ? values[e] / range : (values[e] - lo) / ((hi - lo) || 1), diverging, c);
      else c.copy(t.edgeKind[e] === EDGE_BEAM ? BEAM : t.edgeKind[e] === EDGE_CABLE ? CABLE : PATCH);
      this.edgeColours.set([c.r, c.g, c.b, c.r, c.g, c.b], 6 * solid);
      ++solid;
    }
    this.lines.geometry.setDrawRange(0, 2 * solid);
    this.lines.geometry.attributes.position.needsUpdate = true;
    this.lines.geometry.attributes.color.needsUpdate = true;
    this.dashed.geometry.setDrawRange(0, 2 * slack);
    this.dashed.geometry.attributes.position.needsUpdate = true;
    this.dashed.geometry.attributes.lineDistance.needsUpdate = true;
    if (this.mesh) {
      this.mesh.geometry.attributes.position.needsUpdate = true;
      this.mesh.geometry.computeVertexNormals();
      this.mesh.geometry.computeBoundingSphere();
    }
    this.legend = values ? { lo, hi, diverging, range } : null;
    this.changed = true;
    if (!this.fitted && t.count) this.fit();
    return true;
  }

  fit() {
    const box = new THREE.Box3().setFromBufferAttribute(this.points.geometry.attributes.position);
    const centre = box.getCenter(new THREE.Vector3());
    const size = Math.max(box.getSize(new THREE.Vector3()).length(), 0.5);
    this.controls.target.copy(centre);
    this.camera.position.copy(centre).add(new THREE.Vector3(0.55, -0.75, 0.45).multiplyScalar(size * 1.2));
    this.camera.near = size / 1000;
    this.camera.far = size * 100;
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.fitted = true;
  }

  render() { this.renderer.render(this.scene, this.camera); }
  get changed() { return this._changed; }
  set changed(v) { this._changed = v; }

  // Screen position (CSS pixels in the canvas) of particle index k.
  project(k) {
    const v = new THREE.Vector3(this.positions[3 * k], this.positions[3 * k + 1], this.positions[3 * k + 2]).project(this.camera);
    const r = this.renderer.domElement.getBoundingClientRect();
    return [(v.x + 1) / 2 * r.width, (1 - v.y) / 2 * r.height, v.z];
  }

  // The nearest particle within `radius` pixels of (x, y), else the nearest
  // edge's block within radius, else the patch under the cursor.
  pick(x, y, radius = 8) {
    const t = this.topology;
    if (!t || !this.frame) return null;
    let best = -1, bestD = radius * radius;
    const screen = new Float32Array(2 * t.count);
    for (let k = 0; k < t.count; ++k) {
      const [sx, sy, sz] = this.project(k);
      screen[2 * k] = sx; screen[2 * k + 1] = sy;
      if (sz > 1) continue;
      const d = (sx - x) ** 2 + (sy - y) ** 2;
      if (d < bestD) { bestD = d; best = k; }
    }
    if (best >= 0) return { type: 'particle', id: t.ids[best], index: best };
    let edge = -1; bestD = radius * radius;
    for (let e = 0; e < t.edgeKind.length; ++e) {
      const a = t.edges[2 * e], b = t.edges[2 * e + 1];
      const ax = screen[2 * a], ay = screen[2 * a + 1], bx = screen[2 * b], by = screen[2 * b + 1];
      const vx = bx - ax, vy = by - ay, l2 = vx * vx + vy * vy || 1;
      const s = Math.max(0, Math.min(1, ((x - ax) * vx + (y - ay) * vy) / l2));
      const d = (ax + s * vx - x) ** 2 + (ay + s * vy - y) ** 2;
      if (d < bestD) { bestD = d; edge = e; }
    }
    if (edge >= 0) return { type: 'block', id: t.blocks[t.edgeBlock[edge]], block: t.edgeBlock[edge] };
    if (this.mesh) {
      const r = this.renderer.domElement.getBoundingClientRect();
      const ray = new THREE.Raycaster();
      ray.setFromCamera(new THREE.Vector2(x / r.width * 2 - 1, 1 - y / r.height * 2), this.camera);
      const hit = ray.intersectObject(this.mesh)[0];
      if (hit) return { type: 'block', id: t.blocks[t.triangleBlock[hit.faceIndex]], block: t.triangleBlock[hit.faceIndex] };
    }
    return null;
  }

  // The point under (x, y) on the plane through particle k facing the camera.
  dragPoint(k, x, y) {
    const r = this.renderer.domElement.getBoundingClientRect();
    const at = new THREE.Vector3(this.positions[3 * k], this.positions[3 * k + 1], this.positions[3 * k + 2]);
    const normal = this.camera.getWorldDirection(new THREE.Vector3());
    const plane = new THREE.Plane().setFromNormalAndCoplanarPoint(normal, at);
    const ray = new THREE.Raycaster();
    ray.setFromCamera(new THREE.Vector2(x / r.width * 2 - 1, 1 - y / r.height * 2), this.camera);
    const out = new THREE.Vector3();
    return ray.ray.intersectPlane(plane, out) ? [out.x, out.y, out.z] : null;
  }
}

export function legendGradient(diverging) {
  const css = (c) => `rgb(${c.map((x) => Math.round(255 * x)).join(',')})`;
  return `linear-gradient(to right, ${(diverging ? DIVERGING : SEQUENTIAL).map(css).join(', ')})`;
}
