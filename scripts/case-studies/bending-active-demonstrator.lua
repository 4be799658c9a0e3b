-- Thesis 6.1, the Bending-Active Demonstrator (ICD/ITKE/ITFT, University of
-- Stuttgart): CFRP strips 10-15 mm thick, 12-20 m long, each bent in three
-- dimensions and connected to the others, in two self-equilibrated
-- assemblies covering 7.7 x 5.4 m and up to 5 m high; the bigger one
-- carries a textile hybrid module, form-found elsewhere and taken into the
-- particle model as a rigid body. The scene follows 6.1.2 (figs. 6.3-6.5):
--  (a) each strip starts as a rough, non-developable target (the designers
--      sculpted it in Maya and Rhino): a structured quad mesh of particles
--      on a twisted arch, where the strips cross sharing a particle;
--  (b) planarisation: a planarity goal on every quad and a weak anchor of
--      every particle to its target turn the meshes into planar-quad (PQ)
--      strips, developable: each can be cut flat;
--  (c) when the planar quads are at rest, a trigger reconstructs the model
--      without stopping the solver: the goals go, every strip becomes a
--      bending strip (m:strip: flat at rest, so bent into its PQ shape it
--      carries the prestress of its curvature), its feet are held on the
--      ground, and the textile module comes in as a rigid body;
--  (d) the two assemblies relax to their self-equilibrated state under
--      their weight and the module's;
--  (e) the fine mesh of the FE models, 2 x 2 quads for each coarse one.
--
-- Ours, where the thesis gives no geometry: five strips 0.3 m wide, 10 mm
-- thick, CFRP (tendril.material "cfrp"), three in assembly A crossing over
-- one joint 5.4 m up, two in assembly B crossing 3.2 m up; the strips as
-- grillages of 3-DOF beams (docs/lua-api.md, "Bending strips"); the module
-- a rigid body (m:rigid: shape matching, 6 DOF) of five particles hung from
-- assembly A, 120 kg; the textile itself is left out. The
-- rough meshes come from files (tendril.import), as a CAD tool would write
-- them; ours were drawn by data/bending-active-demonstrator-targets.lua.
-- Multi-resolution: the integration runs on the coarse mesh, planarised
-- and built on; (e) the fine mesh for the FE models comes from it at the
-- end (m:multires, m:refine).
--
--   tendril run scripts/case-studies/bending-active-demonstrator.lua             quick (the test)
--   tendril run scripts/case-studies/bending-active-demonstrator.lua --param full=1 --out out/bad
local case = require("lib.case")

local variant = case.variant()
local along = variant.full and 32 or 12           -- quads along a strip
local across = 2                                   -- quads across it
local width, thickness = 0.3, 0.010                -- m
local cfrp = tendril.material("cfrp")
local settle = { tolerance = variant.full and 1e-3 or 1e-2, max_steps = 400000 }

local m = tendril.model{ integrator = "leapfrog" }
m:gravity{ 0, 0, -9.81 }

