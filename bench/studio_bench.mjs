// `bash bench/run.sh studio`: what a page costs and gets. For nets of 2K,
// 20K and 100K particles (bench/studio_net.lua) it measures the solver's
// steps per second with no page, then with a headless Chromium page asking
// for 60 frames per second: the frames the page receives and draws per
// second, its draw time, the steps per second meanwhile, the studio's CPU
// time per step (and the part its server threads spend), and the latency
// from a mouse drag to the first frame that shows it (the frame of a later
// step than the one the drag was applied at), received and drawn. Then the
// same page not drawing (?draw=0): without a GPU, Chromium's WebGL is a
// software rasteriser on the solver's cores, and this row shows what the
// studio delivers without it. Goals (issue 15): >= 30 frames/s at 20K,
// drag-to-frame < 50 ms, the page costing < 10 % of the steps. Where the
// drawing's time goes: the CPU time of Chromium's processes per frame drawn
// (the GPU process rasterises WebGL and composites the page; the renderer
// runs the page's script), and the resolution the page drew at (1: full,
// 0.5: half, while a large model moves and draws slowly: web/src/studio.js).
// STUDIO_WEB=DIR serves another build of the page (e.g. an older one, to
// compare on the same machine in the same session). STUDIO_PIN=1 keeps the
// studio on core 0 and this script with its Chromium on core 1: the page
// then has a core of its own, as on a designer's machine, where a GPU
// draws it, and the wall cost measures what the page costs the solver
// rather than the software rasteriser's share of two cores.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { openBrowser, startStudio } from '../tests/studio/harness.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const loadAtStart = fs.readFileSync('/proc/loadavg', 'utf8').split(' ').slice(0, 3).join(' ');
const sizes = (process.argv[2] || '2000,20000,100000').split(',').map(Number);
const seconds = Number(process.argv[3] || 5);
const net = path.join(here, 'studio_net.lua');
const web = process.env.STUDIO_WEB ? ['--web', path.resolve(process.env.STUDIO_WEB)] : [];
const pinned = process.env.STUDIO_PIN === '1';
// Every thread of a process on one core; children started later inherit it.
const pin = (pid, core) => execFileSync('taskset', ['-a', '-p', '-c', String(core), String(pid)], { stdio: 'ignore' });
if (pinned) pin(process.pid, 1);
// CPU seconds the studio process has used (user + system), from /proc: on a
// loaded machine the wall-clock steps/s measure the machine, the CPU time per
// step measures what a page costs the studio itself.
const cpu = (pid) => {
  const f = fs.readFileSync(`/proc/${pid}/stat`, 'utf8').split(') ')[1].split(' ');
  return (Number(f[11]) + Number(f[12])) / 100;
};
// The same per thread: the solver's is the busiest; the rest (the sender,
// civetweb's threads, the previews) are the studio's own work for the pages.
const threadCpu = (pid) => {
  const out = new Map();
  for (const t of fs.readdirSync(`/proc/${pid}/task`)) {
    try {
      const f = fs.readFileSync(`/proc/${pid}/task/${t}/stat`, 'utf8').split(') ')[1].split(' ');
      out.set(t, (Number(f[11]) + Number(f[12])) / 100);
    } catch { /* the thread ended */ }
  }
  return out;
};
// CPU seconds of Chromium's processes (this process's descendants but the
// studio), by kind: gpu-process, renderer, the rest.
const chromiumCpu = (studioPid) => {
  const procs = [];
  for (const d of fs.readdirSync('/proc')) {
    if (!/^\d+$/.test(d)) continue;
    try {
      const f = fs.readFileSync(`/proc/${d}/stat`, 'utf8').split(') ')[1].split(' ');
      const type = (fs.readFileSync(`/proc/${d}/cmdline`, 'utf8').match(/--type=([a-z-]+)/) || [])[1];
      procs.push({ pid: Number(d), ppid: Number(f[1]), cpu: (Number(f[11]) + Number(f[12])) / 100, type: type === 'gpu-process' || type === 'renderer' ? type : 'other' });
    } catch { /* ended */ }
  }
  const ours = new Set([process.pid]);
  for (let grew = true; grew;) {
    grew = false;
    for (const p of procs) if (!ours.has(p.pid) && ours.has(p.ppid) && p.pid !== studioPid) { ours.add(p.pid); grew = true; }
  }
  const out = { 'gpu-process': 0, renderer: 0, other: 0 };
  for (const p of procs) if (ours.has(p.pid) && p.pid !== process.pid) out[p.type] += p.cpu;
  return out;
};
const serverCpu = (before, after) => {
  const d = [...after].map(([t, s]) => s - (before.get(t) || 0)).sort((a, b) => b - a);
  return d.slice(1).reduce((a, b) => a + b, 0);
};
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const say = (what) => process.stderr.write(`[studio bench ${new Date().toISOString().slice(11, 19)}] ${what}\n`);

