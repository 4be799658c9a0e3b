-- A bending-active bow: a 6 m glass-fibre rod, straight at rest, is held bent
-- by a 4.5 m cable between its ends; then refined with rule 13 and relaxed
-- again. Units: m, N. Outputs: bow.xml (model database), bow.obj (polylines).
local m = tendril.model{ damping = "kinetic" }

-- The rod: 20 mm diameter GFRP, E = 25 GPa.
local d = 0.02
local rod = { E = 25e9, A = math.pi * d^2 / 4, I = math.pi * d^4 / 64 }
local length, span, n = 6.0, 4.5, 16

-- Start on the circular arc of the right length and chord (the rest lengths
-- are taken from it; the rest shape of a beam is always straight).
local lo, hi = 1e-6, 2 * math.pi - 1e-6     -- the arc's angle: chord(angle) = span
for _ = 1, 100 do
  local mid = (lo + hi) / 2
  if 2 * (length / mid) * math.sin(mid / 2) > span then lo = mid else hi = mid end
end
local angle = (lo + hi) / 2
local radius = length / angle
local points = {}
for i = 0, n do
  local phi = angle * (i / n - 0.5)
  points[#points + 1] = { radius * math.sin(phi), 0, radius * (math.cos(phi) - math.cos(angle / 2)) }
end
local beam = m:beam{ points = points, E = rod.E, A = rod.A, I = rod.I }
local ps = m:particles(beam)
local left, right = ps[1], ps[#ps]

local string_ = m:cable(left, right, { EA = 1e5, rest_length = span })
m:lock(left, "xyz")
m:lock(right, "yz")
for _, p in ipairs(ps) do m:lock(p, "y") end

local r = m:run{ tolerance = 1e-4, max_steps = 200000 }
local rise = m:position(ps[n // 2 + 1])[3]
local tension = m:results(string_).elements[1].axial
local stretch = m:position(right)[1] - m:position(left)[1] - span
print(string.format("coarse: %d steps, residual %.2e N, rise %.4f m, cable tension %.1f N",
  r.steps, r.residual, rise, tension))
assert(math.abs(tension - 1e5 * stretch / span) < 1e-9 * tension, "m:results: the string's tension is EA * strain")
assert(r.converged and rise > 1.5, "the bow did not reach equilibrium")

-- Refine: one particle between every consecutive pair (rule 13), keep running.
for i = 1, #ps - 1 do m:insert(ps[i], ps[i + 1]) end
m:check()
r = m:run{ tolerance = 1e-4, max_steps = 400000 }
local top = m:particles(beam)[n + 1]
print(string.format("fine:   %d steps, residual %.2e N, rise %.4f m, %d particles",
  r.steps, r.residual, m:position(top)[3], m:count().particles))
assert(r.converged, "the refined bow did not reach equilibrium")

-- The rod's results (docs/lua-api.md, "Results"): cut at the crown, the
-- string's tension T acts at the lever arm of the rise, so M = T rise there.
local section = tendril.section.rod{ d = d, material = "gfrp" }
local res = m:results(beam, section)
tension = m:results(string_).elements[1].axial
local crown = tension * m:position(top)[3]
print(string.format("largest moment %.1f N m (T rise %.1f N m), stress %.0f MPa, utilisation %.2f",
  res.max_moment, crown, res.max_stress / 1e6, res.max_utilisation))
assert(math.abs(res.max_moment - crown) < 0.02 * crown, "the crown's moment is not T * rise")

m:save(tendril.out("bow.xml"))
m:save_obj(tendril.out("bow.obj"))
