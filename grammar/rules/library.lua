-- The built-in rules of thesis 4.2.7, as tendril.rules.<key>. Each is an
-- ordinary rule (tendril.rule): its axiom judges states and topology, its
-- production calls the model's primitive operations.
local rules = {}

local function define(key, name, axiom, production)
  rules[key] = tendril.rule{ name = name, axiom = axiom, production = production }
end

local function state_is(m, p, ...)
  local s = m:state(p)
  for _, wanted in ipairs{ ... } do
    if s == wanted then return true end
  end
  return false, string.format("particle %d is %s", p.id, s)
end

local function kind_is(m, b, wanted)
  local k = m:kind(b)
  return k == wanted, string.format("block %d is a %s, not a %s", b.id, k, wanted)
end

local function on_patch(m, p)
  for _, b in ipairs(m:blocks(p)) do
    if m:kind(b) == "patch" then return b end
  end
end

local function on_beam(m, p)
  for _, b in ipairs(m:blocks(p)) do
    if m:kind(b) == "beam" then return b end
  end
end

-- Particles ------------------------------------------------------------------

define("add_particle", "rule 1: add a particle", nil,
  function(m, xyz) return m:particle(xyz) end)

define("delete_particle", "rule 2: delete an isolated particle",
  function(m, p) return state_is(m, p, "isolated") end,
  function(m, p) m:delete_particle(p) end)

