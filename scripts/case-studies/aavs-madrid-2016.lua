-- Thesis 6.2, AAVS Madrid 2016: the bending-active part of a registration
-- counter, 22 pultruded GFRP rods (d 5-20 mm, 1.5-6 m, E 25 GPa) added one
-- by one as straight 3-DOF spline beams (rule 10, Leapfrog) and connected by
-- rule 3 where a designer drags their ends, so that the structure passes from
-- arcs to cantilevers to a grid (fig. 6.8); one connection is erroneous (the
-- rod would break) and is reverted by rule 4. Every step ends in an
-- equilibrium, and the journal is the assembly sequence.
--
-- The thesis gives the envelope (6 x 2 m, 2.5 m high), the rods' range and E,
-- not their layout: the layout below is ours, chosen to fit that envelope
-- with the same three stages. Density 1900 kg/m3 and a characteristic
-- bending strength of 400 MPa are assumed (the thesis gives neither).
--
--   tendril run scripts/case-studies/aavs-madrid-2016.lua               quick (the test)
--   tendril run scripts/case-studies/aavs-madrid-2016.lua --param full=1 --out out/aavs
local case = require("lib.case")
local assemble = require("lib.assemble")
local R = tendril.rules

local variant = case.variant()
local segment = variant.full and 0.25 or 0.5       -- m: rods are cut into segments of about this
local m = tendril.model{ integrator = "leapfrog" }
m:gravity{ 0, 0, -9.81 }
local seq = assemble.new(m, { settle = { tolerance = variant.full and 1e-3 or 1e-2, max_steps = 400000 }, weight = 1e4 })

local rods = {}      -- name -> { beam =, section =, length = }
local function section(d) return case.rod(case.gfrp, d) end

