-- Autonomous growth (thesis 5.5.1): four flocking parents cross a 6 m square,
-- each dropping children that become a bent GFRP rod pinned at both ends;
-- tensile linkers tie neighbouring rods with cables; the network then relaxes
-- under its own weight. Parameters: tendril.param(name, default); `tendril
-- sweep` varies them. Same seed, same network. Prints the most stressed rod.
local A = tendril.agents
local spacing = tendril.param("spacing", 0.3)
local view = tendril.param("view", 50)
local jitter = tendril.param("jitter", 0.3)

local m = tendril.model()
m:gravity{ 0, 0, -9.81 }
local d = 0.012
local rod = { E = 25e9, A = math.pi * d^2 / 4, I = math.pi * d^4 / 64, line_mass = 1850 * math.pi * d^2 / 4 }

-- Each parent starts on one side, rises over the middle and lands opposite.
local function jittered(x, y, z)
  return { x + jitter * (math.random() - 0.5), y + jitter * (math.random() - 0.5), z }
end
local parents = {}
for k = 0, 3 do
  local a = k * math.pi / 2 + math.pi / 4
  local c, s = math.cos(a), math.sin(a)
  parents[#parents + 1] = {
    position = jittered(3 * c, 3 * s, 0),
    velocity = { 0, 0, 0.05 },
    targets = { jittered(1.2 * c, 1.2 * s, 2.2), jittered(-1.2 * s, 1.2 * c, 2.6), jittered(-3 * c, -3 * s, -0.4) },
  }
end
local flock = A.flock{ model = m, parents = parents, section = rod, spacing = spacing, children = 32,
                       max_speed = 0.04, max_force = 0.004, reach = 0.35 }
local linker = A.linker{ model = m, flock = flock, distance = 0.9, view = view, max_links = 2,
                         section = { EA = 2e4 }, shrink = 0.95 }

m:trigger{ rule = flock.rule, every = 1, max = 4000 }
m:trigger{ rule = linker.rule, every = 25 }
local grown = m:run{ tolerance = 1e-9, max_steps = 6000 }   -- growth: the parents fly
assert(flock:done(), "the parents did not finish")

local r = m:run{ tolerance = 1e-3, max_steps = 200000 }     -- relax the grown network
local c = m:count()
print(string.format("grown: %d particles, %d beams, %d cables; equilibrium %s after %d steps (residual %.2e N)",
  c.particles, c.beams, c.cables, tostring(r.converged), r.steps, r.residual))
assert(c.beams == 4 and c.cables >= 4, "too few links")
m:check()
-- The most stressed rod and how much of the GFRP's strength it uses
-- (docs/lua-api.md, "Results"); grow.vtk shows every element's for ParaView.
local section = tendril.section.rod{ d = d, material = "gfrp" }
local worst = m:summary(section)
print(string.format("most stressed rod: block %d at particle %d, %.0f MPa, utilisation %.2f", worst.max_stress_block,
  worst.max_stress_particle, worst.max_stress / 1e6, worst.max_utilisation))
tendril.report(m, { converged = r.converged, max_stress = worst.max_stress, utilisation = worst.max_utilisation })
m:save(tendril.out("grow.xml"))
m:save_obj(tendril.out("grow.obj"))
m:export_vtk(tendril.out("grow.vtk"), section)
m:save_journal(tendril.out("journal.txt"))
