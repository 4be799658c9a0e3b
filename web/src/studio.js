// The studio page: a WebSocket to `tendril studio`, the model drawn live
// (scene3d.js), and every control as one of the session's commands
// (studio/session.cpp; docs/studio.md lists them). Nothing is fetched but
// this page and its socket.
import GUI from 'lil-gui';
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import './style.css';
import { View3D, legendGradient } from './scene3d.js';
import * as P from './protocol.js';

const query = new URLSearchParams(location.search);
const token = query.get('token');
const rate = Number(query.get('fps') || 30);
const drawing = query.get('draw') !== '0';  // ?draw=0: receive frames, draw nothing (the benchmark's control)
const $ = (id) => document.getElementById(id);
const view = new View3D($('view'));

// Everything the browser tests and the benchmark read lives here.
const studio = window.studio = {
  view, hello: null, status: null, topology: null, frame: null, preview: null,
  frames: 0, fps: 0, replies: [], errors: [], selection: [], connected: false,
  send, project: (id) => view.topology && view.topology.indexOf.has(id) ? view.project(view.topology.indexOf.get(id)) : null,
  position: (id) => {
    const t = studio.topology, f = studio.frame;
    if (!t || !f || !t.indexOf.has(id)) return null;
    const k = t.indexOf.get(id);
    return [f.positions[3 * k], f.positions[3 * k + 1], f.positions[3 * k + 2]];
  },
  dragLatency: [], drawLatency: [],  // ms from a drag to the first frame showing it: received, drawn
  // The drawn colour at CSS pixel (x, y) of the canvas, as [r, g, b] 0-255.
  pixel: (x, y) => {
    const c = document.createElement('canvas');
    c.width = 1; c.height = 1;
    const g = c.getContext('2d'), s = view.scale;
    g.drawImage(view.renderer.domElement, Math.floor(x * s), Math.floor(y * s), 1, 1, 0, 0, 1, 1);
    return Array.from(g.getImageData(0, 0, 1, 1).data.slice(0, 3));
  },
};

let ws = null, nextId = 1;
const pending = new Map();
function send(command) {
  if (!ws || ws.readyState !== 1) return null;
  command.id = command.id ?? nextId++;
  ws.send(JSON.stringify(command));
  return command.id;
}
function request(command) {
  return new Promise((resolve) => { const id = send(command); if (id === null) resolve(null); else pending.set(id, resolve); });
}
studio.request = request;

// A tab in the background asks for no frames.
document.addEventListener('visibilitychange', () => send({ cmd: 'rate', fps: document.hidden ? 0 : rate }));

function connect() {
  ws = new WebSocket(`ws://${location.host}/ws${token ? '?token=' + encodeURIComponent(token) : ''}`);
  ws.binaryType = 'arraybuffer';
  ws.onopen = () => { studio.connected = true; send({ cmd: 'rate', fps: document.hidden ? 0 : rate }); send({ cmd: 'hello' }); };
  ws.onclose = () => { studio.connected = false; $('stats').textContent = 'disconnected: retrying…'; setTimeout(connect, 1000); };
  ws.onmessage = (e) => (typeof e.data === 'string' ? onText(JSON.parse(e.data)) : onBinary(e.data));
}

// --- messages from the server ------------------------------------------------------

let dragSent = null;  // {at, step} of the drag waiting for its frame
// The server sends the next frame once the page has taken this one
// ("ready"), so frames never pile up in the socket; the draw loop draws the
// latest at each animation frame and skips the ones that came in between.
let undrawn = null;
function onBinary(buffer) {
  const k = P.kind(buffer);
  if (k === P.TOPOLOGY) {
    studio.topologies = (studio.topologies || 0) + 1;
    studio.topology = P.readTopology(buffer);
    if (!studio.preview) { view.setTopology(studio.topology); paintSelection(); }
  } else if (k === P.FRAME) {
    const f = P.readFrame(buffer);
    send({ cmd: 'ready' });  // taken, even when dropped: the server sends nothing more until it hears this
    if (!studio.topology || f.revision !== studio.topology.revision) return;
    studio.frame = f;
    studio.frames++;
    if (dragSent && dragSent.step !== null && f.step > dragSent.step) {
      studio.dragLatency.push(performance.now() - dragSent.at);
      f.dragAt = dragSent.at;
      dragSent = null;
    }
    if (undrawn && f.dragAt === undefined) f.dragAt = undrawn.dragAt;  // a newer frame shows the drag too
    if (!studio.preview && drawing) undrawn = f;
    plotResidual(f);
  } else if (k === P.PREVIEW_TOPOLOGY) {
    if (!scrubbing) return;  // back to live before the replay came: too late
    studio.preview = { topology: P.readTopology(buffer) };
    view.setTopology(studio.preview.topology);
  } else if (k === P.PREVIEW_FRAME) {
    if (!studio.preview) return;
    studio.preview.frame = P.readFrame(buffer);
    view.setFrame(studio.preview.frame);
  }
}