-- A straight rod of length L from particle `start` (rule 10) along `dir`.
local function rod(name, start, dir, L, d)
  local s = section(d)
  local n = math.max(2, math.floor(L / segment + 0.5))
  local k = L / math.sqrt(dir[1]^2 + dir[2]^2 + dir[3]^2)
  local ok, beam = m:apply(R.beam_from, start, { dir[1] * k, dir[2] * k, dir[3] * k }, n, case.beam_options(s))
  assert(ok, beam)
  rods[#rods + 1] = { name = name, beam = beam, section = s, length = L }
  return m:particles(beam)
end

local function beam_of(name)
  for _, r in ipairs(rods) do
    if r.name == name then return r.beam end
  end
  error("no rod " .. name)
end

-- The particle of a rod nearest to a fraction t of its length, and its
-- neighbour `offset` particles further on.
local function at(name, t, offset)
  local ps = m:particles(beam_of(name))
  return ps[math.floor(t * (#ps - 1) + 0.5) + 1 + (offset or 0)]
end

-- The largest bending stress over all rods and the rod it is in.
local function worst(m)
  local sigma, where, radius = 0, "-", math.huge
  for _, r in ipairs(rods) do
    local rmin, s = case.bending(m, r.beam, r.section)
    if s > sigma then sigma, where, radius = s, r.name, rmin end
  end
  return { stress = sigma, utilisation = sigma / case.gfrp.strength, in_rod = where, radius = radius, height = case.envelope(m).height }
end

-- A particle on the floor, pinned: a rod's foot.
local function foot(x, y)
  local p = m:particle{ x, y, 0 }
  m:lock(p, "xyz")
  return p
end

-- Stage 1, arcs: a rod stood up in a base plate on the floor (its first
-- segment held vertical: a clamp), its end dragged into a second base plate
-- and held there the same way.
local function arc(name, from, to, L, d)
  local a = foot(from[1], from[2])
  local dx, dy = to[1] - from[1], to[2] - from[2]
  local h = math.sqrt(dx^2 + dy^2)
  local ps = rod(name, a, { dx / h * 0.3, dy / h * 0.3, 1 }, L, d)
  local up = m:rest_length(ps[1], ps[2])
  m:set_position(ps[2], { from[1], from[2], up })
  m:lock(ps[2], "xy")
  local n = #ps
  seq:drag({ { ps[n], { to[1], to[2], 0 } }, { ps[n - 1], { to[1], to[2], up } } }, "arc " .. name)
  m:lock(ps[n], "xyz")
  m:lock(ps[n - 1], "xy")
  seq:keep("arc " .. name, seq:relax("arc " .. name), worst)
end

arc("A", { 0.5, 0.45 }, { 3.0, 0.45 }, 6.0, 0.020)
arc("B", { 3.0, 1.55 }, { 5.5, 1.55 }, 6.0, 0.020)

-- Stage 2, cantilevers: a rod bundled onto an arc over two segments (rule 8
-- through three of the arc's particles, then its own), running on as a
-- cantilever along the arc's tangent there or towards `heading`, bent by the
-- bundle and its weight.
local function cantilever(name, host, t, L, d, towards, heading)
  local o, p, q = at(host, t, -towards), at(host, t), at(host, t, towards)
  local x, y = m:position(p), m:position(q)
  local dir = heading or { y[1] - x[1], y[2] - x[2], y[3] - x[3] }
  local n = math.max(3, math.floor(L / segment + 0.5))
  local h = math.sqrt(dir[1]^2 + dir[2]^2 + dir[3]^2)
  local step = L / n
  local pts = { o, p, q }
  for k = 1, n - 2 do
    pts[#pts + 1] = m:particle{ y[1] + dir[1] / h * step * k, y[2] + dir[2] / h * step * k, y[3] + dir[3] / h * step * k }
  end
  local s = section(d)
  local ok, beam = m:apply(R.beam, case.beam_options(s, { particles = pts }))
  assert(ok, beam)
  rods[#rods + 1] = { name = name, beam = beam, section = s, length = L }
  seq:keep("cantilever " .. name, seq:relax("cantilever " .. name), worst)
end

cantilever("C1", "A", 0.55, 2.5, 0.012, 1)
cantilever("C2", "B", 0.45, 2.5, 0.012, -1)
cantilever("C3", "A", 0.35, 1.5, 0.010, -1, { -1, 0, 0.1 })
cantilever("C4", "B", 0.65, 1.5, 0.010, 1, { 1, 0, 0.1 })
cantilever("C5", "A", 0.60, 2.0, 0.012, 1)
cantilever("C6", "B", 0.40, 2.0, 0.012, -1)

-- Stage 3, grid: rods from one particle of the structure (rule 10 shares
-- it) dragged onto another and connected (rule 3). A rod is cut a fifth
-- longer than the gap it bridges (at least 1.5 m), unless its length is given.
local function bridge(name, from, to, d, L, lift)
  local x, y = m:position(from), m:position(to)
  local gap = case.distance(x, y)
  L = L or math.max(1.5, 1.2 * gap)
  assert(gap < L, string.format("%s: %.2f m apart, longer than the rod (%.2f m)", name, gap, L))
  local dir = { y[1] - x[1], y[2] - x[2], y[3] - x[3] + (lift or 0.3) }
  local ps = rod(name, from, dir, L, d)
  return seq:step("grid " .. name, { { ps[#ps], to } }, worst)[1], ps
end

bridge("G1", at("C1", 1), at("B", 0.75), 0.010)
bridge("G2", at("C2", 1), at("A", 0.25), 0.010)
bridge("G3", at("C5", 1), at("C6", 1), 0.008)

-- The erroneous connection: a 20 mm rod dragged onto a particle too close to
-- its start bends tighter than the rod can take; the connection is reverted
-- (rule 4) and the rod connected where it belongs.
local wrong_joint = bridge("G4", at("A", 0.5), at("A", 0.65), 0.020, 2.8, 0.6)
local bad = seq.steps[#seq.steps]
assert(bad.utilisation > 1, string.format("the erroneous connection should overstress G4 (utilisation %.2f)", bad.utilisation))
seq:revert(wrong_joint, "revert G4", worst)
local reverted = seq.steps[#seq.steps]
local g4_end = m:particles(beam_of("G4"))
seq:step("grid G4", { { g4_end[#g4_end], at("B", 0.5) } }, worst)

-- Legs from the floor up to the outer cantilevers' tips, pinned on the
-- floor, cut 15 % longer than the gap and bowing outwards.
local function leg(name, x, y, to, d, outwards)
  local p = m:position(to)
  local gap = case.distance(p, { x, y, 0 })
  local dir = { p[1] - x + outwards * 0.3 * gap, p[2] - y, p[3] }
  rod(name, foot(x, y), dir, math.max(1.5, 1.15 * gap), d)
  local ps = m:particles(beam_of(name))
  seq:step("leg " .. name, { { ps[#ps], to } }, worst)
end

leg("L1", -0.2, 1.2, at("C3", 1), 0.016, -1)
leg("L2", 6.2, 0.8, at("C4", 1), 0.016, 1)

bridge("G5", at("L1", 0.6), at("G2", 0.5), 0.008)
bridge("G6", at("L2", 0.6), at("G1", 0.5), 0.008)
bridge("G7", at("G1", 0.5), at("G3", 0.5), 0.006)
bridge("G8", at("G2", 0.5), at("G3", 0.5), 0.006)
bridge("G9", at("C1", 0.7), at("C6", 0.7), 0.005)
bridge("G10", at("C2", 0.7), at("C5", 0.7), 0.005)
bridge("G11", at("C3", 0.5), at("G5", 0.5), 0.006)
bridge("G12", at("C4", 0.5), at("G6", 0.5), 0.006)

-- Figures ---------------------------------------------------------------------
m:check()
local env = case.envelope(m)
local w = worst(m)
local lengths, dmin, dmax = {}, math.huge, 0
for _, r in ipairs(rods) do
  lengths[#lengths + 1] = r.length
  dmin, dmax = math.min(dmin, r.section.d), math.max(dmax, r.section.d)
end
table.sort(lengths)
local reactions = { 0, 0, 0 }
for _, p in ipairs(m:particles()) do
  if m:locks(p) ~= "" then
    local f = m:reaction(p)
    for k = 1, 3 do reactions[k] = reactions[k] + f[k] end
  end
end
local weight = 0
for _, r in ipairs(rods) do weight = weight + r.section.line_mass * r.length * 9.81 end

local rows = {
  { "rods", #rods, "", 22 },
  { "rod diameters", string.format("%g-%g", 1e3 * dmin, 1e3 * dmax), "mm", "5-20" },
  { "rod lengths", string.format("%g-%g", lengths[1], lengths[#lengths]), "m", "1.5-6" },
  { "E", case.gfrp.E / 1e9, "GPa", 25 },
  { "footprint x", env.x, "m", 6, "bounding box" },
  { "footprint y", env.y, "m", 2 },
  { "height", env.height, "m", 2.5 },
  { "assembly steps (equilibria)", #seq.steps, "", nil, "arc, cantilever, grid, one reverted" },
  { "largest bending stress", w.stress / 1e6, "MPa", nil, string.format("rod %s, R = %.2f m", w.in_rod, w.radius) },
  { "utilisation", w.utilisation, "", nil, "of 400 MPa (assumed)" },
  { "G4 connected wrongly: utilisation", bad.utilisation, "", nil, "reverted by rule 4" },
  { "vertical reactions / weight", reactions[3] / weight, "", 1, "self-weight only" },
}
local text = case.table("AAVS Madrid 2016 (thesis 6.2)", rows)
print("assembly sequence: stage | steps to equilibrium | particles | largest stress [MPa] in rod")
for _, s in ipairs(seq.steps) do
  print(string.format("  %-16s %7d %5d %8.1f  %-4s %5.2f", s.stage, s.steps, s.particles, s.stress / 1e6, s.in_rod, s.height))
end

case.write(m, "aavs", text, { height = env.height, length = env.x, width = env.y, utilisation = w.utilisation },
           { direction = { 0.35, -1, 0.45 }, zoom = 0.7 })

-- The quick variant's checks: the figures the thesis gives, within the
-- freedom our layout has.
assert(#rods == 22)
case.expect("footprint x", env.x, 5.5, 6.5)
case.expect("footprint y", env.y, 1.5, 2.5)
case.expect("height", env.height, 2.0, 2.6)
case.expect("utilisation", w.utilisation, 0, 1)
case.expect("vertical reactions / weight", reactions[3] / weight, 0.999, 1.001)
case.expect("utilisation of the reverted G4", reverted.utilisation, 0, 1)
