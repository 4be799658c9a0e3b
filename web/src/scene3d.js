// Draws a model (protocol.js topology + frame) with three.js: particles by
// vertex state, beams and cables as lines (slack cables dashed), patches as
// surfaces, edges coloured by a result field with a legend; an orbit camera.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { EDGE_BEAM, EDGE_CABLE, EDGE_PATCH, STATES, STATE_COLOURS } from './protocol.js';

// Colours pass through as written, sRGB in and out: no conversion per
// pixel, which a software rasteriser pays for in every fragment, and the
// colour maps' edges show the same colours as the legend's CSS gradient.
THREE.ColorManagement.enabled = false;

const SIMPLE = STATES.indexOf('simple');
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

// Software WebGL (SwiftShader, llvmpipe: no GPU, e.g. a headless browser)
// pays for multisampling on the CPU, beside the solver: draw without it there.
function softwareGL() {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return false;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = info ? String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL)) : '';
  const lose = gl.getExtension('WEBGL_lose_context');
  if (lose) lose.loseContext();
  return /swiftshader|llvmpipe|softpipe|software/i.test(name);
}

// Particles drawn this many pixels wide: 6 up to 2000, smaller beyond (a
// dense net is a carpet of dots either way; fewer pixels draw faster).
function autoPointSize(n) { return Math.max(2, Math.min(6, Math.round(6 * Math.sqrt(2000 / Math.max(n, 1))))); }

// Patches: translucent, flat shaded by the triangle's normal taken in the
// fragment shader from the derivatives of the position (no vertex normals to
// recompute and upload every frame), lit from the viewer's side, both faces
// alike. Costs SwiftShader about half of three.js's Lambert material, which
// lights every pixel with the scene's lights.
// While the surface is dense on screen (`tinted` 1) it takes the colour of
// the simple state at the particles that have it (`tint` 1), which are then
// not drawn as dots (View3D.paintStates).
function surfaceMaterial(colour, opacity) {
  return new THREE.ShaderMaterial({
    uniforms: { colour: { value: colour }, opacity: { value: opacity }, tinted: { value: 0 }, tintColour: { value: new THREE.Color(STATE_COLOURS[SIMPLE]) } },
    vertexShader: `attribute float tint; uniform float tinted; varying vec3 at; varying float mixed;
      void main() { vec4 p = modelViewMatrix * vec4(position, 1.0); at = p.xyz; mixed = tinted * tint; gl_Position = projectionMatrix * p; }`,
    fragmentShader: `uniform vec3 colour, tintColour; uniform float opacity; varying vec3 at; varying float mixed;
      void main() {
        vec3 n = normalize(cross(dFdx(at), dFdy(at)));
        gl_FragColor = vec4(mix(colour, tintColour, mixed) * (0.35 + 0.65 * abs(dot(n, vec3(0.5, 0.6, 0.62)))), opacity);
      }`,
    // One pass for both faces (three.js draws a translucent two-sided
    // material twice, back faces then front ones, to order their blending).
    side: THREE.DoubleSide, transparent: true, depthWrite: false, forceSinglePass: true,
  });
}

// A surface is dense on screen when the median length of its edges there
// (up to 255 of them, evenly spread) is below this: View3D.render.
const DENSE_PIXELS = 6;