function onText(m) {
  if (m.type === 'reply') {
    studio.replies.push(m);
    if (studio.replies.length > 200) studio.replies.shift();
    if (m.cmd === 'drag' && dragSent && m.ok && dragSent.step === null) dragSent.step = m.value.step;  // the first drag's
    if (m.cmd === 'hello' && m.ok) onHello(m.value);
    if (pending.has(m.id)) { pending.get(m.id)(m); pending.delete(m.id); }
    if (!['hello', 'drag', 'field', 'timeline'].includes(m.cmd)) say(m.ok ? `${m.cmd}: done` + (m.value && m.value.length ? ' → ' + JSON.stringify(m.value) : '') : `${m.cmd} refused: ${m.message}`, m.ok);
  } else if (m.type === 'status') {
    studio.status = m;
    onStatus(m);
  } else if (m.type === 'error') {
    studio.errors.push(m.message);
    say(m.message, false);
  } else if (m.type === 'reload') {
    send({ cmd: 'hello' });
  }
}

function say(text, ok) {
  const el = $('message');
  el.textContent = text;
  el.className = ok ? 'ok' : 'refused';
}

// --- heads-up display: stats, residual plot, legend ----------------------------------

const plotData = [[], []];
const plot = new uPlot({ width: 288, height: 120, legend: { show: false }, scales: { x: { time: false }, y: { distr: 3 } },
  axes: [{ size: 20 }, { size: 40 }], series: [{}, { stroke: '#1f3a93', label: 'residual [N]' }] }, plotData, $('plot'));
let lastPlot = 0;
function plotResidual(f) {
  const now = performance.now();
  if (now - lastPlot < 100 || !(f.residual > 0)) return;
  lastPlot = now;
  plotData[0].push(f.step);
  plotData[1].push(f.residual);
  if (plotData[0].length > 600) { plotData[0].shift(); plotData[1].shift(); }
  plot.setData(plotData);
}

let frameCount = 0, lastCount = performance.now(), lastStats = 0;
// A few times a second: rewriting the text re-lays out and repaints the page.
function updateStats() {
  const now = performance.now();
  if (now - lastStats < 250) return;
  lastStats = now;
  if (now - lastCount >= 1000) {
    studio.fps = (studio.frames - frameCount) * 1000 / (now - lastCount);
    frameCount = studio.frames;
    lastCount = now;
  }
  const f = studio.frame, s = studio.status;
  $('stats').textContent = f ? `step ${f.step}   residual ${f.residual.toExponential(2)} N\n` +
    `particles ${f.count}   blocks ${studio.topology.blocks.length}   ${studio.fps.toFixed(0)} frames/s` +
    (s ? `\n${s.paused ? 'paused' : s.converged ? 'at equilibrium' : 'running'}   journal ${s.productions} productions` : '') : 'waiting for the model…';
  const L = view.legend;
  $('legend').hidden = !L;
  if (L) {
    $('legend-name').textContent = `${view.field.name} [${view.field.unit}]`;
    $('legend-bar').style.background = legendGradient(L.diverging);
    $('legend-lo').textContent = (L.diverging ? -L.range : L.lo).toPrecision(3);
    $('legend-hi').textContent = (L.diverging ? L.range : L.hi).toPrecision(3);
  }
}

// --- controls: solver, parameters, view --------------------------------------------------

