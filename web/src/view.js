// The static view (`tendril view ... -o page.html`): one file holding the
// model's growth timeline (topology and frame per entry, as the studio sends
// them, base64) and its colour maps; drawn with the studio's renderer, with
// no server.
import './style.css';
import { View3D, legendGradient } from './scene3d.js';
import * as P from './protocol.js';

const $ = (id) => document.getElementById(id);
const data = JSON.parse(document.getElementById('tendril-data').textContent);
const bytes = (b64) => { const s = atob(b64); const a = new Uint8Array(s.length); for (let i = 0; i < s.length; ++i) a[i] = s.charCodeAt(i); return a.buffer; };
const view = new View3D($('view'));
window.tendrilView = { view, data, shown: -1 };

$('title').textContent = data.title;
for (const f of data.fields) {
  const o = document.createElement('option');
  o.value = f.name;
  o.textContent = `${f.name} [${f.unit}]`;
  $('field').appendChild(o);
}

function show(k) {
  const e = data.timeline[k];
  const t = P.readTopology(bytes(e.topology));
  const f = P.readFrame(bytes(e.frame));
  const name = $('field').value;
  const field = data.fields.find((x) => x.name === name) || null;
  f.field = field && e.fields && e.fields[name] ? new Float32Array(bytes(e.fields[name])) : null;
  view.setField(f.field ? field : null);
  view.setTopology(t);
  view.setFrame(f);
  view.render();
  $('scrub-label').textContent = `${e.label} (${k + 1} of ${data.timeline.length})`;
  $('stats').textContent = `step ${f.step}   particles ${t.count}   blocks ${t.blocks.length}`;
  const L = view.legend;
  $('legend').hidden = !L;
  if (L) {
    $('legend-name').textContent = `${field.name} [${field.unit}]`;
    $('legend-bar').style.background = legendGradient(L.diverging);
    $('legend-lo').textContent = (L.diverging ? -L.range : L.lo).toPrecision(3);
    $('legend-hi').textContent = (L.diverging ? L.range : L.hi).toPrecision(3);
  }
  window.tendrilView.shown = k;
}

$('scrub').max = data.timeline.length - 1;
$('scrub').value = data.timeline.length - 1;
$('scrub').addEventListener('input', () => show(Number($('scrub').value)));
$('field').addEventListener('change', () => show(Number($('scrub').value)));
view.controls.addEventListener('change', () => view.render());
show(data.timeline.length - 1);
