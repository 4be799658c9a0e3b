// The page draws the default scene and a scene with every vertex state: the
// screenshot is not blank, and the colour drawn at the projected position of
// each well-separated particle is its state's colour (thesis 4.2.6).
import { check, openPage, run, scene, screenshot, until } from './harness.mjs';

const STATE_COLOURS = [0x000000, 0x808080, 0xff0000, 0xffff00, 0x00ffff, 0x800080, 0xff8c00, 0x2e8b57, 0xff1493];
const STATES = ['isolated', 'passive', 'lock', 'full-lock', 'simple', 'shared', 'parent', 'child', 'volatile'];

// Particles at least 10 px from every other one on screen, with their
// state, projected position and the colour drawn there.
async function sampleStates(page) {
  return page.evaluate(() => {
    const t = studio.topology, pts = [];
    for (let k = 0; k < t.count; ++k) pts.push(studio.project(t.ids[k]));
    const out = [];
    for (let k = 0; k < t.count; ++k) {
      const [x, y] = pts[k];
      if (x < 330 || x > 1000 || y < 10 || y > 740) continue;  // off the panels
      if (pts.some((q, j) => j !== k && Math.hypot(q[0] - x, q[1] - y) < 10)) continue;
      out.push({ id: t.ids[k], state: t.states[k], xy: [x, y], rgb: studio.pixel(x, y) });
    }
    return out;
  });
}

function checkColours(samples, label) {
  let matched = 0;
  const seen = new Set();
  for (const s of samples) {
    const want = STATE_COLOURS[s.state];
    const rgb = [(want >> 16) & 255, (want >> 8) & 255, want & 255];
    const off = Math.max(...rgb.map((v, i) => Math.abs(v - s.rgb[i])));
    if (off > 24) throw new Error(`${label}: particle ${s.id} (${STATES[s.state]}) at ${s.xy.map(Math.round)} is drawn ${s.rgb}, not ${rgb}`);
    matched++;
    seen.add(STATES[s.state]);
  }
  return { matched, seen: [...seen].sort() };
}

await run('draw: default scene', scene('scripts/examples/grow.lua'), ['--speed', '0'], async ({ studio, browser }) => {
  const page = await openPage(browser, studio.url);
  await until(page, () => studio.status && studio.status.converged && studio.frame && studio.frame.step > 6000);
  await page.waitForTimeout(300);
  const blank = await page.evaluate(() => {
    const c = studio.view.renderer.domElement, g = document.createElement('canvas');
    g.width = c.width; g.height = c.height;
    const x = g.getContext('2d');
    x.drawImage(c, 0, 0);
    const d = x.getImageData(0, 0, g.width, g.height).data;
    let ink = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] < 200 || d[i + 1] < 200 || d[i + 2] < 200) ink++;
    return { ink, of: d.length / 4 };
  });
  await screenshot(page, 'studio-grow.png');
  check(blank.ink > 2000, `the default scene is drawn: ${blank.ink} of ${blank.of} pixels not white (> 2000)`);
  const particles = await page.evaluate(() => studio.topology.count);
  check(particles === 128, `all 128 particles of the grown network are on the page (${particles})`);
  const r = checkColours(await sampleStates(page), 'grow');
  check(r.matched >= 10, `${r.matched} separated particles drawn in their state's colour (${r.seen.join(', ')})`);
  check(page.problems.length === 0, 'no error on the page: ' + page.problems.join('; '));
});

await run('draw: every state', scene('tests/studio/states.lua'), ['--speed', '0'], async ({ studio, browser }) => {
  const page = await openPage(browser, studio.url);
  await until(page, () => studio.status && studio.status.converged);
  // Sampled again until every state shows or 5 s pass: under a loaded
  // machine the page may draw the converged frame a little later.
  const want = ['full-lock', 'isolated', 'lock', 'passive', 'shared', 'simple'];
  let r;
  for (let tries = 0; tries < 20; ++tries) {
    await page.waitForTimeout(250);
    r = checkColours(await sampleStates(page), 'states');
    if (want.every((s) => r.seen.includes(s))) break;
  }
  await screenshot(page, 'studio-states.png');
  check(want.every((s) => r.seen.includes(s)), `every thesis state is drawn in its colour: ${r.seen.join(', ')} (${r.matched} particles)`);
  check(page.problems.length === 0, 'no error on the page: ' + page.problems.join('; '));
  const hasSurface = await page.evaluate(() => studio.topology.triangles.length / 3);
  check(hasSurface === 18, `the 3 x 3 patch is drawn as 18 triangles (${hasSurface})`);
});

