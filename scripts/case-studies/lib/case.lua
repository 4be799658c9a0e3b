-- What every case study scene shares (docs/case-studies.md): the quick or
-- full variant, GFRP and bamboo sections, figures measured on the model
-- (envelope, bending stress), the table beside the thesis' numbers, and the
-- outputs of a full run. A scene requires it as require("lib.case").
local case = {}

-- --param full=1 runs the full variant: the thesis' resolution and
-- tolerances. The quick variant (the default, what the test suite runs) is
-- coarser; both assert the same figures and write the same outputs.
function case.variant()
  local full = tendril.param("full", 0) ~= 0
  return { full = full, quick = not full }
end

-- Materials as the thesis gives them (E) and as their makers state them
-- (density, characteristic bending strength); each scene says which it uses.
case.gfrp = { E = 25e9, G = 12.5e9, density = 1900, strength = 400e6, name = "GFRP (pultruded)" }

-- A solid circular rod of diameter d [m]: E, A, I and the line mass of m:beam.
function case.rod(material, d)
  local A, I = math.pi * d^2 / 4, math.pi * d^4 / 64
  return { E = material.E, A = A, I = I, line_mass = material.density * A, c = d / 2, d = d, material = material }
end

-- A bundle of n circular tubes (outer diameter d, wall t) bending together
-- about one axis (thesis 6.3.2: four GFRP tubes bundled).
function case.tubes(material, d, t, n)
  local di = d - 2 * t
  local A, I = math.pi * (d^2 - di^2) / 4, math.pi * (d^4 - di^4) / 64
  return { E = material.E, A = n * A, I = n * I, line_mass = n * material.density * A, c = d / 2, d = d,
           material = material }
end

-- The options of m:beam for a section, plus any extra keys.
function case.beam_options(section, extra)
  local o = { E = section.E, A = section.A, I = section.I, line_mass = section.line_mass }
  for k, v in pairs(extra or {}) do o[k] = v end
  return o
end

-- Vectors {x, y, z}: a - b, a x b, a / |a|.
function case.sub(a, b) return { a[1] - b[1], a[2] - b[2], a[3] - b[3] } end
function case.cross(a, b) return { a[2] * b[3] - a[3] * b[2], a[3] * b[1] - a[1] * b[3], a[1] * b[2] - a[2] * b[1] } end
function case.unit(a)
  local l = math.sqrt(a[1]^2 + a[2]^2 + a[3]^2)
  return { a[1] / l, a[2] / l, a[3] / l }
end

-- The distance between two points {x, y, z}.
function case.distance(x, y)
  return math.sqrt((x[1] - y[1])^2 + (x[2] - y[2])^2 + (x[3] - y[3])^2)
end

-- The bending radius at the middle of three consecutive positions (the
-- circle through them; math.huge on a straight line).
function case.radius(x, y, z)
  local a = { y[1] - x[1], y[2] - x[2], y[3] - x[3] }
  local b = { z[1] - y[1], z[2] - y[2], z[3] - y[3] }
  local c = { z[1] - x[1], z[2] - x[2], z[3] - x[3] }
  local cx = a[2] * b[3] - a[3] * b[2]
  local cy = a[3] * b[1] - a[1] * b[3]
  local cz = a[1] * b[2] - a[2] * b[1]
  local la, lb = math.sqrt(a[1]^2 + a[2]^2 + a[3]^2), math.sqrt(b[1]^2 + b[2]^2 + b[3]^2)
  local sin = math.sqrt(cx^2 + cy^2 + cz^2) / (la * lb)
  if sin <= 0 then return math.huge end
  return math.sqrt(c[1]^2 + c[2]^2 + c[3]^2) / (2 * sin)
end

-- The smallest bending radius along a beam and the bending stress it
-- causes at the section's extreme fibre, E c / R (axial stress is small in
-- a bending-active rod; it is left out and said so in the table), and the
-- particle where it is. skip(p), if given, leaves particles out (supports).
function case.bending(m, beam, section, skip)
  local ps = m:particles(beam)
  local n = #ps
  local closed = m:closed(beam)
  local r_min, at = math.huge, nil
  local first, last = closed and 1 or 2, closed and n or n - 1
  for i = first, last do
    local a, b, c = ps[(i - 2) % n + 1], ps[i], ps[i % n + 1]
    if not (skip and skip(b)) then
      local r = case.radius(m:position(a), m:position(b), m:position(c))
      if r < r_min then r_min, at = r, b end
    end
  end
  return r_min, section.E * section.c / r_min, at
end

