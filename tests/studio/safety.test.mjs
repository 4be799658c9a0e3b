// The studio's safety: a malformed, oversized, binary or unknown message gets
// an error reply and the server goes on; several tabs watch one model;
// closing a tab does not stop the solver; with --host, the page and the
// socket need the token of the printed URL.
import { check, openBrowser, openPage, run, scene, startStudio, until } from './harness.mjs';

// Sends raw messages on a socket of its own from the page; returns the replies.
async function rawReplies(page, messages) {
  return page.evaluate(async (messages) => {
    const ws = new WebSocket(`ws://${location.host}/ws${location.search}`);
    ws.binaryType = 'arraybuffer';
    const replies = [];
    ws.onmessage = (e) => { if (typeof e.data === 'string') replies.push(JSON.parse(e.data)); };
    await new Promise((r) => { ws.onopen = r; });
    for (const m of messages) ws.send(m === 'BINARY' ? new Uint8Array([1, 2, 3]) : m === 'HUGE' ? 'x'.repeat(100000) : m);
    const t0 = performance.now();
    while (replies.filter((r) => r.type === 'error' || r.type === 'reply').length < messages.length && performance.now() - t0 < 5000)
      await new Promise((r) => setTimeout(r, 20));
    ws.close();
    return replies.filter((r) => r.type === 'error' || r.type === 'reply');
  }, messages);
}

await run('safety', scene('tests/studio/states.lua'), ['--speed', '500'], async ({ studio, browser }) => {
  const page = await openPage(browser, studio.url);
  const bad = ['not json', '[1,2]', '{"cmd": 3}', '{"cmd": "rm -rf"}', 'HUGE', 'BINARY',
               '{"cmd": "rule", "rule": "insert", "args": [{"particle": 99999}, {"particle": 1}]}',
               '{"cmd": "drag", "particle": 1, "to": [0, "x", 0]}', '{"cmd": "step", "n": -4}',
               '{"cmd": "rule", "rule": "no_such_rule", "args": []}'];
  const replies = await rawReplies(page, [...bad, '{"cmd": "hello"}']);
  const errors = replies.slice(0, bad.length);
  check(errors.length === bad.length && errors.every((r) => r.type === 'error' || r.ok === false),
        `each of ${bad.length} bad messages got an error reply:\n    ` + errors.map((r) => r.message).join('\n    '));
  check(replies[bad.length] && replies[bad.length].ok && replies[bad.length].cmd === 'hello', 'the same socket still answers a good command');
  check(studio.alive(), 'the server is still running');

  // A second tab watches the same model; closing the first stops nothing.
  const second = await openPage(browser, studio.url);
  const [s1, s2] = await Promise.all([page, second].map((p) => p.evaluate(() => studio.frame.count)));
  check(s1 === s2 && s1 > 0, `two tabs watch the same model (${s1} and ${s2} particles)`);
  await page.evaluate(() => studio.send({ cmd: 'run' }));
  const stepsBefore = await second.evaluate(() => studio.frame.step);
  await page.close();
  // A hidden tab asks for no frames (web/src/studio.js, visibilitychange), and
  // which of two headless tabs Chromium shows is not fixed: once in CI the
  // second stayed hidden, received nothing and timed out.
  await second.bringToFront();
  await second.evaluate(() => studio.send({ cmd: 'settings', settings: { tolerance: 1e-12 } }));
  await until(second, (s) => studio.frame.step > s + 100, stepsBefore);
  check(studio.alive(), 'after the first tab closed, the solver goes on stepping for the second');
});

// With --host the token is required: without it the page is refused (403)
// and so is the socket; with it, both work.
const guarded = await startStudio(scene('tests/studio/states.lua'), ['--host', '127.0.0.1', '--speed', '500']);
const browser = await openBrowser();
try {
  const url = new URL(guarded.url);
  check(/^[0-9a-f]{32}$/.test(url.searchParams.get('token') || ''), `--host prints a URL with a random token: ${guarded.url}`);
  const bare = await browser.newPage();
  const response = await bare.goto(`http://${url.host}/`);
  check(response.status() === 403, `the page without the token is refused (${response.status()})`);
  const socket = await bare.evaluate((host) => new Promise((resolve) => {
    const ws = new WebSocket(`ws://${host}/ws`);
    ws.onopen = () => resolve('open');
    ws.onerror = () => resolve('refused');
  }), url.host);
  check(socket === 'refused', `the WebSocket without the token is refused (${socket})`);
  const page = await openPage(browser, guarded.url);
  check(await page.evaluate(() => studio.frame.count > 0), 'with the token the page connects and draws');
} finally {
  await browser.close();
  const code = await guarded.stop();
  check(code === 0, `the guarded studio stops cleanly (${code})`);
}
console.log('safety (token): passed');
