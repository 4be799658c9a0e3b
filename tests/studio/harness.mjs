// Browser tests of `tendril studio`: a real studio process and a real
// headless Debian Chromium driven by playwright-core (web/node_modules).
// Each test file starts its own studio on a free port and stops it with
// SIGINT (the Ctrl-C path, which saves model.xml, model.obj, journal.txt).
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

// Waits are scaled by TENDRIL_SLOW (5 under the sanitizers: tests/CMakeLists.txt).
export const slow = Number(process.env.TENDRIL_SLOW || 1);

const here = path.dirname(fileURLToPath(import.meta.url));
export const root = path.resolve(here, '../..');
const { chromium } = await import(path.join(root, 'web/node_modules/playwright-core/index.mjs'));

export const tendril = process.env.TENDRIL || path.join(root, 'build/tendril');
export const shots = process.env.TENDRIL_SCREENSHOTS || path.join(os.tmpdir(), 'tendril-studio-shots');

export function scene(name) { return path.join(root, name); }

// The folders a test makes in /tmp (studio outputs, browser profiles) go when
// the process ends; a failed test's studio outputs stay, to look at.
const made = [];
function tempDir(prefix, keepOnFailure) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), prefix));
  made.push({ dir, keepOnFailure });
  return dir;
}
process.on('exit', (code) => {
  for (const { dir, keepOnFailure } of made) {
    if (code !== 0 && keepOnFailure) { console.error(`kept ${dir}`); continue; }
    try { fs.rmSync(dir, { recursive: true, force: true, maxRetries: 5, retryDelay: 100 }); } catch { /* still in use: left */ }
  }
});

// Starts `tendril studio SCENE ARGS...`; resolves once it printed its URL.
export async function startStudio(scenePath, args = []) {
  const out = tempDir('tendril-studio-', true);
  const proc = spawn(tendril, ['studio', scenePath, '--port', '0', '--out', out, ...args], { stdio: ['ignore', 'pipe', 'pipe'] });
  let log = '';
  proc.stderr.on('data', (d) => { log += d; });
  const url = await new Promise((resolve, reject) => {
    let text = '';
    const timer = setTimeout(() => reject(new Error(`the studio printed no URL in ${20 * slow} s:\n` + text + log)), 20000 * slow);
    proc.stdout.on('data', (d) => {
      text += d;
      const m = text.match(/open (http:\/\/\S+)/);
      if (m) { clearTimeout(timer); resolve(m[1]); }
    });
    proc.on('exit', (code) => reject(new Error(`the studio exited (${code}) before printing its URL:\n${text}${log}`)));
  });
  return {
    url, out, proc, log: () => log,
    alive: () => proc.exitCode === null && proc.signalCode === null,
    // Ctrl-C: the studio saves into out/ and exits with status 0.
    stop: () => new Promise((resolve) => {
      if (proc.exitCode !== null) return resolve(proc.exitCode);
      proc.on('exit', (code) => resolve(code));
      proc.kill('SIGINT');
    }),
  };
}

// A fresh headless Chromium with the flags this machine needs (no network
// beyond loopback, a new profile every time).
export async function openBrowser() {
  const profile = tempDir('tendril-chromium-', false);
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: '/usr/bin/chromium', headless: true, viewport: { width: 1200, height: 800 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  context.on('close', () => {  // Chromium may still be writing into it: retried, never fatal
    try { fs.rmSync(profile, { recursive: true, force: true, maxRetries: 5, retryDelay: 100 }); } catch { /* left in tmp */ }
  });
  return context;
}

export async function openPage(context, url) {
  const page = await context.newPage();
  const problems = [];
  page.on('pageerror', (e) => problems.push(e.message));
  await page.goto(url);
  await page.waitForFunction(() => window.studio && window.studio.hello && window.studio.frame, null, { timeout: 30000 * slow });
  page.problems = problems;
  return page;
}

export async function until(page, fn, arg, timeout = 30000) {
  return (await page.waitForFunction(fn, arg, { timeout: timeout * slow, polling: 50 })).jsonValue();
}

export async function screenshot(page, name) {
  fs.mkdirSync(shots, { recursive: true });
  const file = path.join(shots, name);
  await page.screenshot({ path: file });
  return file;
}

// The colours [r, g, b] at CSS pixels [x, y] of a screenshot of the page
// (what the page shows, panels and compositing included, not the canvas
// alone), decoded by the browser itself.
export async function screenshotPixels(page, points) {
  const png = (await page.screenshot()).toString('base64');
  return page.evaluate(async ([png, points]) => {
    const img = new Image();
    img.src = 'data:image/png;base64,' + png;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width;
    c.height = img.height;
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0);
    return points.map(([x, y]) => Array.from(g.getImageData(x, y, 1, 1).data.slice(0, 3)));
  }, [png, points]);
}

export function check(condition, message) {
  if (!condition) throw new Error(message);
  console.log('ok: ' + message);
}

// Runs a test body with a studio and a browser; always cleans up.
export async function run(name, scenePath, args, body) {
  const studio = await startStudio(scenePath, args);
  const browser = await openBrowser();
  let failed = null;
  try {
    await body({ studio, browser });
  } catch (e) {
    failed = e;
  }
  await browser.close().catch(() => {});
  const code = await studio.stop();
  if (failed) {
    console.error(`${name}: FAILED: ${failed.stack || failed}\n--- studio stderr ---\n${studio.log()}`);
    process.exit(1);
  }
  if (code !== 0) {
    console.error(`${name}: the studio exited with ${code} on Ctrl-C\n${studio.log()}`);
    process.exit(1);
  }
  console.log(`${name}: passed`);
}