-- (a) The rough targets, as the designers drew them: quad meshes read from
-- data/bending-active-demonstrator-ALONG.obj, one group per strip (A1-A3,
-- B1-B2) of 3 rows of ALONG + 1 vertices, its quads row by row, each a
-- twisted arch (data/bending-active-demonstrator-targets.lua drew them).
-- The two joints, where the strips of an assembly cross, are the file's
-- first two vertices, shared by those strips: one particle each.
local here = debug.getinfo(1, "S").source:match("^@(.*)/") or "."
local drawn = tendril.import(string.format("%s/data/bending-active-demonstrator-%d.obj", here, along))
local particle = {}
for v, x in ipairs(drawn.vertices) do particle[v] = m:particle(x) end
local joints = { A = particle[1], B = particle[2] }
local strips = {}
for _, group in ipairs(drawn.groups) do
  assert(#group.faces == across * along, group.name .. ": not a grid of " .. across .. " x " .. along .. " quads")
  local index = {}
  for r = 1, across + 1 do index[r] = {} end
  for r = 1, across do
    for c = 1, along do
      local f = group.faces[(r - 1) * along + c]
      index[r][c], index[r][c + 1], index[r + 1][c + 1], index[r + 1][c] = f[1], f[2], f[3], f[4]
    end
  end
  local grid, target = {}, {}
  for r = 1, across + 1 do
    grid[r], target[r] = {}, {}
    for c = 1, along + 1 do grid[r][c], target[r][c] = particle[index[r][c]], drawn.vertices[index[r][c]] end
  end
  strips[#strips + 1] = { design = { assembly = group.name:sub(1, 1) }, target = target, grid = grid }
end
local sub, cross, unit = case.sub, case.cross, case.unit

-- (b) Planarisation: the mesh's edges as soft bars (a quad grid: they
-- keep the quads' sizes, so the strip develops to its target's length), a
-- planarity goal on every quad, each particle anchored to its target.
local goals = {}
local plane_weight, anchor_weight, mesh_EA = 1e5, 10, 1e4
for _, s in ipairs(strips) do
  local flat = {}
  for _, row in ipairs(s.grid) do for _, p in ipairs(row) do flat[#flat + 1] = p end end
  s.mesh = m:quad_grid{ particles = flat, rows = across + 1, cols = along + 1, EA = mesh_EA }
  for r = 1, across do
    for c = 1, along do
      local g = m:planarity({ s.grid[r][c], s.grid[r][c + 1], s.grid[r + 1][c + 1], s.grid[r + 1][c] }, plane_weight)
      goals[#goals + 1] = g
    end
  end
  for r, row in ipairs(s.grid) do
    for c, p in ipairs(row) do
      if not (r == across / 2 + 1 and c == along / 2 + 1) then goals[#goals + 1] = m:anchor(p, s.target[r][c], anchor_weight) end
    end
  end
end
for _, name in ipairs{ "A", "B" } do goals[#goals + 1] = m:anchor(joints[name], m:position(joints[name]), anchor_weight) end

-- The largest distance of a quad's corner from its best-fit plane, over
-- every strip, relative to the quad's size (computed here from the four
-- corners: the centroid and the normal of the two diagonals' cross product).
local function warp()
  local worst = 0
  for _, s in ipairs(strips) do
    for r = 1, across do
      for c = 1, along do
        local q = { m:position(s.grid[r][c]), m:position(s.grid[r][c + 1]), m:position(s.grid[r + 1][c + 1]),
                    m:position(s.grid[r + 1][c]) }
        local n = unit(cross(sub(q[3], q[1]), sub(q[4], q[2])))
        local h = (q[1][1] - q[2][1] + q[3][1] - q[4][1]) * n[1] + (q[1][2] - q[2][2] + q[3][2] - q[4][2]) * n[2]
                  + (q[1][3] - q[2][3] + q[3][3] - q[4][3]) * n[3]
        worst = math.max(worst, math.abs(h) / 4 / case.distance(q[1], q[3]))
      end
    end
  end
  return worst
end
local rough_warp = warp()
local pq_warp

-- (c) The reconstruction, a rule a trigger fires at the PQ state's rest.
local module_mass = 120
local function distance(p, q)
  local a, b = m:position(p), m:position(q)
  return math.sqrt((a[1] - b[1])^2 + (a[2] - b[2])^2 + (a[3] - b[3])^2)
end
local module_                                    -- kg
local rebuild = tendril.rule{
  name = "bending strips and the module",
  production = function(m)
    pq_warp = warp()
    for k = #goals, 1, -1 do m:remove_goal(goals[k]) end
    for _, s in ipairs(strips) do
      s.length = 0
      local middle = s.grid[across / 2 + 1]
      for c = 1, along do s.length = s.length + case.distance(m:position(middle[c]), m:position(middle[c + 1])) end
      s.strip = m:strip{ particles = s.grid, E = cfrp.E, t = thickness, nu = 0.3, density = cfrp.density }
      for r = 1, across + 1 do
        m:lock(s.grid[r][1], "xyz")
        m:lock(s.grid[r][along + 1], "xyz")
      end
      m:delete(s.mesh)                                     -- its particles stay: the strip has them
    end
    -- The module: hung from the three strips of A a quarter along each,
    -- two free corners cantilevering out, one rigid body; two frame
    -- members give its free corners blocks (a particle in none never moves).
    local hold = {}
    for k = 1, 3 do hold[k] = strips[k].grid[across / 2 + 1][along / 4 + 1] end
    local c = { 0, 0, 0 }
    for _, p in ipairs(hold) do
      local x = m:position(p)
      c = { c[1] + x[1] / 3, c[2] + x[2] / 3, c[3] + x[3] / 3 }
    end
    local body = { hold[1], hold[2], hold[3], m:particle{ c[1] - 0.8, c[2] - 0.8, c[3] - 0.6 },
                   m:particle{ c[1] - 1.2, c[2] + 0.2, c[3] - 0.9 } }
    m:bar(body[1], body[4], { EA = 1e7 })
    m:bar(body[3], body[5], { EA = 1e7 })
    local rest = {}
    for i = 1, #body do
      rest[i] = {}
      for j = 1, #body do rest[i][j] = distance(body[i], body[j]) end
    end
    m:rigid(body, 1e8)
    for k = 4, 5 do m:load(body[k], { 0, 0, -module_mass * 9.81 / 2 }) end
    module_ = { particles = body, rest = rest }
  end,
}
m:trigger{ rule = rebuild, on = "equilibrium", max = 1 }

-- (b) to (d) in one run: the trigger rebuilds the model at the PQ rest and
-- the run goes on to the assemblies' equilibrium.
local r = case.settle(m, "(b) planarisation, (c) reconstruction, (d) equilibrium", settle)
assert(pq_warp, "the reconstruction did not fire")

-- Figures.
local count = m:count()
local function assembly_particles(name)
  local ps = {}
  for _, s in ipairs(strips) do
    if s.design.assembly == name then
      for _, row in ipairs(s.grid) do for _, p in ipairs(row) do ps[#ps + 1] = p end end
    end
  end
  return ps
end
local A, B, all = case.envelope(m, assembly_particles("A")), case.envelope(m, assembly_particles("B")), case.envelope(m)
local worst, worst_strip = 0, nil
for k, s in ipairs(strips) do
  for _, b in ipairs(s.strip.rows) do
    local _, stress = case.bending(m, b, { E = cfrp.E, c = thickness / 2 })
    if stress > worst then worst, worst_strip = stress, k end
  end
end
local module_strain = 0  -- the largest relative change of a distance between its particles
for i, p in ipairs(module_.particles) do
  for j, q in ipairs(module_.particles) do
    if i < j then module_strain = math.max(module_strain, math.abs(distance(p, q) / module_.rest[i][j] - 1)) end
  end
end
local weight, feet = 0, 0
for _, s in ipairs(strips) do weight = weight + s.length * width * thickness * cfrp.density * 9.81 end
weight = weight + module_mass * 9.81
for _, reaction in ipairs(m:reactions()) do feet = feet + reaction.force[3] end
local lengths = {}
for _, s in ipairs(strips) do lengths[#lengths + 1] = string.format("%.1f", s.length) end

local rows = {
  { "strips (assembly A + B)", #strips, "", 5, "3 + 2" },
  { "strip length [m]", table.concat(lengths, ", "), "", "12 to 20", "ours: plain arches over the same area" },
  { "strip section", string.format("%.0f x %.0f mm", width * 1000, thickness * 1000), "", "10-15 mm thick", "CFRP" },
  { "quads per strip", string.format("%d x %d", along, across), "", nil, "the coarse mesh" },
  { "quad warp / diagonal: rough target", rough_warp, "", nil, "twisted arches: not developable" },
  { "quad warp / diagonal: PQ", pq_warp, "", nil, "after planarisation (b)" },
  { "covered area [m]", string.format("%.1f x %.1f", all.x, all.y), "", "7.7 x 5.4" },
  { "height A, B", string.format("%.2f, %.2f", A.height, B.height), "m", "5 (max)" },
  { "steps to equilibrium", r.steps, "", nil, "(b) to (d), one run" },
  { "largest bending stress", worst / 1e6, "MPa", nil, string.format("E t / 2R, strip %d", worst_strip) },
  { "utilisation", worst / cfrp.strength, "", nil, "of 1200 MPa (tendril.material cfrp)" },
  { "module: mass, largest shape strain", string.format("%d kg, %.1e", module_mass, module_strain), "", nil, "a rigid body (m:rigid)" },
  { "feet reactions / weight", feet / weight, "", 1, "self-equilibrated: only the feet" },
}
local text = case.table("Bending-Active Demonstrator (thesis 6.1)", rows)
case.write(m, "bending-active-demonstrator", text,
           { height_A = A.height, height_B = B.height, pq_warp = pq_warp, utilisation = worst / cfrp.strength },
           { direction = { 0.5, -1, 0.6 }, zoom = 1.15 })

-- (e) The fine mesh of the FE models (6.1.2: the high resolution was "a
-- pre-established requisite for facilitating the creation of FE-models";
-- the integration ran on its coarse representation, fig. 6.4), by
-- multi-resolution (m:multires, docs/meshing.md): each strip's grid as a
-- patch split 2 x 2 into a fine one, its new particles passive, then
-- m:refine puts them on the strip as it stands (bilinear in their coarse
-- quads) and deletes the coarse links. After the figures and the outputs
-- above, which stay those of the integrated model; the model with its fine
-- patches goes to NAME-fine.obj (a group per block: the fine meshes are its
-- patch groups; the strips share their joints, so they are not one
-- manifold surface a binary PLY could hold).
local fine_particles = 0
for _, s in ipairs(strips) do
  local flat = {}
  for _, row in ipairs(s.grid) do for _, p in ipairs(row) do flat[#flat + 1] = p end end
  local mr = m:multires(m:quad_grid{ particles = flat, rows = across + 1, cols = along + 1, EA = 1 }, { factor = 2 })
  m:refine(mr)
  fine_particles = fine_particles + #mr.particles
end
m:save_obj(tendril.out("bending-active-demonstrator-fine.obj"))
print(string.format("fine mesh for the FE models: %d x %d quads per strip, %d particles added (bending-active-demonstrator-fine.obj)",
                    2 * along, 2 * across, fine_particles))

-- The quick variant's checks.
assert(fine_particles == #strips * ((2 * along + 1) * (2 * across + 1) - (along + 1) * (across + 1)))
assert(count.beams == #strips * (across + 1 + along + 1) and count.patches == 0)
assert(count.two_way_bars == #strips * 2 * along * across + 2)
case.expect("PQ warp / rough warp", pq_warp / rough_warp, 0, 0.2)
case.expect("covered x [m]", all.x, 7.2, 8.2)
case.expect("covered y [m]", all.y, 5.0, 5.8)
case.expect("height A [m]", A.height, 4.5, 5.2)
case.expect("height B [m]", B.height, 2.5, 4)
case.expect("utilisation", worst / cfrp.strength, 0.05, 1)
case.expect("module's largest shape strain", module_strain, 0, 1e-4)
case.expect("feet reactions / weight", feet / weight, 0.99, 1.01)
