-- Textile hybrids with every integrator (issue 11): each case is built the
-- way docs/meshing.md builds it, form-found, loaded, and relaxed to
-- 1e-3 N; the table gives steps, wall time and how far the shape is from
-- Leapfrog's (the largest particle distance over the case's span).
--   bash bench/run.sh hybrids
local integrators = { "leapfrog", "symplectic_euler", "velocity_verlet", "midpoint", "rk4", "vie", "projective", "mixed" }

local function tube(d, t) return math.pi * (d^2 - (d - 2 * t)^2) / 4, math.pi * (d^4 - (d - 2 * t)^4) / 64 end

local cases = {}

-- Two GFRP arches (20 mm rods), a CST strip of 50 N/m, then 10 Pa of wind.
cases[#cases + 1] = { name = "arches+strip", span = 4, build = function(m)
  local E, d = 25e9, 0.02
  local function arch(y)
    local pts = {}
    for i = 0, 16 do
      local t = math.pi * i / 16
      pts[#pts + 1] = { 2 * math.cos(t), y, 1.5 * math.sin(t) }
    end
    local beam = m:beam{ points = pts, EA = E * math.pi * d^2 / 4, EI = E * math.pi * d^4 / 64 }
    local ps = m:particles(beam)
    for _, foot in ipairs{ ps[1], ps[#ps] } do m:lock(foot, "xyz"); m:clamp(foot, beam) end
    return ps
  end
  local strip = m:project{ from = arch(0), to = arch(2), rows = 7, EA = 2e3, prestress = 20 }
  return function()
    m:formulation(strip, "cst", { stress = { 50, 50 } })
    local r = m:run{ tolerance = 1e-3, max_steps = 400000 }
    if not r.converged then return r end
    m:pressure(strip, 10, { 0, 0, 1 })
    return m:run{ tolerance = 1e-3, max_steps = 400000 }
  end
end }

-- A steel ring (50 x 4 mm tube, radius 2 m) on four supports with a paved
-- CST membrane of 500 N/m, inflated by 200 Pa: a cushion.
cases[#cases + 1] = { name = "ring cushion", span = 4, build = function(m)
  local A, I = tube(0.05, 0.004)
  local rim = m:beam{ centre = { 0, 0, 0 }, normal = { 0, 0, 1 }, radius = 2, segments = 32, EA = 210e9 * A, EI = 210e9 * I }
  local ps = m:particles(rim)
  for i = 1, #ps, 8 do m:lock(ps[i], "xyz") end
  local membrane = m:pave{ particles = ps, EA = 5e3, prestress = 100 }
  return function()
    m:formulation(membrane, "cst", { stress = { 500, 500 }, seams = true })
    m:pressure(membrane, 200, { 0, 0, 1 })
    return m:run{ tolerance = 1e-3, max_steps = 400000 }
  end
end }

-- A cable net (bars patch, 10 kN EA, 200 N prestress) between a GFRP arch
-- (40 x 3 mm tube) and a pinned ground line, under 20 N per net node.
cases[#cases + 1] = { name = "arch+cable net", span = 6, build = function(m)
  local A, I = tube(0.04, 0.003)
  local pts, ground = {}, {}
  for i = 0, 12 do
    local t = math.pi * i / 12
    pts[#pts + 1] = { 3 * math.cos(t), 0, 2.5 * math.sin(t) }
    ground[#ground + 1] = m:particle{ 3 * math.cos(t), 3, 0 }
    m:lock(ground[#ground], "xyz")
  end
  local beam = m:beam{ points = pts, EA = 25e9 * A, EI = 25e9 * I }
  local ps = m:particles(beam)
  for _, foot in ipairs{ ps[1], ps[#ps] } do m:lock(foot, "xyz"); m:clamp(foot, beam) end
  local net = m:project{ from = ps, to = ground, rows = 5, EA = 1e4, prestress = 200 }
  return function()
    for _, p in ipairs(m:particles(net)) do
      if m:state(p) == "simple" then m:load(p, { 0, 0, -20 }) end
    end
    return m:run{ tolerance = 1e-3, max_steps = 400000 }
  end
end }

print("case             integrator        converged    steps   time s   shape vs leapfrog [% span]")
for _, case in ipairs(cases) do
  local reference
  for _, integrator in ipairs(integrators) do
    local m = tendril.model()
    local go = case.build(m)
    assert(m:run{ tolerance = 1e-3, max_steps = 400000 }.converged, case.name .. ": the bars did not relax")
    m:settings{ integrator = integrator }
    local t0, s0 = os.clock(), m:steps()
    local ok, r = pcall(go)
    local seconds = os.clock() - t0
    local shape = {}
    for i, p in ipairs(m:particles()) do shape[i] = m:position(p) end
    reference = reference or shape
    local worst = 0
    for i, x in ipairs(shape) do
      local y = reference[i]
      worst = math.max(worst, math.sqrt((x[1] - y[1])^2 + (x[2] - y[2])^2 + (x[3] - y[3])^2))
    end
    if ok then
      print(string.format("%-16s %-17s %-9s %8d %8.2f %12.4f", case.name, integrator, tostring(r.converged), m:steps() - s0,
        seconds, 100 * worst / case.span))
    else
      print(string.format("%-16s %-17s failed: %s", case.name, integrator, tostring(r):gsub("\n.*", "")))
    end
  end
end
