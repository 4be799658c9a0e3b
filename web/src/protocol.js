// Reads the studio's binary messages (studio/frames.hpp has the layout).
export const TOPOLOGY = 0x54504f54;
export const FRAME = 0x4d415246;
export const PREVIEW_TOPOLOGY = 0x54505250;
export const PREVIEW_FRAME = 0x46525250;

export const EDGE_CABLE = 0, EDGE_BEAM = 1, EDGE_PATCH = 2;
export const BLOCK_KINDS = ['cable', 'beam', 'patch'];
// Vertex states (core/model/types.hpp order) and their colours: thesis
// 4.2.6 for the first six; parent, child and volatile (5.5.1, 6.5.2) have
// none there.
export const STATES = ['isolated', 'passive', 'lock', 'full-lock', 'simple', 'shared', 'parent', 'child', 'volatile'];
export const STATE_COLOURS = [0x000000, 0x808080, 0xff0000, 0xffff00, 0x00ffff, 0x800080, 0xff8c00, 0x2e8b57, 0xff1493];

export function kind(buffer) {
  return new DataView(buffer).getUint32(0, true);
}

function pad4(n) { return (n + 3) & ~3; }

export function readTopology(buffer) {
  const v = new DataView(buffer);
  const revision = v.getUint32(4, true);
  const n = v.getUint32(8, true), ne = v.getUint32(12, true), nt = v.getUint32(16, true), nb = v.getUint32(20, true);
  let at = 24;
  const take = (Type, count) => {
    const a = new Type(buffer, at, count);
    at = pad4(at + count * Type.BYTES_PER_ELEMENT);
    return a;
  };
  const t = { revision, count: n };
  t.ids = take(Uint32Array, n);
  t.blocks = take(Uint32Array, nb);
  t.blockKind = take(Uint8Array, nb);
  t.blockForm = take(Uint8Array, nb);
  t.states = take(Uint8Array, n);
  t.locks = take(Uint8Array, n);
  t.edgeKind = take(Uint8Array, ne);
  t.edges = take(Uint32Array, 2 * ne);
  t.edgeBlock = take(Uint32Array, ne);
  t.restLength = take(Float32Array, ne);
  t.triangles = take(Uint32Array, 3 * nt);
  t.triangleBlock = take(Uint32Array, nt);
  t.indexOf = new Map();
  for (let k = 0; k < n; ++k) t.indexOf.set(t.ids[k], k);
  return t;
}

export function readFrame(buffer) {
  const v = new DataView(buffer);
  const f = {
    revision: v.getUint32(4, true),
    step: v.getFloat64(8, true),
    residual: v.getFloat64(16, true),
    time: v.getFloat64(24, true),
    count: v.getUint32(32, true),
  };
  const nf = v.getUint32(36, true);
  f.positions = new Float32Array(buffer, 40, 3 * f.count);
  f.field = nf ? new Float32Array(buffer, 40 + 12 * f.count, nf) : null;
  return f;
}
