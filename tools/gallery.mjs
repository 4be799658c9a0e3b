// The case studies' gallery (docs/case-studies.md): runs each case study's
// full variant, draws its model with tendril's own static view (`tendril
// view`) in headless Chromium, and writes the picture.
//
//   node tools/gallery.mjs [--quick | --no-run] [--tendril PATH] [--work DIR] [--out DIR] [CASE...]
//
// CASE is a scene name in scripts/case-studies (default: all of them). The
// run's outputs stay in --work (default /tmp/tendril-gallery/CASE); the
// pictures go to --out (default docs/gallery/CASE.png). --quick runs the quick
// variant instead (what the test does, so that the pipeline cannot rot);
// --no-run draws what a run left in --work (to try other views). A
// scene may write view.json into its output folder: {"direction": [x, y, z]}
// looks at the model from that side (default: the studio's), "zoom" < 1
// comes closer.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const { chromium } = await import(path.join(root, 'web/node_modules/playwright-core/index.mjs'));

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const k = args.indexOf(name);
  if (k < 0) return fallback;
  const v = args[k + 1];
  args.splice(k, 2);
  return v;
};
const flag = (name) => {
  const k = args.indexOf(name);
  if (k >= 0) args.splice(k, 1);
  return k >= 0;
};
const quick = flag('--quick'), norun = flag('--no-run');
const tendril = option('--tendril', path.join(root, 'build/tendril'));
const work = option('--work', path.join(os.tmpdir(), 'tendril-gallery'));
const out = option('--out', path.join(root, 'docs/gallery'));
const unknown = args.find((a) => a.startsWith('--'));
if (unknown) {
  console.error(`gallery: unknown option ${unknown}`);
  process.exit(2);
}
const scenes = path.join(root, 'scripts/case-studies');
const cases = args.length ? args : fs.readdirSync(scenes).filter((f) => f.endsWith('.lua')).map((f) => f.slice(0, -4)).sort();

fs.mkdirSync(out, { recursive: true });
const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'tendril-gallery-chromium-'));
const browser = await chromium.launchPersistentContext(profile, {
  executablePath: '/usr/bin/chromium', headless: true, viewport: { width: 1200, height: 800 },
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
         '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});
let failed = 0;
try {
  for (const name of cases) {
    const scene = path.join(scenes, name + '.lua');
    const dir = path.join(work, name);
    const started = Date.now();
    if (!norun) try {
      fs.rmSync(dir, { recursive: true, force: true });
      execFileSync(tendril, ['run', scene, '--out', dir, '--quiet', ...(quick ? [] : ['--param', 'full=1'])],
                   { stdio: ['ignore', 'inherit', 'inherit'] });
    } catch (e) {
      console.error(`gallery: ${name}: the scene failed (status ${e.status})`);
      ++failed;
      continue;
    }
    if (!fs.existsSync(path.join(dir, 'journal.txt'))) {
      // A quick run writes no outputs: save its journal the way a full run does.
      console.error(`gallery: ${name}: no journal.txt in ${dir} (the quick variant writes none; run without --quick)`);
      ++failed;
      continue;
    }
    const html = path.join(dir, 'page.html');
    execFileSync(tendril, ['view', dir, '-o', html, '--entries', '2'], { stdio: 'ignore' });
    const hint = fs.existsSync(path.join(dir, 'view.json')) ? JSON.parse(fs.readFileSync(path.join(dir, 'view.json'), 'utf8')) : {};
    const page = await browser.newPage();
    const problems = [];
    page.on('pageerror', (e) => problems.push(e.message));
    await page.goto('file://' + html);
    await page.waitForFunction(() => window.tendrilView && tendrilView.shown >= 0, null, { timeout: 60000 });
    await page.addStyleTag({ content: '#hud, #timeline { display: none !important; }' });
    await page.evaluate(([direction, zoom]) => {
      const v = tendrilView.view;
      v.resize();
      const t = v.controls.target, c = v.camera.position;
      const d = direction ? direction : [c.x - t.x, c.y - t.y, c.z - t.z];
      const n = Math.hypot(d[0], d[1], d[2]);
      const r = Math.hypot(c.x - t.x, c.y - t.y, c.z - t.z) * (zoom || 1);
      c.set(t.x + d[0] / n * r, t.y + d[1] / n * r, t.z + d[2] / n * r);
      v.controls.update();
      v.render();
    }, [hint.direction || null, hint.zoom || 1]);
    // The share of the picture the model covers (not white): a blank or
    // misplaced view is a failure, not a picture.
    const drawn = await page.evaluate(() => {
      const src = tendrilView.view.renderer.domElement;
      const c = document.createElement('canvas');
      c.width = src.width;
      c.height = src.height;
      const g = c.getContext('2d');
      g.drawImage(src, 0, 0);
      const px = g.getImageData(0, 0, c.width, c.height).data;
      let ink = 0;
      for (let k = 0; k < px.length; k += 4) if (px[k] < 240 || px[k + 1] < 240 || px[k + 2] < 240) ++ink;
      return ink / (px.length / 4);
    });
    const file = path.join(out, name + '.png');
    await page.screenshot({ path: file });
    await page.close();
    if (problems.length || !(drawn > 0.002)) {
      console.error(`gallery: ${name}: the page failed: ${problems.join('; ') || `the model covers ${(100 * drawn).toFixed(2)} % of the picture`}`);
      ++failed;
      continue;
    }
    console.log(`gallery: ${name} -> ${path.relative(process.cwd(), file)}: the model covers ${(100 * drawn).toFixed(1)} % of the picture (${((Date.now() - started) / 1000).toFixed(1)} s)`);
  }
} finally {
  await browser.close();
  fs.rmSync(profile, { recursive: true, force: true, maxRetries: 5, retryDelay: 100 });
}
process.exit(failed ? 1 : 0);