let gui = null;
const list = (x) => (Array.isArray(x) ? x : []);  // an empty Lua table comes as {}
const INTEGRATORS = ['auto', 'leapfrog', 'symplectic_euler', 'velocity_verlet', 'midpoint', 'rk4', 'vie', 'projective', 'mixed', 'newton'];
function onHello(h) {
  studio.hello = h;
  if (gui) gui.destroy();
  gui = new GUI({ title: h.scene });
  const solver = gui.addFolder('solver');
  const st = Object.assign({ tolerance: h.tolerance, speed: h.speed }, h.settings || {});
  const set = (key) => (v) => send({ cmd: 'settings', settings: { [key]: v } });
  solver.add(st, 'integrator', INTEGRATORS).onChange(set('integrator'));
  solver.add(st, 'damping', ['none', 'viscous', 'kinetic']).onChange(set('damping'));
  solver.add(st, 'dt', 1e-4, 10).onFinishChange(set('dt'));
  solver.add(st, 'viscous', 0, 1).onFinishChange(set('viscous'));
  solver.add(st, 'mass_factor', 1, 10).onFinishChange(set('mass_factor'));
  solver.add(st, 'tolerance').onFinishChange(set('tolerance'));
  solver.add(st, 'speed', 0, 20000, 100).name('steps/s (0: no limit)').onFinishChange(set('speed'));
  const params = gui.addFolder('scene parameters (re-run the scene)');
  const values = {};
  for (const p of list(h.params)) {
    values[p.name] = p.value;
    const c = typeof p.value === 'number'
      ? params.add(values, p.name, Math.min(0, 2 * p.value), Math.max(2 * p.value, 1e-9 + 2 * Math.abs(p.default || 1)))
      : params.add(values, p.name);
    c.onFinishChange((v) => send({ cmd: 'param', name: p.name, value: v }));
  }
  const look = gui.addFolder('view');
  const viewState = { colour: h.field || 'none', points: view.points ? view.points.material.size : 6, fit: () => view.fit() };
  look.add(viewState, 'colour', ['none', ...h.fields.map((f) => f.name)]).onChange((v) => {
    const f = h.fields.find((x) => x.name === v) || null;
    view.setField(f);
    send({ cmd: 'field', name: f ? f.name : '' });
  });
  look.add(viewState, 'points', 1, 20, 1).onChange((v) => view.setPointSize(v));
  look.add(viewState, 'fit');
  renderPalette(list(h.palette));
}

// --- selection and the rule palette ---------------------------------------------------------

function argFor(name, i) {
  const sel = studio.selection;
  const ps = sel.filter((s) => s.type === 'particle').map((s) => s.id);
  if (/^(ps|particles)$/.test(name)) return { particles: ps };
  if (/^(xyz|point|position|to)$/.test(name)) return studio.position(ps[0]) ? Array.from(studio.position(ps[0])).map((x) => +x.toFixed(3)) : [0, 0, 0];
  const item = sel[i];
  return item ? { [item.type]: item.id } : null;
}

let armed = null;
function renderPalette(palette) {
  const root = $('rules');
  root.innerHTML = '';
  for (const r of palette) {
    const args = Array.isArray(r.args) ? r.args : [];
    const div = document.createElement('div');
    div.className = 'rule';
    div.dataset.rule = r.key;
    const button = document.createElement('button');
    button.textContent = r.name;
    button.className = 'rule-name';
    const form = document.createElement('div');
    form.hidden = true;
    const inputs = args.map((a) => {
      const label = document.createElement('label');
      label.textContent = a + ' ';
      const input = document.createElement('input');
      input.name = a;
      label.appendChild(input);
      form.appendChild(label);
      form.appendChild(document.createTextNode(' '));
      return input;
    });
    const apply = document.createElement('button');
    apply.textContent = 'apply';
    apply.className = 'apply';
    const cancel = document.createElement('button');
    cancel.textContent = 'cancel';
    form.append(apply, cancel);
    const fill = () => inputs.forEach((input, i) => { const v = argFor(input.name, i); input.value = v === null ? '' : JSON.stringify(v); });
    button.onclick = () => {
      if (armed && armed !== form) armed.hidden = true;
      armed = form;
      form.hidden = false;
      form.fill = fill;
      fill();
      document.body.classList.add('armed');  // thesis fig. 5.10b: black while a rule is armed
      view.setBackground(true);
    };
    const disarm = () => { form.hidden = true; armed = null; document.body.classList.remove('armed'); view.setBackground(false); };
    cancel.onclick = disarm;
    apply.onclick = async () => {
      const missing = inputs.filter((i) => i.value.trim() === '').map((i) => i.name);
      if (missing.length) {  // null, typed, is an argument; an empty field is one forgotten
        say(`${r.name}: give ${missing.join(', ')} (click a particle or a block, or type its id)`, false);
        return;
      }
      let values;
      try {
        values = inputs.map((i) => JSON.parse(i.value));
      } catch (e) {
        say(`${r.name}: an argument is not JSON (${e.message})`, false);
        return;
      }
      const m = await request({ cmd: 'rule', rule: r.key, args: values });
      if (m && m.ok) disarm();
    };
    const argsLine = document.createElement('div');
    argsLine.className = 'args';
    argsLine.textContent = args.length ? '(' + args.join(', ') + ')' : '()';
    div.append(button, argsLine, form);
    root.appendChild(div);
  }
}