// Steps per second seen by a socket that asks for no frames (frame_rate 0:
// the studio builds none), from the step counts of two status replies.
async function stepsWithoutPage(url, pid) {
  const ws = new WebSocket(url.replace('http', 'ws').replace(/\/(\?|$)/, '/ws$1'));
  const statuses = [];
  ws.onmessage = (e) => { if (typeof e.data === 'string') { const m = JSON.parse(e.data); if (m.type === 'status') statuses.push({ at: performance.now(), steps: m.steps }); } };
  await new Promise((r) => { ws.onopen = r; });
  ws.send(JSON.stringify({ cmd: 'hello' }));
  const poll = async () => { ws.send(JSON.stringify({ cmd: 'run' })); await sleep(300); return statuses[statuses.length - 1]; };
  await sleep(1500);
  let a = await poll();
  while (!a || a.steps === 0) { await sleep(500); a = await poll(); }
  const c0 = cpu(pid);
  await sleep(seconds * 1000);
  const b = await poll();
  const c1 = cpu(pid);
  ws.close();
  return { rate: (b.steps - a.steps) / ((b.at - a.at) / 1000), cpuPerStep: (c1 - c0) / (b.steps - a.steps) };
}

// Frames received and drawn per second by a page, the solver's steps and
// the studio's CPU time meanwhile.
async function measurePage(page, pid) {
  await sleep(1500);
  const probe = () => page.evaluate(() => ({ frames: studio.frames, drawn: studio.drawnFrames || 0, step: studio.frame.step,
                                             at: performance.now(), draw: studio.renderMs, n: studio.frame.count, scale: studio.view.scale ?? 1 }));
  const m0 = await probe(), c0 = cpu(pid), t0 = threadCpu(pid), g0 = chromiumCpu(pid);
  await sleep(seconds * 1000);
  const m1 = await probe(), c1 = cpu(pid), t1 = threadCpu(pid), g1 = chromiumCpu(pid);
  const dt = (m1.at - m0.at) / 1000, drawn = Math.max(1, m1.drawn - m0.drawn);
  return { n: m1.n, steps: (m1.step - m0.step) / dt, cpuPerStep: (c1 - c0) / (m1.step - m0.step), serverPerStep: serverCpu(t0, t1) / (m1.step - m0.step),
           fps: (m1.frames - m0.frames) / dt, drawn: (m1.drawn - m0.drawn) / dt, draw: m1.draw, scale: m1.scale,
           gpuPerFrame: (g1['gpu-process'] - g0['gpu-process']) / drawn, rendererPerFrame: (g1.renderer - g0.renderer) / drawn };
}

const median = (xs) => { xs.sort((a, b) => a - b); return xs.length ? xs[Math.floor(xs.length / 2)] : NaN; };
const rows = [];
for (const size of sizes) {
  const studio = await startStudio(net, ['--param', `particles=${size}`, '--speed', '0', '--tolerance', '1e-12', '--no-wait', ...web]);
  if (pinned) pin(studio.proc.pid, 0);
  const browser = await openBrowser();
  try {
    say(`${size} particles: steps without a page`);
    const alone = await stepsWithoutPage(studio.url, studio.proc.pid);
    say(`${size} particles: ${alone.rate.toFixed(0)} steps/s; opening the page`);
    const page = await browser.newPage();
    await page.goto(studio.url + '?fps=60');
    await page.waitForFunction(() => window.studio && studio.frame, null, { timeout: 120000 });
    const paged = await measurePage(page, studio.proc.pid);
    say(`${size} particles: ${paged.fps.toFixed(1)} frames/s; dragging`);
    // Drag a particle near the middle for a second and a half.
    const target = await page.evaluate(() => {
      const t = studio.topology, k = Math.floor(t.count / 2) + Math.floor(Math.sqrt(t.count) / 2);
      const [x, y] = studio.project(t.ids[k]);
      return { x, y };
    });
    await page.mouse.move(target.x, target.y);
    await page.mouse.down();
    for (let k = 1; k <= 30; ++k) { await page.mouse.move(target.x, target.y - 2 * k); await sleep(50); }
    await page.mouse.up();
    const lat = await page.evaluate(() => studio.dragLatency), drawnLat = await page.evaluate(() => studio.drawLatency);
    await page.close();
    // The control: the same page receiving frames without drawing them
    // (?draw=0), so without the browser's software WebGL.
    say(`${size} particles: a page that does not draw`);
    const bare = await browser.newPage();
    await bare.goto(studio.url + '?fps=60&draw=0');
    await bare.waitForFunction(() => window.studio && studio.frame, null, { timeout: 120000 });
    const undrawn = await measurePage(bare, studio.proc.pid);
    rows.push({ particles: paged.n, bare: alone.rate, paged: paged.steps, cpuAlone: alone.cpuPerStep, cpuPaged: paged.cpuPerStep, server: paged.serverPerStep,
                fps: paged.fps, drawnFps: paged.drawn, draw: paged.draw, undrawnFps: undrawn.fps, undrawnSteps: undrawn.steps,
                scale: paged.scale, gpu: paged.gpuPerFrame, renderer: paged.rendererPerFrame,
                latency: median(lat), drawnLatency: median(drawnLat), drags: lat.length });
  } finally {
    await browser.close();
    await studio.stop();
  }
}

