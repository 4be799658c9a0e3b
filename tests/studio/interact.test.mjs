// Interaction with the default scene while it runs: a mouse drag moves a
// particle on the server and the model relaxes around it; rule 13 applied
// from the palette adds a particle; a refused rule shows its reason; the
// timeline shows an earlier model; the session's journal, saved by Ctrl-C,
// replays with `tendril replay` to the same model database, byte for byte.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { check, openPage, run, scene, screenshot, screenshotPixels, slow, tendril, until } from './harness.mjs';

// A free (unlocked) particle of the given state at least 14 px from all others on screen,
// inside the drawing (not under a panel).
async function lonely(page, wantState, exclude = []) {
  return page.evaluate(([want, exclude]) => {
    const t = studio.topology, pts = [];
    for (let k = 0; k < t.count; ++k) pts.push(studio.project(t.ids[k]));
    for (let k = 0; k < t.count; ++k) {
      const [x, y] = pts[k];
      if (t.states[k] !== want || t.locks[k] || exclude.includes(t.ids[k]) || x < 360 || x > 930 || y < 120 || y > 700) continue;
      if (pts.some((q, j) => j !== k && Math.hypot(q[0] - x, q[1] - y) < 14)) continue;
      return { id: t.ids[k], x, y };
    }
    return null;
  }, [wantState, exclude]);
}

const CHILD = 7;
const dist = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

