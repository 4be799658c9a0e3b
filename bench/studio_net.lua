-- The studio benchmark's model (bench/studio_bench.mjs): a square net of
-- about `particles` particles (a bar patch, n x n), its corners pinned,
-- sagging under its own weight. Parameters: particles (default 2000).
local target = tendril.param("particles", 2000)
local n = math.max(2, math.floor(math.sqrt(target) + 0.5))
local m = tendril.model()
m:gravity{ 0, 0, -9.81 }
local h = 10 / (n - 1)
local grid = {}
for r = 0, n - 1 do
  for c = 0, n - 1 do grid[#grid + 1] = m:particle{ c * h, r * h, 0 } end
end
m:quad_grid{ particles = grid, rows = n, cols = n, EA = 1e5, line_mass = 0.5 }
for _, k in ipairs{ 1, n, n * (n - 1) + 1, n * n } do m:lock(grid[k], "xyz") end
print(string.format("studio_net: %d particles", n * n))