function paintSelection() {
  view.selected = new Set(studio.selection.filter((s) => s.type === 'particle').map((s) => s.id));
  if (view.topology) view.paintStates();
  $('selection').textContent = studio.selection.length
    ? studio.selection.map((s) => `${s.type} ${s.id}` + (s.type === 'block' ? ` (${blockLabel(s.id)})` : '')).join(', ')
    : 'click a particle or a block; shift-click adds';
  if (armed && armed.fill) armed.fill();
  const tools = $('selection-tools');
  tools.innerHTML = '';
  const last = studio.selection[studio.selection.length - 1];
  if (!last) return;
  const add = (label, command) => {
    const b = document.createElement('button');
    b.textContent = label;
    b.onclick = () => send(command);
    tools.appendChild(b);
  };
  if (last.type === 'particle') {
    for (const ax of ['x', 'y', 'z', 'xyz']) add('lock ' + ax, { cmd: 'lock', particle: last.id, axes: ax });
    add('unlock', { cmd: 'unlock', particle: last.id, axes: 'xyz' });
  } else {
    const kind = blockLabel(last.id);
    if (kind.startsWith('beam')) { add('3 DOF', { cmd: 'formulation', block: last.id, dofs: 3 }); add('6 DOF', { cmd: 'formulation', block: last.id, dofs: 6 }); }
    if (kind.startsWith('patch')) { add('bars', { cmd: 'formulation', block: last.id, membrane: 'bars' }); add('CST', { cmd: 'formulation', block: last.id, membrane: 'cst' }); }
  }
}

function blockLabel(id) {
  const t = studio.topology;
  const k = t ? Array.prototype.indexOf.call(t.blocks, id) : -1;
  if (k < 0) return '?';
  const kind = P.BLOCK_KINDS[t.blockKind[k]];
  if (kind === 'beam') return `beam, ${t.blockForm[k]} DOF`;
  if (kind === 'patch') return `patch, ${t.blockForm[k] ? 'CST' : 'bars'}`;
  return kind;
}

$('clear-selection').onclick = () => { studio.selection = []; paintSelection(); };

// --- mouse: pick, select, drag (a goal while held) --------------------------------------------

const canvas = view.renderer.domElement;
let press = null, dragTarget = null;
canvas.addEventListener('pointerdown', (e) => {
  if (e.button !== 0 || studio.preview) return;
  const hit = view.pick(e.offsetX, e.offsetY);
  press = { x: e.offsetX, y: e.offsetY, hit, shift: e.shiftKey, moved: false };
  if (hit && hit.type === 'particle') { view.controls.enabled = false; canvas.setPointerCapture(e.pointerId); }
});
canvas.addEventListener('pointermove', (e) => {
  if (!press || !press.hit || press.hit.type !== 'particle') return;
  if (!press.moved && Math.hypot(e.offsetX - press.x, e.offsetY - press.y) < 3) return;
  press.moved = true;
  dragTarget = view.dragPoint(press.hit.index, e.offsetX, e.offsetY);
});
canvas.addEventListener('pointerup', (e) => {
  if (!press) return;
  if (press.moved) { dragTarget = null; send({ cmd: 'release' }); }
  else if (!press.moved && Math.hypot(e.offsetX - press.x, e.offsetY - press.y) < 3) {
    const hit = press.hit;
    if (!hit) { if (!press.shift) studio.selection = []; }
    else {
      const item = { type: hit.type, id: hit.id };
      if (press.shift) studio.selection.push(item);
      else studio.selection = [item];
    }
    paintSelection();
  }
  view.controls.enabled = true;
  press = null;
});

// --- run controls, undo, save, timeline, snapshots ------------------------------------------

