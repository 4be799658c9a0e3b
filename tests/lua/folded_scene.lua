-- A patch with a quad turned inside out: m:run says so, converged or not
-- (tests/CMakeLists.txt checks the final line).
local m = tendril.model()
local grid = {}
for r = 0, 2 do for c = 0, 2 do grid[#grid + 1] = m:particle{ c, r, 0 } end end
local patch = m:quad_grid{ particles = grid, rows = 3, cols = 3, EA = 10, prestress = 1 }
for _, p in ipairs(grid) do m:lock(p, "xyz") end
m:set_position(grid[5], { 2.5, 2.5, 0 })   -- the centre beyond the far corner
local r = m:run{}
assert(r.converged and #r.folded == 3, #r.folded)   -- the three quads round the centre
local f = r.folded[1]
assert(f.patch == patch and f.jacobian < 0 and #f.particles == 4)
local has_centre = false
for _, p in ipairs(f.particles) do has_centre = has_centre or p == grid[5] end
assert(has_centre)