await run('interact', scene('scripts/examples/grow.lua'), ['--speed', '0'], async ({ studio, browser }) => {
  const page = await openPage(browser, studio.url);
  await until(page, () => studio.status && studio.status.converged && studio.frame.step > 6000);

  // --- drag -------------------------------------------------------------------------
  const p = await lonely(page, CHILD);
  check(p !== null, `a child particle to drag: ${JSON.stringify(p)}`);
  const before = await page.evaluate((id) => studio.position(id), p.id);
  const others = await page.evaluate(() => Array.from(studio.frame.positions));
  await page.mouse.move(p.x, p.y);
  await page.mouse.down();
  for (let k = 1; k <= 10; ++k) await page.mouse.move(p.x, p.y - 8 * k);
  await page.waitForTimeout(1500);
  const held = await page.evaluate((id) => studio.position(id), p.id);
  const moved = dist(before, held);
  const around = await page.evaluate((was) => {
    let n = 0;
    const now = studio.frame.positions;
    for (let k = 0; k < now.length; k += 3) if (Math.hypot(now[k] - was[k], now[k + 1] - was[k + 1], now[k + 2] - was[k + 2]) > 1e-3) n++;
    return n;
  }, others);
  await screenshot(page, 'studio-drag.png');
  await page.mouse.up();
  await until(page, () => studio.replies.some((r) => r.cmd === 'release'));
  check(moved > 0.05, `the dragged particle moved ${moved.toFixed(3)} m on the server (> 0.05 m)`);
  check(around > 5, `${around} other particles moved with it (> 5): the model relaxes around the drag`);
  const latency = await page.evaluate(() => studio.dragLatency);
  check(latency.length >= 1, `drag-to-frame latency measured: ${latency.map((x) => x.toFixed(1)).join(', ')} ms`);
  await until(page, () => studio.status.converged && studio.frame.residual < 1e-3);
  const residual = await page.evaluate(() => studio.frame.residual);
  check(residual < 1e-3, `released, the model relaxed back to equilibrium (residual ${residual.toExponential(2)} N < 1e-3)`);

  // --- rule 13 from the palette --------------------------------------------------------------
  const pair = await page.evaluate(() => {
    const t = studio.topology, pts = [];
    for (let k = 0; k < t.count; ++k) pts.push(studio.project(t.ids[k]));
    const free = (k) => pts[k][0] > 360 && pts[k][0] < 930 && pts[k][1] > 120 && pts[k][1] < 700 &&
      !pts.some((q, j) => j !== k && Math.hypot(q[0] - pts[k][0], q[1] - pts[k][1]) < 14);
    for (let e = 0; e < t.edgeKind.length; ++e) {
      const a = t.edges[2 * e], b = t.edges[2 * e + 1];
      if (t.edgeKind[e] === 1 && free(a) && free(b)) return [{ id: t.ids[a], x: pts[a][0], y: pts[a][1] }, { id: t.ids[b], x: pts[b][0], y: pts[b][1] }];
    }
    return null;
  });
  check(pair !== null, `two consecutive beam particles to pick: ${pair && pair.map((q) => q.id)}`);
  await page.mouse.click(pair[0].x, pair[0].y);
  await page.keyboard.down('Shift');
  await page.mouse.click(pair[1].x, pair[1].y);
  await page.keyboard.up('Shift');
  const selected = await page.evaluate(() => studio.selection.map((s) => s.id));
  check(selected.join() === pair.map((q) => q.id).join(), `both are selected by clicking: ${selected}`);
  const count0 = await page.evaluate(() => studio.topology.count);
  await page.click('div[data-rule="insert"] .rule-name');
  await page.click('div[data-rule="insert"] .apply');
  const reply = await until(page, () => studio.replies.find((r) => r.cmd === 'rule'));
  check(reply.ok, `rule 13 applied from the palette: ${JSON.stringify(reply.value || reply.message)}`);
  await until(page, (n) => studio.topology.count === n + 1, count0);
  check(true, `the model has one particle more (${count0} -> ${count0 + 1})`);

  // --- a refused rule shows why ----------------------------------------------------------------
  // The model moves on after the insertion: look again for up to 5 s for a
  // child particle clear of the others, and click it until it is the
  // selection (a frame that came between the look and the click may have
  // moved it from under the cursor).
  let q = null, picked = [];
  for (let tries = 0; tries < 20; ++tries) {
    q = await lonely(page, CHILD, [p.id]);
    if (q !== null) {
      await page.mouse.click(q.x, q.y);
      picked = await page.evaluate(() => studio.selection.map((s) => s.id));
      if (picked.length === 1 && picked[0] === q.id) break;
    }
    await page.waitForTimeout(250);
  }
  check(q !== null && picked.join() === String(q.id), `another child particle picked by clicking: ${JSON.stringify(q)} (${picked})`);
  await page.click('div[data-rule="delete_particle"] .rule-name');
  await page.click('div[data-rule="delete_particle"] .apply');
  await until(page, () => document.getElementById('message').className === 'refused');
  const why = await page.textContent('#message');
  check(/not applicable: particle \d+ is child/.test(why), `rule 2 on a child particle is refused, and the page says why: "${why}"`);
  await screenshot(page, 'studio-refused.png');
  // Below the settings panel the page shows the canvas (black while a rule
  // is armed), not a white area the compositor left.
  const below = [];
  for (let x = 960; x <= 1170; x += 70) for (let y = 460; y <= 740; y += 70) below.push([x, y]);
  const [shown, drawn] = [await screenshotPixels(page, below), await page.evaluate((pts) => pts.map(([x, y]) => studio.pixel(x, y)), below)];
  const worst = Math.max(...shown.map((c, i) => Math.max(...c.map((v, k) => Math.abs(v - drawn[i][k])))));
  check(worst <= 24, `below the settings panel the screenshot shows what the canvas drew (largest difference ${worst} of 255)`);
  // An argument left empty is named by the page, and nothing is sent.
  const rulesAsked = await page.evaluate(() => studio.replies.filter((r) => r.cmd === 'rule').length);
  await page.fill('div[data-rule="delete_particle"] input', '');
  await page.click('div[data-rule="delete_particle"] .apply');
  await until(page, () => document.getElementById('message').textContent.includes('give'));
  const forgot = await page.textContent('#message');
  await page.waitForTimeout(300 * slow);
  const rulesAfter = await page.evaluate(() => studio.replies.filter((r) => r.cmd === 'rule').length);
  check(/: give \w+ \(click a particle/.test(forgot) && rulesAfter === rulesAsked,
        `a rule applied with its argument left empty is not sent, and the page names what is missing: "${forgot}"`);

  // --- timeline --------------------------------------------------------------------------------
  const live = await page.evaluate(() => studio.topology.count);
  await page.evaluate(() => {
    const s = document.getElementById('scrub');
    s.value = 40;
    s.dispatchEvent(new Event('input'));
  });
  await until(page, () => studio.preview && studio.preview.frame);
  const earlier = await page.evaluate(() => ({ n: studio.preview.topology.count, label: document.getElementById('scrub-label').textContent }));
  await page.waitForTimeout(200);
  await screenshot(page, 'studio-timeline.png');
  check(earlier.n > 0 && earlier.n < live, `the timeline shows an earlier model: ${earlier.label}, ${earlier.n} particles (live: ${live})`);
  await page.click('#live');

  // A preview replays in a thread of its own: the live model goes on
  // stepping, and frames keep coming, while the whole journal replays.
  await page.evaluate(() => { studio.send({ cmd: 'settings', settings: { tolerance: 1e-12 } }); studio.send({ cmd: 'run' }); });
  await until(page, () => studio.status && !studio.status.converged && !studio.status.paused);
  const during = await page.evaluate(async () => {
    const frames = studio.frames, step = studio.frame.step, t0 = performance.now();
    const m = await studio.request({ cmd: 'timeline', index: studio.status.productions });
    return { ok: m.ok, ms: performance.now() - t0, frames: studio.frames - frames, steps: studio.frame.step - step, replayed: m.value && m.value.steps };
  });
  check(during.ok && during.frames >= 5 && during.steps > 0,
        `while the whole journal replayed (${during.replayed} steps, ${during.ms.toFixed(0)} ms) the page got ${during.frames} live frames (>= 5), ${during.steps} steps on`);
  await page.evaluate(() => studio.send({ cmd: 'settings', settings: { tolerance: 1e-3 } }));

  // --- the session's journal replays to the same model ----------------------------------------
  await page.click('#pause');
  await until(page, () => studio.status && studio.status.paused);
  const code = await studio.stop();
  check(code === 0, `Ctrl-C stops the studio cleanly (exit ${code})`);
  const replayed = path.join(studio.out, 'replayed');
  execFileSync(tendril, ['replay', path.join(studio.out, 'journal.txt'), '--out', replayed]);
  const a = fs.readFileSync(path.join(studio.out, 'model.xml'), 'utf8'), b = fs.readFileSync(path.join(replayed, 'model.xml'), 'utf8');
  const journal = fs.readFileSync(path.join(studio.out, 'journal.txt'), 'utf8');
  check(/^goal anchor /m.test(journal) && /^insert /m.test(journal), 'the journal holds the drag (goal anchor) and rule 13 (insert)');
  check(a === b, `tendril replay of the session's journal gives the same model.xml, byte for byte (${a.length} bytes)`);
});
