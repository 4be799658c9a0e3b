-- Thesis 6.3.2, BAT02 (Foster + Partners, 2018): a meeting pod shaped from a
-- closed bending-active ring of four bundled pultruded GFRP tubes and a
-- membrane, held in shape by the prestress of its tensile elements alone.
-- The scene follows fig. 6.18: (a) a closed 3-DOF spline-beam ring on the
-- XY plane (the ring rule: centre, plane, radius, resolution); (b) a
-- membrane paved inside it (rule 20: a structured quad patch of elastic
-- bars with geometric stiffness only); (c) four particles locked, one in
-- each quadrant, two of them moved normal to the XY plane step by step into
-- a cocoon; (d) two elastic bars added (two-way bars, rule 6) between
-- opposite quadrants before the upper particles are unlocked: the pod
-- stands by itself. Then the snap-through of fig. 6.19, and the range of
-- equilibrium states between open and closed of fig. 6.17:
--  - pushed down at its two upper quadrant particles, the cocoon snaps
--    through into the state turned inside out (the upper particles below
--    the feet), and stays there when let go: a second equilibrium of the
--    same model; pushed back up, it snaps back at another load;
--  - the bar between the upper particles, shortened or lengthened (a
--    calibration, as an actuator would), closes or opens the cocoon.
--
-- From the thesis: the ring is four GFRP tubes, d 9.25 mm, wall 3.25 mm,
-- bundled; 3-DOF beams and bars with geometric stiffness. Ours (the thesis
-- gives no dimensions): a ring 4 m across, a membrane stress of 30 N/m (the
-- bars' prestress is that times their spacing), the quadrant particles at
-- 0, 90, 180 and 270 degrees, the upper two lifted 2 m, and feet: the two
-- lower quadrant particles (one pinned, one on a rail along x) and their
-- neighbours resting on the floor (z locked), so the pod cannot roll over
-- its feet. GFRP (tendril.material "gfrp": E 25 GPa, 1900 kg/m3, 400 MPa);
-- the membrane's weight is left out (the ring's is in).
--
--   tendril run scripts/case-studies/bat02.lua                 quick (the test)
--   tendril run scripts/case-studies/bat02.lua --param full=1 --out out/bat02
local case = require("lib.case")
local R = tendril.rules

local variant = case.variant()
local n = variant.full and 64 or 32                 -- ring segments
local radius, lift, sigma = 2.0, 2.0, 30            -- m, m, N/m
local settle = { tolerance = variant.full and 1e-3 or 1e-2, max_steps = 300000 }

-- Four tubes bundled: they bend together, each carrying a quarter of the
-- moment, so the bundle's EA, EI, W and line mass are four tubes'.
local tube = tendril.section.tube{ d = 0.00925, t = 0.00325, material = "gfrp" }
local bundle = { EA = 4 * tube.EA, EI = 4 * tube.EI, W = 4 * tube.Wy, line_mass = 4 * tube.line_mass,
                 strength = tube.strength }

local m = tendril.model{ integrator = "leapfrog" }
m:gravity{ 0, 0, -9.81 }

-- (a) The ring.
local ok, ring = m:apply(R.ring, { centre = { 0, 0, 0 }, normal = { 0, 0, 1 }, radius = radius, segments = n,
                                   EA = bundle.EA, EI = bundle.EI, line_mass = bundle.line_mass })
assert(ok, ring)
local ps = m:particles(ring)

