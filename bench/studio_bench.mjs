// `bash bench/run.sh studio`: what a page costs and gets. For nets of 2K,
// 20K and 100K particles (bench/studio_net.lua) it measures the solver's
// steps per second with no page, then with a headless Chromium page asking
// for 60 frames per second: the frames the page receives per second, its
// draw time, the steps per second meanwhile, and the latency from a mouse
// drag to the first frame that shows it (the frame of a later step than the
// one the drag was applied at). Goals (issue 15): >= 30 frames/s at 20K,
// drag-to-frame < 50 ms, the page costing < 10 % of the steps.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { openBrowser, startStudio } from '../tests/studio/harness.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const sizes = (process.argv[2] || '2000,20000,100000').split(',').map(Number);
const seconds = Number(process.argv[3] || 5);
const net = path.join(here, 'studio_net.lua');
// CPU seconds the studio process has used (user + system), from /proc: on a
// loaded machine the wall-clock steps/s measure the machine, the CPU time per
// step measures what a page costs the studio itself.
const cpu = (pid) => {
  const f = fs.readFileSync(`/proc/${pid}/stat`, 'utf8').split(') ')[1].split(' ');
  return (Number(f[11]) + Number(f[12])) / 100;
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

const rows = [];
for (const size of sizes) {
  const studio = await startStudio(net, ['--param', `particles=${size}`, '--speed', '0', '--tolerance', '1e-12', '--no-wait']);
  try {
    say(`${size} particles: steps without a page`);
    const alone = await stepsWithoutPage(studio.url, studio.proc.pid);
    say(`${size} particles: ${alone.rate.toFixed(0)} steps/s; opening the page`);
    const browser = await openBrowser();
    const page = await browser.newPage();
    await page.goto(studio.url + '?fps=60');
    await page.waitForFunction(() => window.studio && studio.frame, null, { timeout: 120000 });
    await sleep(1500);
    const m0 = await page.evaluate(() => ({ frames: studio.frames, step: studio.frame.step, at: performance.now() }));
    const c0 = cpu(studio.proc.pid);
    await sleep(seconds * 1000);
    const m1 = await page.evaluate(() => ({ frames: studio.frames, step: studio.frame.step, at: performance.now(), draw: studio.renderMs, n: studio.frame.count }));
    const c1 = cpu(studio.proc.pid);
    const dt = (m1.at - m0.at) / 1000;
    say(`${size} particles: ${((m1.frames - m0.frames) / dt).toFixed(1)} frames/s; dragging`);
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
    const lat = (await page.evaluate(() => studio.dragLatency)).sort((a, b) => a - b);
    await browser.close();
    rows.push({ particles: m1.n, bare: alone.rate, paged: (m1.step - m0.step) / dt,
                cpuAlone: alone.cpuPerStep, cpuPaged: (c1 - c0) / (m1.step - m0.step), fps: (m1.frames - m0.frames) / dt, draw: m1.draw,
                latency: lat.length ? lat[Math.floor(lat.length / 2)] : NaN, drags: lat.length });
  } finally {
    await studio.stop();
  }
}

const pad = (s, n) => String(s).padStart(n);
const load = fs.readFileSync('/proc/loadavg', 'utf8').split(' ').slice(0, 3).join(' ');
console.log(`\nstudio: a headless Chromium page asking 60 frames/s (load average ${load} on ${(await import('node:os')).cpus().length} cores)`);
console.log('drag-to-frame: median over the drags of one gesture; CPU ms/step: the studio process\'s own CPU time per solver step');
console.log(`${pad('particles', 10)} ${pad('steps/s alone', 14)} ${pad('with page', 10)} ${pad('wall cost', 10)} ${pad('CPU ms/step alone', 18)} ${pad('with page', 10)} ${pad('CPU cost', 9)} ${pad('frames/s', 9)} ${pad('draw ms', 8)} ${pad('drag->frame ms', 15)}`);
for (const r of rows)
  console.log(`${pad(r.particles, 10)} ${pad(r.bare.toFixed(0), 14)} ${pad(r.paged.toFixed(0), 10)} ${pad((100 * (1 - r.paged / r.bare)).toFixed(1) + ' %', 10)} ` +
              `${pad((1e3 * r.cpuAlone).toFixed(3), 18)} ${pad((1e3 * r.cpuPaged).toFixed(3), 10)} ${pad((100 * (r.cpuPaged / r.cpuAlone - 1)).toFixed(1) + ' %', 9)} ` +
              `${pad(r.fps.toFixed(1), 9)} ${pad(r.draw.toFixed(1), 8)} ${pad(r.latency.toFixed(1) + ` (${r.drags})`, 15)}`);
