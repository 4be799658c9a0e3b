-- Every vertex state of thesis 4.2.6 in one small model, for the studio's
-- browser tests: a rod locked at one end and fully locked at the other, a
-- cable from its middle (a shared particle) to a free end (simple), an
-- isolated particle, a passive one, and a 3 x 3 patch hung from its corners.
local m = tendril.model()
m:gravity{ 0, 0, -9.81 }
local rod = m:beam{ from = m:particle{ 0, 0, 0 }, direction = { 4, 0, 0 }, segments = 8, EA = 1e6, EI = 200, line_mass = 1 }
local ps = m:particles(rod)
m:lock(ps[1], "xyz")                       -- lock (red)
m:lock(ps[#ps], "full")                    -- full-lock (yellow)
m:cable(ps[5], m:particle{ 2, -1.5, 0.5 }, { EA = 1e4, line_mass = 0.1 })  -- ps[5] shared (purple), its end simple (cyan)
m:particle{ 2, 2, 1.5 }                    -- isolated (black)
local grid = {}
for r = 0, 3 do
  for c = 0, 3 do grid[#grid + 1] = m:particle{ 1 + c * 0.5, 1 + r * 0.5, 0 } end
end
m:quad_grid{ particles = grid, rows = 4, cols = 4, EA = 1e4, line_mass = 0.1 }
for _, k in ipairs{ 1, 4, 13, 16 } do m:lock(grid[k], "xyz") end
m:passive(grid[6], true)                   -- passive (grey)
local r = m:run{ tolerance = 1e-3, max_steps = 50000 }
print(string.format("states scene: %d particles, equilibrium %s after %d steps", m:count().particles, tostring(r.converged), r.steps))