-- (b) The membrane, paved inside the ring: its bars' prestress is the
-- membrane stress times their spacing (the ring's segment length), their
-- EA five times that: soft enough that the quads do not fold where the
-- cocoon shrinks the membrane (ten times folds them in the full variant),
-- stiff enough to keep the flat net regular.
local spacing = 2 * math.pi * radius / n
local membrane_section = { EA = 5 * sigma * spacing, prestress = sigma * spacing }
local ok2, membrane = m:apply(R.patch_paving, { particles = ps, EA = membrane_section.EA,
                                                prestress = membrane_section.prestress })
assert(ok2, membrane)

-- (c) Four quadrant particles: q[1] and q[3] on the floor (q[1] pinned, q[3]
-- on a rail along x, their neighbours resting on the floor), q[2] and q[4]
-- locked in z and lifted in steps.
local q = {}
for k = 0, 3 do q[k + 1] = ps[k * n // 4 + 1] end
m:lock(q[1], "xyz")
m:lock(q[3], "yz")
for _, i in ipairs{ 2, n, n // 2, n // 2 + 2 } do m:lock(ps[i], "z") end
m:lock(q[2], "z")
m:lock(q[4], "z")
local flat = case.settle(m, "(b) the membrane in the flat ring", settle)

local stages = {}
local function crown() return 0.5 * (m:position(q[2])[3] + m:position(q[4])[3]) end
local lifts = variant.full and 8 or 4
for k = 1, lifts do
  for _, p in ipairs{ q[2], q[4] } do
    local x = m:position(p)
    m:set_position(p, { x[1], x[2], lift * k / lifts })
  end
  local r = case.settle(m, string.format("(c) lifted to %.2f m", lift * k / lifts), settle)
  stages[#stages + 1] = { stage = string.format("(c) lifted to %.2f m", lift * k / lifts), steps = r.steps, crown = crown() }
end

-- (d) Two elastic bars between opposite quadrants, at the distances the
-- cocoon has now, then the upper particles let go.
local bar_section = { EA = bundle.EA }
local top_bar = m:bar(q[2], q[4], bar_section)
local foot_bar = m:bar(q[1], q[3], bar_section)
m:unlock(q[2])
m:unlock(q[4])
local r = case.settle(m, "(d) unlocked", settle)
stages[#stages + 1] = { stage = "(d) unlocked: self-standing", steps = r.steps, crown = crown() }

-- The state of the model now: crown height, energies, bar forces, the
-- ring's largest bending stress (m:forces: moment over the bundle's W).
local function gravity_energy()
  local e = 0
  for i = 1, n do
    local a, b = m:position(ps[i]), m:position(ps[i % n + 1])
    e = e + bundle.line_mass * case.distance(a, b) * 9.81 * 0.5 * (a[3] + b[3])
  end
  return e
end
local function state(name)
  local stress = case.moment_stress(m, ring, bundle.W)
  local s = {
    name = name, crown = crown(), top = case.envelope(m).top, bottom = case.envelope(m).bottom,
    bending = case.energy(m, ring), membrane = case.energy(m, membrane, membrane_section),
    bars = case.energy(m, top_bar) + case.energy(m, foot_bar), weight = gravity_energy(),
    top_bar = m:forces(top_bar).segments[1].axial, foot_bar = m:forces(foot_bar).segments[1].axial,
    stress = stress, utilisation = stress / bundle.strength,
  }
  s.total = s.bending + s.membrane + s.bars + s.weight
  return s
end
local A = state("A: as unlocked")

-- Snap-through (fig. 6.19): a load on the two upper particles, raised in
-- increments, each to equilibrium; at each, let go and see whether the
-- crown stays on the other side of the feet (it snapped through) or
-- springs back (then the load goes on). And back, from the other side.
local increment = variant.full and 2 or 5             -- N per particle
local function push(direction, snapped)
  local F = 0
  repeat
    F = F + increment
    assert(F <= 500, "no snap-through up to 500 N")
    for _, p in ipairs{ q[2], q[4] } do m:load(p, { 0, 0, direction * F }) end
    case.settle(m, string.format("pushed with %g N", direction * F), settle)
    local through = snapped(crown())
    for _, p in ipairs{ q[2], q[4] } do m:load(p, { 0, 0, 0 }) end
    if through then case.settle(m, "let go", settle) end
  until through and snapped(crown())
  return F
end
local snap_down = push(-1, function(z) return z < 0 end)
local B = state("B: snapped through")
local snap_up = push(1, function(z) return z > 0 end)
local A2 = state("A again")

-- The range between open and closed (fig. 6.17): the bar between the upper
-- particles calibrated shorter (closing the cocoon) and longer (opening it).
local L0 = m:rest_length(q[2], q[4])
local range = {}
local factors = variant.full and { 0.7, 0.8, 0.9, 1.1, 1.2 } or { 0.8, 1.2 }
for _, f in ipairs(factors) do
  m:rest_length(q[2], q[4], f * L0)
  case.settle(m, string.format("top bar at %.2f of its length", f), settle)
  local s = state(string.format("top bar x %.1f", f))
  s.factor, s.length = f, f * L0
  range[#range + 1] = s
end
m:rest_length(q[2], q[4], L0)
case.settle(m, "top bar back to its length", settle)
m:check()

-- Figures ---------------------------------------------------------------------
local env = case.envelope(m)
local feet = 0
for _, p in ipairs(m:particles()) do
  if m:locks(p) ~= "" then feet = feet + m:reaction(p)[3] end
end
local weight = bundle.line_mass * 9.81 * 2 * math.pi * radius
local worst = math.max(A.utilisation, B.utilisation)
for _, s in ipairs(range) do worst = math.max(worst, s.utilisation) end
local count = m:count()
local quality = m:quality(membrane)
local rows = {
  { "ring", "4 tubes d 9.25 / 3.25 mm", "", "4 tubes d 9.25 / 3.25 mm", "GFRP, bundled" },
  { "ring diameter", 2 * radius, "m", nil, "ours" },
  { "blocks: ring, membrane, bars", string.format("%d, %d, %d", count.beams, count.patches, count.two_way_bars), "", "1, 1, 2" },
  { "membrane quads, particles", string.format("%d, %d", quality.quads, count.particles), "", nil, "paved, rule 20" },
  { "membrane: smallest scaled Jacobian", quality.jacobian_min, "", nil, "in A: no quad folded" },
  { "crown as unlocked (A)", A.crown, "m", nil, string.format("lifted to %.1f m, locked", lift) },
  { "crown snapped through (B)", B.crown, "m", nil, "below the feet: turned inside out" },
  { "snap-through load A -> B", 2 * snap_down, "N", nil, string.format("both upper particles, in %g N steps", 2 * increment) },
  { "snap-through load B -> A", 2 * snap_up, "N", nil, "pushed back up" },
  { "crown back in A", A2.crown, "m", nil, "the same state" },
  { "energy A: bending, membrane, bars, weight [J]", string.format("%.1f, %.1f, %.2f, %.1f", A.bending, A.membrane, A.bars, A.weight), "" },
  { "energy B: bending, membrane, bars, weight [J]", string.format("%.1f, %.1f, %.2f, %.1f", B.bending, B.membrane, B.bars, B.weight), "" },
  { "bar forces A: top, feet [N]", string.format("%.0f, %.0f", A.top_bar, A.foot_bar), "", nil, "tension > 0" },
  { string.format("crown, top bar %.1f to %.1f of its length [m]", range[1].factor, range[#range].factor),
    string.format("%.2f to %.2f", range[1].crown, range[#range].crown), "", nil, "fig. 6.17: closed to open" },
  { "largest bending stress", worst * bundle.strength / 1e6, "MPa", nil, "M / (4 W), every state" },
  { "utilisation", worst, "", nil, "of 400 MPa (tendril.material gfrp)" },
  { "floor reactions / ring weight", feet / weight, "", 1, "self-standing: only the feet" },
}
local text = case.table("BAT02 (thesis 6.3.2)", rows)
print("sequence: stage | steps to equilibrium | crown [m]")
for _, s in ipairs(stages) do print(string.format("  %-30s %7d %6.3f", s.stage, s.steps, s.crown)) end
print("states: name | crown [m] | energy: bending, membrane, bars, weight, total [J] | bars: top, feet [N] | utilisation")
for _, s in ipairs{ A, B, A2, table.unpack(range) } do
  print(string.format("  %-20s %6.3f  %7.2f %7.2f %6.3f %7.2f %7.2f  %7.1f %7.1f  %.2f", s.name, s.crown, s.bending, s.membrane,
                      s.bars, s.weight, s.total, s.top_bar, s.foot_bar, s.utilisation))
end
case.write(m, "bat02", text, { crown_A = A.crown, crown_B = B.crown, snap_down = 2 * snap_down, snap_up = 2 * snap_up,
                               energy_A = A.total, energy_B = B.total, utilisation = worst },
           { direction = { 1, -0.8, 0.5 }, zoom = 0.8 })

-- The quick variant's checks.
assert(count.beams == 1 and count.patches == 1 and count.two_way_bars == 2 and m:closed(ring))
case.expect("crown as unlocked [m]", A.crown, 0.8, lift)
case.expect("crown snapped through [m]", B.crown, -lift, -0.8)
case.expect("crown back in A [m]", A2.crown, A.crown - 0.01, A.crown + 0.01)
case.expect("snap-through load A -> B [N]", 2 * snap_down, 10, 1000)
case.expect("utilisation", worst, 0, 1)
case.expect("membrane: smallest scaled Jacobian", quality.jacobian_min, 0.3, 1)
case.expect("floor reactions / ring weight", feet / weight, 0.99, 1.01)