// A net dense on screen (its edges a few pixels long): the patch bars are
// left out, the simple particles are shown by the surface's colour, and the
// others (the locked corners) still as dots in their state's colour; close
// up again, every particle is a dot.
await run('draw: a dense net', scene('bench/studio_net.lua'), ['--param', 'particles=5000', '--speed', '0'], async ({ studio, browser }) => {
  const page = await openPage(browser, studio.url);
  await page.evaluate(() => studio.request({ cmd: 'pause' }));
  const away = (factor) => page.evaluate((f) => {
    const v = studio.view, c = v.controls;
    v.camera.position.sub(c.target).multiplyScalar(f).add(c.target);
    c.update();
  }, factor);
  await away(3);
  const dense = await until(page, () => studio.view.frame && studio.view.dots.visible && studio.view.scale === 1 &&
                                      { edge: studio.view.edgePixels, dots: studio.view.dots.geometry.drawRange.count, bars: studio.view.patchBars.visible });
  check(dense.edge < 6 && !dense.bars, `far away the net's edges are ${dense.edge.toFixed(1)} px on screen and its bars are left out`);
  await screenshot(page, 'studio-dense.png');
  const shown = await page.evaluate(() => {
    const t = studio.topology, out = [];
    let simple = -1;
    for (let k = 0; k < t.count; ++k) {
      if (t.states[k] !== 4) { const [x, y] = studio.project(t.ids[k]); out.push({ id: t.ids[k], state: t.states[k], xy: [x, y], rgb: studio.pixel(x, y) }); }
      else if (simple < 0 && k > t.count / 2) simple = k;
    }
    const [x, y] = studio.project(t.ids[simple]);
    return { others: out, simple: studio.pixel(x, y), simpleId: t.ids[simple], count: t.count };
  });
  check(dense.dots === shown.others.length && dense.dots < shown.count / 10, `${dense.dots} dots drawn, the particles that are not simple (of ${shown.count})`);
  const r = checkColours(shown.others, 'dense');
  check(r.matched >= 4, `those ${r.matched} are drawn in their state's colour (${r.seen.join(', ')})`);
  const [red, green, blue] = shown.simple;
  check(green > red + 40 && blue > red + 40 && Math.abs(green - blue) < 24, `a simple particle in the middle shows the surface tinted with the simple state's cyan (${shown.simple})`);
  // A new topology comes a moment before its first frame (each page's hello
  // gets one): meanwhile the picture and the particles' places stay.
  const waiting = await page.evaluate((id) => {
    const v = studio.view, before = studio.project(id);
    v.setTopology(studio.topology);
    v.render();
    const during = { xy: studio.project(id), rgb: studio.pixel(...before) };
    v.topology = null;  // none of its particles known before: none has a place yet
    v.setTopology(studio.topology);
    v.render();
    const unknown = studio.pixel(...before);
    v.setFrame(studio.frame);
    v.render();  // what the page shows derived again (the new objects start with every dot shown)
    return { before, during, unknown };
  }, shown.simpleId);
  const moved = Math.hypot(waiting.during.xy[0] - waiting.before[0], waiting.during.xy[1] - waiting.before[1]);
  check(moved < 1e-3 && waiting.during.rgb.every((c, i) => Math.abs(c - shown.simple[i]) <= 2),
        `a topology without its frame yet leaves the particle in place (${moved.toFixed(4)} px) and the picture as it was (${waiting.during.rgb})`);
  check(waiting.unknown.every((c, i) => Math.abs(c - shown.simple[i]) <= 2),
        `nor is a topology of particles not seen before drawn without its frame (${waiting.unknown})`);
  await away(1 / 3);
  // Once the page has derived the view for the new camera (edgePixels
  // moved from the far value): before that, the last render's view is read.
  const close = await until(page, (far) => studio.view.edgePixels !== far && studio.view.points.visible &&
                                           !studio.view.dots.visible &&
                                           { edge: studio.view.edgePixels, bars: studio.view.patchBars.visible }, dense.edge);
  check(close.edge >= 6 && close.bars, `close up (edges ${close.edge.toFixed(1)} px) every particle is a dot again and the bars are drawn`);
  check(page.problems.length === 0, 'no error on the page: ' + page.problems.join('; '));
});