$('pause').onclick = () => send({ cmd: 'pause' });
$('run').onclick = () => send({ cmd: 'run' });
$('step').onclick = () => send({ cmd: 'step', n: 1 });
$('undo').onclick = () => send({ cmd: 'undo' });
$('save').onclick = () => send({ cmd: 'save' });
let scrubbing = false, scrubTimer = null;
function onStatus(s) {
  const scrub = $('scrub');
  const atEnd = Number(scrub.value) >= Number(scrub.max);
  scrub.max = s.productions;
  if (!scrubbing && atEnd) scrub.value = s.productions;
  const snaps = $('snapshots');
  snaps.innerHTML = '';
  s.snapshots.slice(-6).forEach((p, i, shown) => {
    const b = document.createElement('button');
    b.textContent = `eq. @${p.steps}`;
    b.title = `equilibrium at step ${p.steps}, residual ${p.residual.toExponential(2)} N: branch from here`;
    b.onclick = () => send({ cmd: 'branch', snapshot: s.snapshots.length - shown.length + i });
    snaps.appendChild(b);
  });
}
$('scrub').addEventListener('input', () => {
  scrubbing = true;
  clearTimeout(scrubTimer);
  scrubTimer = setTimeout(showTimeline, 120);
});
async function showTimeline() {
  const scrub = $('scrub');
  const index = Number(scrub.value);
  if (index >= Number(scrub.max)) return backToLive();
  const m = await request({ cmd: 'timeline', index });
  if (!m || !m.ok) return;
  $('scrub-label').textContent = `production ${index} of ${m.value.of}, step ${m.value.steps}`;
  $('branch').hidden = false;
  $('live').hidden = false;
}
function backToLive() {
  scrubbing = false;
  studio.preview = null;
  $('scrub').value = $('scrub').max;
  $('scrub-label').textContent = 'live';
  $('branch').hidden = true;
  $('live').hidden = true;
  if (studio.topology) { view.setTopology(studio.topology); if (studio.frame) view.setFrame(studio.frame); paintSelection(); }
}
$('live').onclick = backToLive;
$('branch').onclick = async () => { await request({ cmd: 'branch', index: Number($('scrub').value) }); backToLive(); };

// --- the draw loop: one drag target per animation frame ---------------------------------------

// Draws only when something changed (a frame, the camera, a colour), so an
// idle page costs the machine, and the solver beside it, nothing.
//
// Without a GPU the browser draws on the CPU (SwiftShader), and a large
// model costs it more per frame than a live picture allows; part of that is
// per pixel. So while a large model (view.large) moves, the page draws it at
// half resolution (a quarter of the pixels) under software WebGL, and with
// a GPU once a draw holds back the next animation frame by more than
// SLOW_DRAW_MS (a running mean: studio.drawGap); once nothing has changed
// for REST_MS it draws again at full resolution. A small model draws fast
// (a slow frame there is the machine's load, which a smaller canvas would
// not help).
const SLOW_DRAW_MS = 40, REST_MS = 300;
let dirty = true, drewAt = null, lastDraw = 0;
view.controls.addEventListener('change', () => { dirty = true; });
studio.renderMs = 0;
studio.drawGap = 0;
function loop(now) {
  if (drewAt !== null) {  // the first animation frame after a draw: how long the draw held it back
    studio.drawGap = 0.8 * studio.drawGap + 0.2 * (now - drewAt);
    drewAt = null;
    if (studio.drawGap > SLOW_DRAW_MS && view.large) view.setScale(0.5);
  }
  if (dragTarget && press && press.hit) {
    send({ cmd: 'drag', particle: press.hit.id, to: dragTarget });
    if (!dragSent) dragSent = { at: performance.now(), step: null };
    dragTarget = null;
  }
  view.controls.update();
  let dragAt = null;
  if (undrawn) {
    if (view.setFrame(undrawn)) {
      studio.drawnFrames = (studio.drawnFrames || 0) + 1;
      if (view.large && view.software) view.setScale(0.5);
    }
    dragAt = undrawn.dragAt ?? null;
    undrawn = null;
  }
  if (drawing && view.scale < 1 && now - lastDraw > REST_MS && !dirty && !view.changed) {
    view.setScale(1);  // at rest: the full picture once
    studio.drawGap = 0;
  }
  if (drawing && (dirty || view.changed)) {
    const t0 = performance.now();
    view.render();
    if (dragAt !== null) studio.drawLatency.push(performance.now() - dragAt);
    studio.renderMs = 0.9 * studio.renderMs + 0.1 * (performance.now() - t0);
    dirty = view.changed = false;
    drewAt = now;
    lastDraw = now;
  }
  updateStats();
  requestAnimationFrame(loop);
}
connect();
requestAnimationFrame(loop);
