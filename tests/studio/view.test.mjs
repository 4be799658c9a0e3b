// `tendril view`: one self-contained HTML file of a session's output (its
// journal: the growth timeline) opens from disk with no server, draws the
// final model, scrubs back to an earlier one, and colours by a result.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { check, openBrowser, run, scene, screenshot, tendril } from './harness.mjs';

let out = null;
await run('view: a session to show', scene('tests/studio/states.lua'), ['--speed', '0', '--no-wait'], async ({ studio }) => {
  await new Promise((r) => setTimeout(r, 1500));
  out = studio.out;
});
const html = path.join(out, 'page.html');
execFileSync(tendril, ['view', out, '-o', html]);
const text = fs.readFileSync(html, 'utf8');
check(!/<script[^>]+src=|<link[^>]+href="(?!data:)/.test(text), `the page links no file and no address (${(text.length / 1e6).toFixed(2)} MB, one file)`);
const browser = await openBrowser();
try {
  const page = await browser.newPage();
  const problems = [];
  page.on('pageerror', (e) => problems.push(e.message));
  page.on('request', (r) => { if (!r.url().startsWith('file:') && !r.url().startsWith('data:')) problems.push('fetched ' + r.url()); });
  await page.goto('file://' + html);
  await page.waitForFunction(() => window.tendrilView && tendrilView.shown >= 0);
  const last = await page.evaluate(() => ({ n: tendrilView.view.topology.count, entries: tendrilView.data.timeline.length }));
  check(last.n === 27 && last.entries > 10, `the final model (27 particles) and a timeline of ${last.entries} models`);
  await page.evaluate(() => { const s = document.getElementById('scrub'); s.value = 2; s.dispatchEvent(new Event('input')); });
  const early = await page.evaluate(() => tendrilView.view.topology.count);
  check(early < last.n, `scrubbing back shows an earlier model (${early} particles)`);
  await page.evaluate(() => { const s = document.getElementById('scrub'); s.value = s.max; s.dispatchEvent(new Event('input')); });
  await page.selectOption('#field', 'axial force');
  const legend = await page.evaluate(() => !document.getElementById('legend').hidden && tendrilView.view.legend);
  check(legend && legend.hi > 0, `colour map by axial force with a legend (${legend.lo.toPrecision(3)} to ${legend.hi.toPrecision(3)} N)`);
  await screenshot(page, 'view-states.png');
  check(problems.length === 0, 'no error and nothing fetched: ' + problems.join('; '));
} finally {
  await browser.close();
}
console.log('view: passed');
