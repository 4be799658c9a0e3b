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
-- Each run checks the positions it ends at: moved back, the centre folds
-- nothing; moved out again, the same three quads.
m:set_position(grid[5], { 1, 1, 0 })
assert(#m:run{}.folded == 0)
m:set_position(grid[5], { 2.5, 2.5, 0 })
assert(#m:run{}.folded == 3)
-- A second patch, folded the same way, joins the report once it exists,
-- and leaves it when it is deleted.
local other = {}
for r = 0, 2 do for c = 0, 2 do other[#other + 1] = m:particle{ c, r + 5, 0 } end end
local second = m:quad_grid{ particles = other, rows = 3, cols = 3, EA = 10, prestress = 1 }
for _, p in ipairs(other) do m:lock(p, "xyz") end
m:set_position(other[5], { 2.5, 7.5, 0 })
local both = m:run{}.folded
assert(#both == 6, #both)
local in_second = 0
for _, q in ipairs(both) do if q.patch == second then in_second = in_second + 1 end end
assert(in_second == 3, in_second)
m:delete(second)
r = m:run{}
assert(#r.folded == 3 and r.folded[1].patch == patch)
