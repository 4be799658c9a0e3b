-- v1 journal fixture: patches by every meshing method, CST switches, multires (generated on 3b364af).
local m = tendril.model()
local R = tendril.rules
local grid = {}
for r = 0, 3 do
  for c = 0, 3 do
    local p = m:particle{ c, r, 0 }
    if r == 0 or c == 0 or r == 3 or c == 3 then m:lock(p, "xyz") end
    grid[#grid + 1] = p
  end
end
local patch = m:quad_grid{ particles = grid, rows = 4, cols = 4, EA = 100, prestress = 50, line_mass = 1 }
m:gravity{ 0, 0, -1 }
m:step(10)
local ok, mr = m:apply(R.multires, patch, { factor = 2 })
assert(ok)
m:step(10)
assert(m:apply(R.refine, mr))
m:step(10)
assert(m:apply(R.coarsen, mr))
m:step(5)
-- paving inside a square
local sq = {}
for i = 0, 3 do sq[#sq + 1] = m:particle{ 10 + i, 0, 0 } end
for i = 0, 3 do sq[#sq + 1] = m:particle{ 14, i, 0 } end
for i = 0, 3 do sq[#sq + 1] = m:particle{ 14 - i, 4, 0 } end
for i = 0, 3 do sq[#sq + 1] = m:particle{ 10, 4 - i, 0 } end
for _, p in ipairs(sq) do m:lock(p, "xyz") end
local paved = m:pave{ particles = sq, EA = 1e3, prestress = 10 }
m:formulation(paved, "cst", { stress = { 5, 5 }, warp = { 1, 0, 0 } })
m:step(10)
m:formulation(paved, "cst", { stress = { 1, 1 }, analysis = { dxx = 800, dyy = 500, dxy = 100, G = 30 } })
m:step(10)
m:formulation(paved, "bars")
local inner = m:particles(paved)
local loop = {}
for i = 0, 5 do
  local t = 2 * math.pi * i / 6
  loop[#loop + 1] = m:particle{ 20 + 2 * math.cos(t), 2 * math.sin(t), 0.4 * (i % 2) }
end
local cc = m:catmull_clark{ particles = loop, levels = 1, EA = 1e3, prestress = 10 }
local finer = m:subdivide_patch(cc)
m:delete(cc)
local function arch(x, y, n)
  local pts = {}
  for i = 0, n do
    local t = math.pi * i / n
    pts[#pts + 1] = { x + 3 * math.cos(t), y, 2 * math.sin(t) }
  end
  return m:particles(m:beam{ points = pts, EA = 1e7, EI = 1e3 })
end
local a, b = arch(30, 0, 8), arch(30, 4, 8)
local strip = m:project{ from = a, to = b, rows = 3, EA = 2e3, prestress = 20 }
local c2 = arch(30, 8, 8)
local strip2 = m:project{ from = b, to = c2, rows = 2, EA = 2e3, prestress = 20 }
m:merge_patches(strip, strip2)
local sp = m:particles(strip)
for _, p in ipairs(sp) do
  if m:state(p) == "simple" then m:remove_from_patch(p) break end
end
m:step(20)
m:save(tendril.out("live.xml"))
m:save_journal(tendril.out("journal.txt"))