-- joint: "rigid" makes every two beams meeting at the merged particle a
-- rigid connection (m:connection) keeping the angle they make; "pinned"
-- (the default) leaves them pinned.
define("merge", "rule 3: merge particles",
  function(m, ps, joint)
    if #ps < 2 then return false, "needs at least two particles" end
    if joint ~= nil and joint ~= "rigid" and joint ~= "pinned" then
      return false, "the joint must be \"rigid\" or \"pinned\""
    end
    for _, p in ipairs(ps) do
      local ok, why = state_is(m, p, "simple", "shared", "lock", "full-lock")
      if not ok then return false, why end
    end
    return true
  end,
  function(m, ps, joint)
    local p = m:merge(ps)
    if joint == "rigid" then
      local beams = {}
      for _, b in ipairs(m:blocks(p)) do
        if m:kind(b) == "beam" then beams[#beams + 1] = b end
      end
      for i = 1, #beams do
        for j = i + 1, #beams do m:connection(p, beams[i], beams[j], "rigid") end
      end
    end
    return p
  end)

-- A particle is shared when it holds two or more references: blocks, or one
-- block twice where a loop joins a beam to itself (m:references).
define("explode", "rule 4: explode a shared particle",
  function(m, p)
    local n = #m:references(p)
    if m:state(p) == "passive" then return false, "particle is passive" end
    return n >= 2, string.format("particle %d holds %d reference(s) to blocks", p.id, n)
  end,
  function(m, p) return m:explode(p) end)

define("explode_from", "rule 5: explode a particle from one block",
  function(m, p, b)
    local bs = m:references(p)
    if #bs < 2 or m:state(p) == "passive" then return false, string.format("particle %d is not shared", p.id) end
    for _, x in ipairs(bs) do
      if x == b then return true end
    end
    return false, string.format("particle %d is not on block %d", p.id, b.id)
  end,
  function(m, p, b) return m:explode_from(p, b) end)

-- Cables ---------------------------------------------------------------------

-- kind: "cable" (tension only, the default) or "bar" (two-way elastic bar).
define("cable", "rule 6: create a cable or a two-way bar",
  function(m, a, b, section, kind)
    return kind == nil or kind == "cable" or kind == "bar", "the kind must be \"cable\" or \"bar\""
  end,
  function(m, a, b, section, kind)
    if kind == "bar" then return m:bar(a, b, section) end
    return m:cable(a, b, section)
  end)

define("delete_cable", "rule 7: delete a cable or a two-way bar",
  function(m, c)
    local k = m:kind(c)
    return k == "cable" or k == "bar", string.format("block %d is a %s, not a cable or a bar", c.id, k)
  end,
  function(m, c) m:delete(c) end)

-- Beams ----------------------------------------------------------------------

define("beam", "rule 8: a spline beam through particles",
  function(m, options)
    return options.particles ~= nil and #options.particles >= 2, "needs a list of at least two particles"
  end,
  function(m, options) return m:beam(options) end)

define("grow", "rule 9: grow a spline beam from its end particle to a particle",
  function(m, beam, tip, p)
    local ok, why = kind_is(m, beam, "beam")
    if not ok then return false, why end
    if m:closed(beam) then return false, string.format("beam %d is a ring", beam.id) end
    local ps = m:particles(beam)
    return tip == ps[1] or tip == ps[#ps], string.format("particle %d is not an end of beam %d", tip.id, beam.id)
  end,
  function(m, beam, tip, p) m:extend(beam, tip, p) end)

define("beam_from", "rule 10: a spline beam from a particle, a direction and subdivisions", nil,
  function(m, p, direction, segments, section)
    local options = { from = p, direction = direction, segments = segments }
    for k, v in pairs(section) do options[k] = v end
    return m:beam(options)
  end)

define("remove_simple", "rule 11: delete a simple particle of a beam",
  function(m, p)
    local ok, why = state_is(m, p, "simple")
    if not ok then return false, why end
    return on_beam(m, p) ~= nil, string.format("particle %d is not on a beam", p.id)
  end,
  function(m, p) m:remove_from_beam(p) end)

define("remove_shared", "rule 12: delete a shared particle of a beam",
  function(m, p, beam)
    local ok, why = state_is(m, p, "shared")
    if not ok then return false, why end
    return kind_is(m, beam, "beam")
  end,
  function(m, p, beam)
    local q = m:explode_from(p, beam)   -- rule 5, then rule 11 on the beam's copy
    m:remove_from_beam(q)
  end)

define("insert", "rule 13: add a particle between two consecutive beam particles", nil,
  function(m, a, b) return m:insert(a, b) end)

define("subdivide", "rule 14: subdivide a spline beam",
  function(m, beam) return kind_is(m, beam, "beam") end,
  function(m, beam)
    local ps = m:particles(beam)
    for i = 1, #ps - 1 do m:insert(ps[i], ps[i + 1]) end
    if m:closed(beam) then m:insert(ps[#ps], ps[1]) end
  end)

define("unsubdivide", "rule 15: inverse subdivision of a spline beam",
  function(m, beam)
    local ok, why = kind_is(m, beam, "beam")
    if not ok then return false, why end
    local ps = m:particles(beam)
    for i = 2, #ps - 1, 2 do
      if m:state(ps[i]) ~= "simple" then return false, string.format("particle %d is %s", ps[i].id, m:state(ps[i])) end
    end
    return #ps >= 3, "the beam has no interior particle"
  end,
  function(m, beam)
    local ps = m:particles(beam)
    for i = 2, #ps - 1, 2 do m:remove_from_beam(ps[i]) end
  end)

-- Whether p is a particle of the beam where it can break (not an open end).
local function interior_of(m, beam, p)
  local ps = m:particles(beam)
  for i, x in ipairs(ps) do
    if x == p then
      return m:closed(beam) or (i > 1 and i < #ps), string.format("particle %d is an end of beam %d", p.id, beam.id)
    end
  end
  return false, string.format("particle %d is not on beam %d", p.id, beam.id)
end

define("break_simple", "rule 16: break a spline beam on a simple particle",
  function(m, beam, p)
    local ok, why = kind_is(m, beam, "beam")
    if not ok then return false, why end
    ok, why = state_is(m, p, "simple")
    if not ok then return false, why end
    return interior_of(m, beam, p)
  end,
  function(m, beam, p) return m:split(beam, p) end)

define("break_shared", "rule 17: break a spline beam on a shared particle",
  function(m, beam, p)
    local ok, why = kind_is(m, beam, "beam")
    if not ok then return false, why end
    ok, why = state_is(m, p, "shared")
    if not ok then return false, why end
    return interior_of(m, beam, p)
  end,
  function(m, beam, p)
    local copy = m:explode_from(p, beam)   -- rule 5, then rule 16 at the beam's copy
    return m:split(beam, copy)
  end)

define("delete_beam", "rule 18: delete a spline beam",
  function(m, beam) return kind_is(m, beam, "beam") end,
  function(m, beam) m:delete(beam) end)

define("ring", "ring: a closed spline beam from a centre, a plane normal, a radius and segments (thesis 6.3.2)",
  function(m, options)
    return type(options) == "table" and options.centre ~= nil,
      "needs the options of m:beam with 'centre', 'normal', 'radius' and 'segments'"
  end,
  function(m, options) return m:beam(options) end)

-- Looped typologies (thesis fig. 6.10): a beam connected to itself --------------

local function open_beam(m, beam, at_least)
  local ok, why = kind_is(m, beam, "beam")
  if not ok then return false, why end
  if m:closed(beam) then return false, string.format("beam %d is already a ring", beam.id) end
  local n = #m:particles(beam)
  return n >= at_least, string.format("beam %d has %d particles, needs %d", beam.id, n, at_least)
end

define("ring_loop", "closed ring: first two particles onto the last two, ascending",
  function(m, beam) return open_beam(m, beam, 5) end,
  function(m, beam)
    local ps = m:particles(beam)
    local n = #ps
    return m:merge{ ps[1], ps[n - 1] }, m:merge{ ps[2], ps[n] }
  end)

define("drop_single", "drop-like loop with a single joint: both ends together",
  function(m, beam) return open_beam(m, beam, 4) end,
  function(m, beam)
    local ps = m:particles(beam)
    return m:merge{ ps[1], ps[#ps] }
  end)

define("drop_double", "drop-like loop with a double joint: first two onto the last two, inverse",
  function(m, beam) return open_beam(m, beam, 6) end,
  function(m, beam)
    local ps = m:particles(beam)
    local n = #ps
    return m:merge{ ps[1], ps[n] }, m:merge{ ps[2], ps[n - 1] }
  end)

-- Tensile patches (thesis 4.2.7.4, meshing/; see docs/meshing.md) ------------
-- Each takes the options table of the model method it wraps and returns the
-- new patch. The boundary particles become shared, the new ones are simple.

local function particle_list(options, key)
  if type(options) ~= "table" or type(options[key]) ~= "table" then
    return nil, string.format("needs options with '%s', a list of particles", key)
  end
  return options[key]
end

local function at_least(options, key, n)
  local ps, why = particle_list(options, key)
  if not ps then return false, why end
  return #ps >= n, string.format("'%s' has %d particles, needs at least %d", key, #ps, n)
end

local function two_sequences(options, least)
  local a, why = particle_list(options, "from")
  if not a then return false, why end
  local b, why_b = particle_list(options, "to")
  if not b then return false, why_b end
  if #a ~= #b then return false, string.format("'from' has %d particles and 'to' %d", #a, #b) end
  return #a >= least, string.format("each sequence has %d particles, needs at least %d", #a, least)
end

define("patch_subdivision", "rule 19: a tensile patch from particles by Catmull-Clark subdivision",
  function(m, options) return at_least(options, "particles", 3) end,
  function(m, options) return m:catmull_clark(options) end)

define("patch_paving", "rule 20: a tensile patch from particles by paving",
  function(m, options) return at_least(options, "particles", 8) end,
  function(m, options) return m:pave(options) end)

define("patch_projection", "rule 21: a tensile patch between two particle sequences by projection",
  function(m, options) return two_sequences(options, 2) end,
  function(m, options) return m:project(options) end)

-- Rule 22 (thesis fig. 4.39): { between = { p1, p2 }, rows =, rings =, EA = ... }
-- cuts the neighbourhoods of two simple particles out of their patches and
-- joins the two rims with a tube (m:tube); the production checks that the
-- neighbourhoods are equivalent (rims of equal length) and disjoint. The
-- older form { from = ring1, to = ring2, ... } joins two given rings.
define("patch_tube", "rule 22: a tube between two patches' interiors",
  function(m, options)
    if type(options) == "table" and options.between ~= nil then
      local ps, why = particle_list(options, "between")
      if not ps then return false, why end
      if #ps ~= 2 then return false, string.format("'between' has %d particles, needs 2", #ps) end
      for _, p in ipairs(ps) do
        local ok, why_state = state_is(m, p, "simple")
        if not ok then return false, why_state end
        if on_patch(m, p) == nil then return false, string.format("particle %d is not on a patch", p.id) end
      end
      return true
    end
    return two_sequences(options, 3)
  end,
  function(m, options)
    if options.between ~= nil then return m:tube(options) end
    local tube = {}
    for k, v in pairs(options) do tube[k] = v end
    tube.closed = true
    return m:project(tube)
  end)

-- The finer patch reuses every particle of the old one, which goes (rule 27).
define("patch_refine", "rule 25: subdivide a tensile patch by Catmull-Clark",
  function(m, patch) return kind_is(m, patch, "patch") end,
  function(m, patch, section)
    local finer = m:subdivide_patch(patch, section)
    m:delete(patch)
    return finer
  end)

define("patch_remove_simple", "rule 23: delete a simple particle of a tensile patch and its quads",
  function(m, p)
    local ok, why = state_is(m, p, "simple")
    if not ok then return false, why end
    return on_patch(m, p) ~= nil, string.format("particle %d is not on a patch", p.id)
  end,
  function(m, p) m:remove_from_patch(p) end)

define("patch_remove_shared", "rule 24: delete a shared particle of a tensile patch",
  function(m, p, patch)
    local ok, why = state_is(m, p, "shared")
    if not ok then return false, why end
    ok, why = kind_is(m, patch, "patch")
    if not ok then return false, why end
    for _, b in ipairs(m:blocks(p)) do
      if b == patch then return true end
    end
    return false, string.format("particle %d is not on patch %d", p.id, patch.id)
  end,
  function(m, p, patch)
    local q = m:explode_from(p, patch)   -- rule 5, then rule 23 on the patch's copy
    m:remove_from_patch(q)
  end)

define("patch_merge", "rule 26: merge two tensile patches along their common particles",
  function(m, a, b)
    local ok, why = kind_is(m, a, "patch")
    if not ok then return false, why end
    ok, why = kind_is(m, b, "patch")
    if not ok then return false, why end
    local mine = {}
    for _, p in ipairs(m:particles(a)) do mine[p.id] = true end
    for _, p in ipairs(m:particles(b)) do
      if mine[p.id] then return true end
    end
    return false, string.format("patches %d and %d share no particle", a.id, b.id)
  end,
  function(m, a, b) return m:merge_patches(a, b) end)

define("patch_delete", "rule 27: delete a tensile patch",
  function(m, patch) return kind_is(m, patch, "patch") end,
  function(m, patch) m:delete(patch) end)

-- Multi-resolution tensile patches (thesis 5.5.2.3; docs/meshing.md) ---------

define("multires", "multi-resolution: a coarse patch with its fine patch, fine particles passive",
  function(m, patch, options) return kind_is(m, patch, "patch") end,
  function(m, patch, options) return m:multires(patch, options) end)

local function multires_in(mr, coarse)
  if type(mr) ~= "table" or mr.core == nil then return false, "needs a patch from tendril.rules.multires" end
  if mr.is_coarse ~= coarse then return false, coarse and "the patch is fine" or "the patch is coarse" end
  return true
end

define("refine", "multi-resolution: activate the fine particles, drop the coarse links",
  function(m, mr) return multires_in(mr, true) end,
  function(m, mr) m:refine(mr) end)

define("coarsen", "multi-resolution: fine particles passive again, coarse links back",
  function(m, mr) return multires_in(mr, false) end,
  function(m, mr) m:coarsen(mr) end)

tendril.rules = rules

-- tendril.report(m, extra): m:summary() and the extra fields as one CSV row
-- (with its header) in the run's output directory: what `tendril sweep`
-- collects from every run.
function tendril.report(m, extra)
  local row = m:summary()
  for k, v in pairs(extra or {}) do row[k] = v end
  local keys = {}
  for k in pairs(row) do keys[#keys + 1] = k end
  table.sort(keys)
  local values = {}
  for i, k in ipairs(keys) do
    local v = row[k]
    values[i] = type(v) == "number" and string.format("%.10g", v) or tostring(v)
  end
  -- Called through pcall, the error has no place of its own: it takes the scene's.
  local ok, err = pcall(tendril.write_file, tendril.out("summary.csv"),
                        tendril.csv_line(keys) .. "\n" .. tendril.csv_line(values) .. "\n")
  if not ok then error("tendril.report: " .. err, 2) end
end