export class View3D {
  constructor(container) {
    this.container = container;
    this.software = softwareGL();
    this.renderer = new THREE.WebGLRenderer({ antialias: !this.software, preserveDrawingBuffer: true });
    this.scale = 1;  // canvas pixels per CSS pixel: setScale
    this.renderer.setPixelRatio(this.scale);
    this.renderer.outputColorSpace = THREE.LinearSRGBColorSpace;  // no conversion: see ColorManagement above
    this.renderer.setClearColor(0xffffff);
    container.appendChild(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(45, 1, 0.01, 1e5);
    this.camera.up.set(0, 0, 1);
    this.camera.position.set(8, -10, 6);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.pointSize = null;  // null: autoPointSize of the particle count
    this.topology = null;
    this.frame = null;
    this.field = null;
    this.fitted = false;
    this.selected = new Set();
    this.objects = [];
    this.resize();
    window.addEventListener('resize', () => this.resize());
  }

  resize() {
    const w = this.container.clientWidth || window.innerWidth, h = this.container.clientHeight || window.innerHeight;
    this.renderer.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.changed = true;
  }

  // Draws at `scale` canvas pixels per CSS pixel (the page lowers it while
  // a moving model draws slowly: studio.js). Particles and lines keep their
  // size on screen (three.js scales them by the ratio).
  setScale(scale) {
    if (scale === this.scale) return;
    this.scale = scale;
    this.renderer.setPixelRatio(scale);
    this.resize();
  }

  setBackground(dark) { this.renderer.setClearColor(dark ? 0x000000 : 0xffffff); this.changed = true; }

  clear() {
    for (const o of this.objects) {
      this.scene.remove(o);
      o.geometry.dispose();
      o.material.dispose();
    }
    this.objects = [];
    this.points = this.dots = this.mesh = this.fieldLines = this.cableLines = this.slackLines = this.patchBars = null;
  }

  add(object, order = 0) {
    object.frustumCulled = false;  // no bounding sphere to recompute every frame
    object.renderOrder = order;
    this.scene.add(object);
    this.objects.push(object);
    return object;
  }

  // One position buffer, uploaded once a frame, is shared by the particles,
  // the beams and patch bars (index lists of their edges) and the patch
  // surfaces; only cables (solid or dashed when slack) and a colour map's
  // edges (a colour per edge) are written out edge by edge.
  setTopology(t) {
    const before = this.topology, was = this.positions;
    this.clear();
    this.topology = t;
    this.frame = null;
    this.edgesShown = true;
    const n = t.count, ne = t.edgeKind.length;
    // Enough primitives that a software rasteriser's frame can be slow:
    // below, a slow frame is the machine's load, not the drawing's (studio.js).
    this.large = n + ne + t.triangles.length / 3 >= 10000;
    // Until its first frame comes, a particle that was there keeps its place
    // (what project and pick see then matches the picture, which stays).
    this.positions = new Float32Array(3 * n);
    if (before) {
      for (let k = 0; k < n; ++k) {
        const j = before.indexOf.get(t.ids[k]);
        if (j !== undefined) this.positions.set(was.subarray(3 * j, 3 * j + 3), 3 * k);
      }
    }
    this.position = new THREE.BufferAttribute(this.positions, 3).setUsage(THREE.DynamicDrawUsage);
    const pg = new THREE.BufferGeometry();
    pg.setAttribute('position', this.position);
    this.pointColours = new Float32Array(3 * n);
    const colours = new THREE.BufferAttribute(this.pointColours, 3);
    pg.setAttribute('color', colours);
    // On top of everything: among the transparent objects, so drawn after
    // the patches, but written without blending (they are opaque).
    const size = this.pointSize ?? autoPointSize(n);
    const dotMaterial = new THREE.PointsMaterial({ size, sizeAttenuation: false, vertexColors: true, depthTest: false, transparent: true, blending: THREE.NoBlending });
    this.points = this.add(new THREE.Points(pg, dotMaterial), 2);
    // The same, only the particles a dense surface does not show by its
    // colour (an index list: paintStates).
    const dg = new THREE.BufferGeometry();
    dg.setAttribute('position', this.position);
    dg.setAttribute('color', colours);
    dg.setIndex(new THREE.BufferAttribute(new Uint32Array(n), 1));
    this.dots = this.add(new THREE.Points(dg, dotMaterial.clone()), 2);
    this.dots.visible = false;
    const byKind = [[], [], []], cables = [];
    for (let e = 0; e < ne; ++e) {
      byKind[t.edgeKind[e]].push(t.edges[2 * e], t.edges[2 * e + 1]);
      if (t.edgeKind[e] === EDGE_CABLE) cables.push(e);
    }
    this.kindLines = [];
    for (const [kind, colour] of [[EDGE_BEAM, BEAM], [EDGE_PATCH, PATCH]]) {
      if (!byKind[kind].length) continue;
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', this.position);
      g.setIndex(new THREE.BufferAttribute(new Uint32Array(byKind[kind]), 1));
      const lines = this.add(new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: colour })));
      this.kindLines.push(lines);
      if (kind === EDGE_PATCH) this.patchBars = lines;
    }
    // Edges of the surface whose length on screen tells when it is dense.
    const nt = t.triangles.length / 3, every = Math.max(1, Math.floor(nt / 255));
    this.edgeSample = [];
    for (let k = 0; k < nt; k += every) this.edgeSample.push(t.triangles[3 * k], t.triangles[3 * k + 1]);
    this.cables = Uint32Array.from(cables);
    if (cables.length) {
      this.cableLines = this.add(this.edgeLines(cables.length, false, new THREE.LineBasicMaterial({ color: CABLE })));
      this.slackLines = this.add(this.edgeLines(cables.length, true, new THREE.LineDashedMaterial({ color: 0x777777, dashSize: 0.05, gapSize: 0.04 })));
    }
    if (t.triangles.length) {
      const mg = new THREE.BufferGeometry();
      mg.setAttribute('position', this.position);
      mg.setIndex(new THREE.BufferAttribute(t.triangles, 1));
      this.tint = new Float32Array(n);
      mg.setAttribute('tint', new THREE.BufferAttribute(this.tint, 1));
      this.mesh = this.add(new THREE.Mesh(mg, surfaceMaterial(PATCH, 0.55)), 1);
      this.onSurface = new Uint8Array(n);
      for (const k of t.triangles) this.onSurface[k] = 1;
    }
    this.paintStates();
    this.changed = true;
  }

  // Lines written edge by edge (count edges at most): positions, and a
  // colour per vertex or the distance along each (for dashes).
  edgeLines(count, dashed, material) {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(6 * count), 3).setUsage(THREE.DynamicDrawUsage));
    if (dashed) g.setAttribute('lineDistance', new THREE.BufferAttribute(new Float32Array(2 * count), 1).setUsage(THREE.DynamicDrawUsage));
    else if (material.vertexColors) g.setAttribute('color', new THREE.BufferAttribute(new Float32Array(6 * count), 3).setUsage(THREE.DynamicDrawUsage));
    g.setDrawRange(0, 0);
    return new THREE.LineSegments(g, material);
  }

  // Each particle in its state's colour (magenta when selected). A dense
  // surface is tinted with the simple state's colour at its simple
  // particles (not selected), and the dots drawn over it are the others.
  paintStates() {
    const t = this.topology, c = new THREE.Color(), out = this.pointColours;
    const dots = this.dots.geometry.index.array;
    let m = 0;
    for (let k = 0; k < t.count; ++k) {
      const selected = this.selected.has(t.ids[k]);
      c.setHex(selected ? 0xff00ff : STATE_COLOURS[t.states[k]] ?? 0);
      out[3 * k] = c.r; out[3 * k + 1] = c.g; out[3 * k + 2] = c.b;
      const shown = this.mesh && this.onSurface[k] && t.states[k] === SIMPLE && !selected;
      if (this.mesh) this.tint[k] = shown ? 1 : 0;
      if (!shown) dots[m++] = k;
    }
    this.points.geometry.attributes.color.needsUpdate = true;
    this.dots.geometry.index.needsUpdate = true;
    this.dots.geometry.setDrawRange(0, m);
    this.dots.material.size = this.pointSize ?? autoPointSize(m);  // few: as large as on a small model
    if (this.mesh) this.mesh.geometry.attributes.tint.needsUpdate = true;
    this.changed = true;
  }

  setPointSize(size) {
    this.pointSize = size;
    if (this.points) {
      this.points.material.size = size ?? autoPointSize(this.topology.count);
      this.dots.material.size = size ?? autoPointSize(this.dots.geometry.drawRange.count);
    }
    this.changed = true;
  }

  setField(field) { this.field = field; }  // {name, unit} or null

  setFrame(f) {
    const t = this.topology;
    if (!t || f.revision !== t.revision || f.count !== t.count) return false;
    this.frame = f;
    this.positions.set(f.positions);
    this.position.needsUpdate = true;
    const p = f.positions, ne = t.edgeKind.length;
    let range = 0, lo = Infinity, hi = -Infinity;
    const values = this.field && f.field && f.field.length === ne ? f.field : null;
    if (values) {
      for (let e = 0; e < ne; ++e) if (Number.isFinite(values[e])) { lo = Math.min(lo, values[e]); hi = Math.max(hi, values[e]); }
      if (lo > hi) lo = hi = 0;
      range = Math.max(Math.abs(lo), Math.abs(hi)) || 1;
    }
    const diverging = values && lo < 0 && hi > 0;
    this.edgesShown = !values;
    for (const o of this.kindLines) o.visible = !values;
    if (this.cableLines) { this.cableLines.visible = !values; this.slackLines.visible = !values; }
    if (values) this.paintField(values, diverging, lo, hi, range);
    else if (this.cables.length) this.placeCables(p);
    this.legend = values ? { lo, hi, diverging, range } : null;
    this.changed = true;
    if (!this.fitted && t.count) this.fit();
    return true;
  }

  // Taut cables solid, slack ones (shorter than their rest length) dashed.
  placeCables(p) {
    const t = this.topology;
    const solid = this.cableLines.geometry, slack = this.slackLines.geometry;
    const sp = solid.attributes.position.array, dp = slack.attributes.position.array, dd = slack.attributes.lineDistance.array;
    let ns = 0, nd = 0;
    for (const e of this.cables) {
      const a = 3 * t.edges[2 * e], b = 3 * t.edges[2 * e + 1];
      const len = Math.hypot(p[b] - p[a], p[b + 1] - p[a + 1], p[b + 2] - p[a + 2]);
      const isSlack = len < t.restLength[e] * (1 - 1e-6);
      const out = isSlack ? dp : sp, at = 6 * (isSlack ? nd : ns);
      for (let c = 0; c < 3; ++c) { out[at + c] = p[a + c]; out[at + 3 + c] = p[b + c]; }
      if (isSlack) { dd[2 * nd] = 0; dd[2 * nd + 1] = len; ++nd; } else ++ns;
    }
    solid.setDrawRange(0, 2 * ns);
    solid.attributes.position.needsUpdate = true;
    slack.setDrawRange(0, 2 * nd);
    slack.attributes.position.needsUpdate = true;
    slack.attributes.lineDistance.needsUpdate = true;
  }

  // Every edge in the colour of its value (the kind's colour where the
  // quantity does not apply: NaN).
  paintField(values, diverging, lo, hi, range) {
    const t = this.topology, ne = t.edgeKind.length, p = this.positions, c = new THREE.Color();
    if (!this.fieldLines) this.fieldLines = this.add(this.edgeLines(ne, false, new THREE.LineBasicMaterial({ vertexColors: true })));
    const g = this.fieldLines.geometry, xyz = g.attributes.position.array, rgb = g.attributes.color.array;
    for (let e = 0; e < ne; ++e) {
      const a = 3 * t.edges[2 * e], b = 3 * t.edges[2 * e + 1];
      if (Number.isFinite(values[e])) colourOf(diverging ? values[e] / range : (values[e] - lo) / ((hi - lo) || 1), diverging, c);
      else c.copy(t.edgeKind[e] === EDGE_BEAM ? BEAM : t.edgeKind[e] === EDGE_CABLE ? CABLE : PATCH);
      for (let k = 0; k < 3; ++k) { xyz[6 * e + k] = p[a + k]; xyz[6 * e + 3 + k] = p[b + k]; }
      rgb[6 * e] = rgb[6 * e + 3] = c.r; rgb[6 * e + 1] = rgb[6 * e + 4] = c.g; rgb[6 * e + 2] = rgb[6 * e + 5] = c.b;
    }
    g.setDrawRange(0, 2 * ne);
    g.attributes.position.needsUpdate = true;
    g.attributes.color.needsUpdate = true;
  }

  fit() {
    const box = new THREE.Box3().setFromBufferAttribute(this.position);
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

  // Where the surface is dense on screen a software rasteriser would spend
  // most of a frame on primitives that show nothing more: patch bars that
  // only darken their surface, and a dot at every particle. There the
  // patch bars are left out, and the simple particles on the surface are
  // shown by its colour (paintStates) rather than a dot each.
  // A topology is not drawn before its first frame (its positions): the
  // picture of the last one stays until then.
  render() {
    if (!this.topology) return this.renderer.render(this.scene, this.camera);
    if (!this.frame) return;
    const dense = this.surfaceDense();
    if (this.patchBars) this.patchBars.visible = this.edgesShown && !dense;
    this.points.visible = !dense;
    this.dots.visible = dense;
    if (this.mesh) this.mesh.material.uniforms.tinted.value = dense ? 1 : 0;
    this.renderer.render(this.scene, this.camera);
  }

  // The median length on screen, in CSS pixels, of the sampled surface
  // edges is below DENSE_PIXELS (no surface: never).
  surfaceDense() {
    const s = this.edgeSample, p = this.positions, n = s.length / 2;
    if (!n) return false;
    const h = this.renderer.domElement.clientHeight / 2, w = this.renderer.domElement.clientWidth / 2;
    const a = new THREE.Vector3(), b = new THREE.Vector3(), lengths = new Float32Array(n);
    for (let k = 0; k < n; ++k) {
      a.fromArray(p, 3 * s[2 * k]).project(this.camera);
      b.fromArray(p, 3 * s[2 * k + 1]).project(this.camera);
      lengths[k] = Math.hypot((a.x - b.x) * w, (a.y - b.y) * h);
    }
    lengths.sort();
    this.edgePixels = lengths[n >> 1];
    return this.edgePixels < DENSE_PIXELS;
  }
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
      this.mesh.geometry.computeBoundingSphere();  // the raycaster tests it first
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
