// The studio's controls on the states scene: pause, step, run; lock, then
// undo; a beam to 6 DOF and a patch to CST and back; a solver setting; save
// from the page; branching back to an equilibrium snapshot.
import fs from 'node:fs';
import path from 'node:path';
import { check, openPage, run, scene, until } from './harness.mjs';

const reply = async (page, command) => page.evaluate((c) => studio.request(c), command);

await run('controls', scene('tests/studio/states.lua'), ['--speed', '0'], async ({ studio, browser }) => {
  const page = await openPage(browser, studio.url);
  await until(page, () => studio.status && studio.status.converged);

  // pause, step, run
  await page.click('#pause');
  await until(page, () => studio.status.paused);
  const s0 = await page.evaluate(() => studio.status.steps);
  await page.click('#step');
  const s1 = await until(page, (s) => studio.status.steps > s && studio.status.steps, s0);
  check(s1 === s0 + 1, `paused, *step* takes one step (${s0} -> ${s1})`);
  await page.waitForTimeout(300);
  check(await page.evaluate((s) => studio.status.steps === s, s1), 'paused, the solver takes no step by itself');
  await page.click('#run');
  await until(page, () => !studio.status.paused);

  // lock from the selection tools, then undo
  const free = await page.evaluate(() => {
    const t = studio.topology;
    for (let k = 0; k < t.count; ++k) if (t.states[k] === 4) return t.ids[k];  // a simple particle
    return null;
  });
  const lockReply = await reply(page, { cmd: 'lock', particle: free, axes: 'xyz' });
  check(lockReply.ok, `lock particle ${free}`);
  await until(page, (id) => studio.topology.states[studio.topology.indexOf.get(id)] === 2, free);
  check(true, 'it is drawn as lock (red) once the topology came back');
  const undo = await reply(page, { cmd: 'undo' });
  check(undo.ok, `undo: ${JSON.stringify(undo.value)}`);
  await until(page, (id) => studio.topology.states[studio.topology.indexOf.get(id)] === 4, free);
  check(true, `after undo particle ${free} is simple again`);

  // formulations
  const blocks = await page.evaluate(() => Array.from(studio.topology.blocks).map((b, k) => ({ b, kind: studio.topology.blockKind[k] })));
  const beam = blocks.find((x) => x.kind === 1).b, patch = blocks.find((x) => x.kind === 2).b;
  check((await reply(page, { cmd: 'formulation', block: beam, dofs: 6 })).ok, `beam ${beam} to 6 DOF`);
  await until(page, (b) => studio.topology.blockForm[Array.prototype.indexOf.call(studio.topology.blocks, b)] === 6, beam);
  check((await reply(page, { cmd: 'formulation', block: patch, membrane: 'cst' })).ok, `patch ${patch} to CST`);
  await until(page, (b) => studio.topology.blockForm[Array.prototype.indexOf.call(studio.topology.blocks, b)] === 1, patch);
  check((await reply(page, { cmd: 'formulation', block: patch, membrane: 'bars' })).ok, 'and back to bars');
  const wrong = await reply(page, { cmd: 'formulation', block: beam, dofs: 5 });
  check(!wrong.ok && /3 or 6/.test(wrong.message), `5 DOF is refused: ${wrong.message}`);

  // a solver setting
  check((await reply(page, { cmd: 'settings', settings: { integrator: 'symplectic_euler' } })).ok, 'integrator switched to symplectic_euler');
  const bad = await reply(page, { cmd: 'settings', settings: { integrator: 'euler' } });
  check(!bad.ok, `an unknown integrator is refused: ${bad.message}`);

  // any command of docs/commands.md, in its JSON form
  const declared = await reply(page, { cmd: 'commands' });
  check(declared.ok && declared.value.some((c) => c.name === 'load' && c.params.length === 2), `${declared.value.length} commands declared`);
  const loaded = await reply(page, { cmd: 'apply', command: 'load', args: { particle: free, force: [0, 0, -0.5] } });
  check(loaded.ok, `apply: a load on particle ${free}`);
  const badBits = await reply(page, { cmd: 'apply', command: 'lock', args: { particle: free, bits: 64 } });
  check(!badBits.ok && badBits.message === "lock: 'bits' must be a whole number from 0 to 63", `apply: a bad argument is refused: ${badBits.message}`);
  const opened = await reply(page, { cmd: 'apply', command: 'open', args: { path: '/etc/hostname' } });
  check(!opened.ok && /not for the page/.test(opened.message), `apply: open is refused: ${opened.message}`);

  // save from the page
  await until(page, () => studio.status.converged);
  await page.click('#save');
  await until(page, () => studio.replies.some((r) => r.cmd === 'save' && r.ok));
  const saved = ['model.xml', 'model.obj', 'journal.txt'].filter((f) => fs.existsSync(path.join(studio.out, f)));
  check(saved.length === 3, `*save* wrote ${saved.join(', ')} into --out`);
  const journal = fs.readFileSync(path.join(studio.out, 'journal.txt'), 'utf8');
  check(journal.includes(`\nload ${free} 0x0p+0 0x0p+0 -0x1p-1\n`), 'the load applied from the page is in the saved journal');

  // back to the first equilibrium
  const snaps = await page.evaluate(() => studio.status.snapshots);
  check(snaps.length >= 2, `${snaps.length} equilibria kept as snapshots (steps ${snaps.map((s) => s.steps).join(', ')})`);
  const branch = await reply(page, { cmd: 'branch', snapshot: 0 });
  check(branch.ok && branch.value.steps === snaps[0].steps, `branched back to the first equilibrium (step ${branch.value.steps})`);
  const blockForm = await until(page, (b) => {
    const k = Array.prototype.indexOf.call(studio.topology.blocks, b);
    return k >= 0 && studio.topology.blockForm[k] === 3 ? 3 : false;
  }, beam, 15000);
  check(blockForm === 3, 'there the beam is 3 DOF again, as it was');
});