const pad = (s, n) => String(s).padStart(n);
const load = fs.readFileSync('/proc/loadavg', 'utf8').split(' ').slice(0, 3).join(' ');
const renderer = await (async () => {  // what draws the page's WebGL (a software rasteriser without a GPU)
  const browser = await openBrowser();
  const page = await browser.newPage();
  const name = await page.evaluate(() => {
    const gl = document.createElement('canvas').getContext('webgl2');
    const info = gl && gl.getExtension('WEBGL_debug_renderer_info');
    return info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : 'unknown';
  });
  await browser.close();
  return name.includes('SwiftShader') ? 'SwiftShader (software)' : name;
})();
console.log(`\nstudio: a headless Chromium page asking 60 frames/s (load average ${loadAtStart} at the start, ${load} at the end, on ${(await import('node:os')).cpus().length} cores; WebGL ${renderer})${pinned ? '; pinned: the studio on core 0, Chromium on core 1' : ''}`);
console.log('frames/s got, drawn: received by the page and drawn by it; not drawing: the same page with ?draw=0 (no WebGL), and the steps/s beside it');
console.log('drag->frame: median over the drags of one gesture, to the frame received / drawn; CPU ms/step: the studio process\'s own CPU time per solver step;');
console.log('server µs/step: of that CPU time, the threads other than the solver\'s (they send the frames); the solver thread\'s own grows too when the browser competes for the cores and caches');
console.log('draw ms: the page\'s script in render() (the drawing itself is Chromium\'s GPU process); res: the resolution drawn at the end (0.5 while a large model moves and draws slowly);');
console.log('GPU, renderer ms/frame: CPU time of Chromium\'s GPU process (WebGL rasterised by SwiftShader, the page composited) and of the page\'s renderer, per frame drawn');
console.log(`${pad('particles', 10)} ${pad('steps/s alone', 14)} ${pad('with page', 10)} ${pad('wall cost', 10)} ${pad('CPU ms/step alone', 18)} ${pad('with page', 10)} ${pad('CPU cost', 9)} ${pad('server µs/step', 15)} ` +
            `${pad('frames/s got', 13)} ${pad('drawn', 6)} ${pad('draw ms', 8)} ${pad('res', 4)} ${pad('GPU ms/frame', 13)} ${pad('renderer', 9)} ${pad('drag->frame ms got', 19)} ${pad('drawn', 6)} ${pad('not drawing: frames/s', 22)} ${pad('steps/s', 8)}`);
for (const r of rows)
  console.log(`${pad(r.particles, 10)} ${pad(r.bare.toFixed(0), 14)} ${pad(r.paged.toFixed(0), 10)} ${pad((100 * (1 - r.paged / r.bare)).toFixed(1) + ' %', 10)} ` +
              `${pad((1e3 * r.cpuAlone).toFixed(3), 18)} ${pad((1e3 * r.cpuPaged).toFixed(3), 10)} ${pad((100 * (r.cpuPaged / r.cpuAlone - 1)).toFixed(1) + ' %', 9)} ${pad((1e6 * r.server).toFixed(1), 15)} ` +
              `${pad(r.fps.toFixed(1), 13)} ${pad(r.drawnFps.toFixed(1), 6)} ${pad(r.draw.toFixed(1), 8)} ${pad(r.scale, 4)} ${pad((1e3 * r.gpu).toFixed(1), 13)} ${pad((1e3 * r.renderer).toFixed(1), 9)} ${pad(r.latency.toFixed(1) + ` (${r.drags})`, 19)} ${pad(r.drawnLatency.toFixed(1), 6)} ` +
              `${pad(r.undrawnFps.toFixed(1), 22)} ${pad(r.undrawnSteps.toFixed(0), 8)}`);
