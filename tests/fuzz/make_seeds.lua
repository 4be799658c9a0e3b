-- Writes the seed corpora of tests/fuzz/ (tools/fuzz.sh): small model
-- databases and journals that use every element of the format once.
--   tendril run tests/fuzz/make_seeds.lua --out tests/fuzz/corpus-new
local function save(m, name)
  m:save(tendril.out(name .. ".xml"))
  m:save_journal(tendril.out(name .. ".journal"))
end

-- Cables, locks, loads, masses, roles, passive particles, goals, settings.
local m = tendril.model{ dt = 0.5, damping = "viscous", viscous = 0.2, integrator = "rk4" }
local a, b, c = m:particle{ 0, 0, 0 }, m:particle{ 1, 0, 0 }, m:particle{ 1, 1, 0 }
m:cable(a, b, { EA = 1e4 })
m:cable(b, c, { EA = 1e4, prestress = 10, line_mass = 0.1 })
m:lock(a, "xyz")
m:load(c, { 0, 0, -5 })
m:mass(c, 2)
m:role(b, "parent")
m:passive(m:particle{ 5, 5, 5 }, true)
m:anchor(c, { 1, 1, -0.5 }, 100)
m:goal{ kind = "plane", particle = b, point = { 0, 0, 0 }, normal = { 0, 0, 1 }, weight = 50 }
m:goal{ kind = "length", particles = { a, c }, length = 1.2, weight = 10 }
m:step(3)
save(m, "cables")

-- Beams: 3 DOF, 6 DOF with its own section, a ring, a drop (a loop).
m = tendril.model{ integrator = "vie", vie_iterations = 3 }
local beam = m:beam{ points = { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0.1, 0 }, { 3, 0, 0 } }, EA = 1e5, EI = 10 }
m:lock(m:particles(beam)[1], "full")
m:formulation(beam, 6)
m:beam{ points = { { 0, 2, 0 }, { 1, 2, 0 }, { 1, 3, 0 } }, closed = true, EA = 1e5, EI = 5, dofs = 6, GJ = 3 }
local drop = m:beam{ points = { { 0, 5, 0 }, { 1, 5, 0 }, { 1, 6, 0 }, { 0, 6, 0 }, { 0, 5.5, 0 } }, EA = 1e4, EI = 1 }
assert(m:apply(tendril.rules.drop_single, drop))
m:step(2)
save(m, "beams")

-- Patches: bars, CST form-finding, CST analysis.
m = tendril.model()
local function grid(z)
  local ps = {}
  for r = 0, 2 do for col = 0, 2 do ps[#ps + 1] = m:particle{ col, r, z } end end
  for _, k in ipairs{ 1, 3, 7, 9 } do m:lock(ps[k], "xyz") end
  return m:quad_grid{ particles = ps, rows = 3, cols = 3, EA = 1e3 }
end
grid(0)
m:formulation(grid(1), "cst", { stress = { 2, 1 } })
m:formulation(grid(2), "cst", { analysis = { dxx = 100, dyy = 80, dxy = 10, G = 20 }, stress = { 1, 1 } })
m:step(2)
save(m, "patches")