-- The largest bending stress in a 3-DOF beam from what it carries: the
-- largest |moment| of m:forces over its vertices divided by W [m3] (the
-- section's elastic modulus; for a bundle of n members bending together, n
-- times one member's), and the particle where it is. skip(p) as above.
function case.moment_stress(m, beam, W, skip)
  local moment, at = 0, nil
  for _, v in ipairs(m:forces(beam).vertices) do
    if not (skip and skip(v.particle)) and math.abs(v.moment) > moment then moment, at = math.abs(v.moment), v.particle end
  end
  return moment / W, moment, at
end

-- The elastic energy [J] a block stores now, from what it carries
-- (m:forces): bending at a beam's vertices, 1/2 M kappa over half of the
-- two segments beside each; axial in bars, cables and patch edges,
-- prestress times length (the work of a geometric tension, thesis eq. 3.32)
-- plus 1/2 EA strain^2 L0 as 1/2 (N - prestress) strain L0. The section
-- {EA =, prestress =} is what the block was made with.
function case.energy(m, block, section)
  local f, energy = m:forces(block), 0
  local ps = m:particles(block)
  if f.vertices then
    local where, n, closed = {}, #ps, m:closed(block)
    for i, p in ipairs(ps) do where[p.id] = i end
    for _, v in ipairs(f.vertices) do
      local i = where[v.particle.id]
      local a, c = ps[(i - 2) % n + 1], ps[i % n + 1]
      if closed or (i > 1 and i < n) then
        local l = 0.5 * (case.distance(m:position(a), m:position(v.particle)) + case.distance(m:position(v.particle), m:position(c)))
        energy = energy + 0.5 * v.moment * v.curvature * l
      end
    end
  end
  local prestress = section and section.prestress or 0
  for _, s in ipairs(f.segments or {}) do
    if not s.slack then
      local L = case.distance(m:position(s.a), m:position(s.b))
      local L0 = L / (1 + s.strain)
      energy = energy + prestress * L + 0.5 * (s.axial - prestress) * s.strain * L0
    end
  end
  return energy
end

-- The bounding box of some particles (all by default): its extent in x and
-- y, its height above the lowest point, and its lowest and highest z.
function case.envelope(m, ps)
  local lo, hi = { math.huge, math.huge, math.huge }, { -math.huge, -math.huge, -math.huge }
  for _, p in ipairs(ps or m:particles()) do
    local x = m:position(p)
    for k = 1, 3 do
      lo[k] = math.min(lo[k], x[k])
      hi[k] = math.max(hi[k], x[k])
    end
  end
  return { x = hi[1] - lo[1], y = hi[2] - lo[2], height = hi[3] - lo[3], top = hi[3], bottom = lo[3], lo = lo, hi = hi }
end

-- Area of a patch: the sum of its quads split along a diagonal.
function case.area(m, quads)
  local total = 0
  for _, q in ipairs(quads) do
    for _, t in ipairs{ { q[1], q[2], q[3] }, { q[1], q[3], q[4] } } do
      local a, b, c = m:position(t[1]), m:position(t[2]), m:position(t[3])
      local u = { b[1] - a[1], b[2] - a[2], b[3] - a[3] }
      local v = { c[1] - a[1], c[2] - a[2], c[3] - a[3] }
      total = total + 0.5 * math.sqrt((u[2] * v[3] - u[3] * v[2])^2 + (u[3] * v[1] - u[1] * v[3])^2 + (u[1] * v[2] - u[2] * v[1])^2)
    end
  end
  return total
end

-- A run to equilibrium that must converge: the scene stops, naming the
-- stage, if it does not.
function case.settle(m, stage, options)
  local r = m:run(options or { tolerance = 1e-3, max_steps = 400000 })
  if not r.converged then
    error(string.format("%s: no equilibrium after %d steps (residual %.3g N)", stage, r.steps, r.residual), 2)
  end
  return r
end

-- The table of figures beside the thesis' numbers. rows: { {figure, value,
-- unit, thesis (number, string or nil), note}, ... }. Returns the markdown.
function case.table(title, rows)
  local out = { "| figure | tendril | thesis | note |", "|---|---:|---:|---|" }
  local function show(v, unit)
    if v == nil then return "—" end
    if type(v) == "number" then
      local s = math.abs(v) >= 100 and string.format("%.0f", v) or string.format("%.3g", v)
      return unit and unit ~= "" and s .. " " .. unit or s
    end
    return tostring(v)
  end
  for _, r in ipairs(rows) do
    out[#out + 1] = string.format("| %s | %s | %s | %s |", r[1], show(r[2], r[3]), show(r[4], r[3]), r[5] or "")
  end
  local text = table.concat(out, "\n")
  print("\n" .. title .. "\n\n" .. text .. "\n")
  return text
end

-- The outputs of a run, in --out: the model database, journal, assembly
-- sequence (assembly.tsv, m:assembly()), OBJ, the
-- table (NAME.md), summary.csv (the figures, for sweeps) and view.json (the
-- side tools/gallery.mjs draws the model from: {direction = {x, y, z}}).
function case.write(m, name, table_text, figures, view)
  m:save(tendril.out(name .. ".xml"))
  m:save_journal(tendril.out("journal.txt"))
  tendril.write_file(tendril.out("assembly.tsv"), m:assembly())
  m:save_obj(tendril.out(name .. ".obj"))
  tendril.write_file(tendril.out(name .. ".md"), table_text .. "\n")
  tendril.report(m, figures)
  if view then
    local d = view.direction
    tendril.write_file(tendril.out("view.json"), string.format('{"direction": [%g, %g, %g], "zoom": %g}\n',
                                                                d[1], d[2], d[3], view.zoom or 1))
  end
end

-- Asserts a figure of the quick variant with its tolerance, saying what it
-- measured when it fails.
function case.expect(what, value, low, high)
  if not (value >= low and value <= high) then
    error(string.format("%s = %.6g, expected between %.6g and %.6g", what, value, low, high), 2)
  end
end

return case
