-- A newcomer's portal from docs/lua-api.md alone: two posts and a beam,
-- rigid corners, posts clamped at the ground, a load at mid-span; then
-- what each member carries.
local m = tendril.model()
local function line(a, b, n)
  local pts = {}
  for i = 0, n do pts[#pts + 1] = { a[1] + (b[1] - a[1]) * i / n, 0, a[3] + (b[3] - a[3]) * i / n } end
  return pts
end
local left = m:beam{ points = line({ 0, 0, 0 }, { 0, 0, 2 }, 10), EA = 1e6, EI = 100 }
local top = m:beam{ points = line({ 0, 0, 2 }, { 4, 0, 2 }, 20), EA = 1e6, EI = 100 }
local right = m:beam{ points = line({ 4, 0, 2 }, { 4, 0, 0 }, 10), EA = 1e6, EI = 100 }
local L, T, R = m:particles(left), m:particles(top), m:particles(right)
local c1 = m:merge{ L[#L], T[1] }
local c2 = m:merge{ T[#T], R[1] }
m:connection(c1, left, top, "rigid")
m:connection(c2, top, right, "rigid")
assert(m:connection(c1, left, top) == "rigid")
m:lock(L[1]); m:lock(R[#R])
m:clamp(L[1], left); m:clamp(R[#R], right)
for _, p in ipairs(m:particles()) do m:lock(p, "y") end
local mid = m:particles(top)[11]
m:load(mid, { 0, 0, -10 })
assert(m:run{ tolerance = 1e-6, max_steps = 500000 }.converged)
-- Vertical equilibrium: the two ground reactions carry the load.
local rz = m:reaction(L[1])[3] + m:reaction(R[#R])[3]
assert(math.abs(rz - 10) < 1e-3, rz)
-- Each post carries half the load in compression (symmetry).
local post = m:forces(left).segments[1].axial
assert(math.abs(post + 5) < 0.05, post)
local biggest = 0
for _, v in ipairs(m:forces(top).vertices) do biggest = math.max(biggest, math.abs(v.moment)) end
print(string.format("post axial %.3f N, largest beam moment %.3f N m", post, biggest))
assert(biggest > 0 and biggest < 10 * 4 / 4, "a mid-span moment below the simply supported beam's PL/4")
