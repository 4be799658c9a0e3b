-- Thesis 6.5, Self-Choreographic Networks: a network of bent GFRP rods
-- joined by robotic joints, one rotational and one sliding, whose readings
-- arrive as a stream; the model is the structure's digital twin and finds
-- the equilibrium each reading leads to (fig. 6.31).
--
-- The stream is text, one reading per line ('#' starts a comment):
--   rotate J DEGREES   the rotational joint J (m:joint) turns to this angle
--   slide J METRES     the sliding joint J moves its connection this far along its rod
--   relax              the network comes to rest: one equilibrium state of fig. 6.31
-- After each reading the model takes `steps` solver steps (default 40), as a
-- live model does between two sensor messages. --param input=FILE reads a
-- file (default: data/self-choreographic-networks.txt beside this scene) or
-- a named pipe; input=- reads stdin, so a socket is a pipe away:
--   nc -l 7000 | tendril run scripts/case-studies/self-choreographic-networks.lua --param input=-
-- (a joint sends its readings with: printf 'rotate 1 70\nrelax\n' | nc localhost 7000).
--
-- The thesis gives no dimensions for this prototype. Ours: two 4 m rods
-- (d 10 mm) bent into arches over 2.4 m, crossing at their crowns, where the
-- rotational joint sets the angle between them in plan (fig. 6.32); each
-- arch's feet are tied by a cable and stand on rollers (one foot pinned, one
-- on a rail, so the network cannot drift). A third rod (2.6 m, d 8 mm)
-- rises from a pinned foot to the first arch, where a sliding joint moves
-- its connection along the arch (fig. 6.33). 3-DOF beams, Leapfrog.
local case = require("lib.case")
local R = tendril.rules

local variant = case.variant()
local here = debug.getinfo(1, "S").source:match("^@(.*)/") or "."
local input_name = tendril.param("input", here .. "/data/self-choreographic-networks.txt")
local steps_per_reading = tendril.param("steps", 40)
local n = variant.full and 16 or 8              -- segments per arch (even: the crown is a node)

local m = tendril.model{ integrator = "leapfrog" }
m:gravity{ 0, 0, -9.81 }
local arch_section, rod_section = case.rod(case.gfrp, 0.010), case.rod(case.gfrp, 0.008)

-- An arch of 4 m over a span of 2.4 m along `axis`, its points on a sine
-- whose rise gives it that length (at rest straight: bending it is what holds
-- it up), through the shared crown.
local span, length = 2.4, 4.0
local function sine_length(rise)
  local total, last = 0, { -span / 2, 0 }
  for i = 1, 400 do
    local t = i / 400
    local p = { -span / 2 + span * t, rise * math.sin(math.pi * t) }
    total = total + math.sqrt((p[1] - last[1])^2 + (p[2] - last[2])^2)
    last = p
  end
  return total
end
local lo, hi = 0, length
for _ = 1, 60 do
  local mid = (lo + hi) / 2
  if sine_length(mid) < length then lo = mid else hi = mid end
end
local rise = lo
local function arch_points(axis, crown)
  local ps = {}
  for i = 0, n do
    local t = i / n
    local s = -span / 2 + span * t
    local x = axis == "x" and { s, 0, rise * math.sin(math.pi * t) } or { 0, s, rise * math.sin(math.pi * t) }
    ps[#ps + 1] = (i == n / 2 and crown) or m:particle(x)
  end
  return ps
end
local crown = m:particle{ 0, 0, rise }
local ax = arch_points("x", crown)
local ay = arch_points("y", crown)
local ok, arch1 = m:apply(R.beam, case.beam_options(arch_section, { particles = ax }))
local ok2, arch2 = m:apply(R.beam, case.beam_options(arch_section, { particles = ay }))
assert(ok and ok2)
m:lock(ax[2], "y")              -- the first arch's base plates keep it upright
m:lock(ax[n], "y")
for _, p in ipairs{ ax[1], ax[n + 1], ay[1], ay[n + 1] } do m:lock(p, "xyz") end   -- pinned feet
local joint = m:joint(crown, { stiffness = 1e5 * (n / 8)^2 })   -- 90 degrees as built; stiff: a motor

-- The third rod, from a pinned foot up to the first arch at a quarter of its
-- length: 2.6 m of rod over a gap of about 2 m, bowed upwards.
local foot = m:particle{ -1.0, 1.6, 0 }
m:lock(foot, "xyz")
local at = ax[n / 4 + 1]
local x = m:position(at)
local rod_pts = { foot }
local k = variant.full and 12 or 6
for i = 1, k - 1 do
  local t = i / k
  rod_pts[#rod_pts + 1] = m:particle{ -1.0 + t * (x[1] + 1.0), 1.6 + t * (x[2] - 1.6), t * x[3] + 0.5 * math.sin(math.pi * t) }
end
rod_pts[#rod_pts + 1] = at
local ok3, rod = m:apply(R.beam, case.beam_options(rod_section, { particles = rod_pts }))
assert(ok3)
local slider = tendril.agents.sliding_joint{ model = m, beam = arch1, at = at, connection = rod }

local built   -- the crown at the first equilibrium
local function state(label)
  local r = case.settle(m, label, { tolerance = variant.full and 1e-4 or 1e-3, max_steps = 400000 })
  local stress = 0
  for _, b in ipairs{ { arch1, arch_section }, { arch2, arch_section } } do
    local _, s = case.bending(m, b[1], b[2])
    stress = math.max(stress, s)
  end
  local _, rod_stress = case.bending(m, rod, rod_section)
  local c = m:position(crown)
  built = built or c
  return { label = label, steps = r.steps, angle = m:joint_angle(joint), slide = slider:position(), crown = c[3],
           shift = math.sqrt((c[1] - built[1])^2 + (c[2] - built[2])^2), stress = stress, rod_stress = rod_stress }
end

-- The robotic joints as rules: each reading is a production in the journal.
local rotate = tendril.rule{ name = "robotic joint: rotate", production = function(m, j, deg) m:joint_angle(j, deg) end }
local slide = tendril.rule{ name = "robotic joint: slide", production = function(m, ds) slider:slide(ds) end }

local states = { state("as built") }
local targets = { angle = 90, slide = slider:position() }
local input = input_name == "-" and io.stdin or assert(io.open(input_name, "r"))
local readings = 0
for line in input:lines() do
  local words = {}
  for w in line:gsub("#.*", ""):gmatch("%S+") do words[#words + 1] = w end
  if #words > 0 then
    readings = readings + 1
    local what = words[1]
    if what == "rotate" then
      assert(tonumber(words[2]) == 1, "rotate: this network has one rotational joint, 1")
      targets.angle = assert(tonumber(words[3]), "rotate: DEGREES is not a number: " .. line)
      assert(m:apply(rotate, joint, targets.angle))
    elseif what == "slide" then
      assert(tonumber(words[2]) == 1, "slide: this network has one sliding joint, 1")
      local ds = assert(tonumber(words[3]), "slide: METRES is not a number: " .. line)
      targets.slide = targets.slide + ds
      assert(m:apply(slide, ds))
    elseif what == "relax" then
      local s = state(string.format("reading %d", readings))
      s.target_angle, s.target_slide = targets.angle, targets.slide
      states[#states + 1] = s
    else
      error("unknown reading '" .. what .. "' (rotate, slide or relax): " .. line)
    end
    if what ~= "relax" then m:step(steps_per_reading) end
  end
end
if input ~= io.stdin then input:close() end
m:check()

print("equilibrium states (fig. 6.31): reading | joint angle [deg] (target) | connection along arch 1 [m] (target) |")
print("  crown height [m] | crown moved in plan [mm] | largest bending stress in the arches, in the third rod [MPa] | steps")
for _, s in ipairs(states) do
  print(string.format("  %-11s %6.2f (%s) %6.3f (%s) %6.3f %6.1f %7.1f %7.1f %7d", s.label, s.angle,
                      s.target_angle and string.format("%.0f", s.target_angle) or "-", s.slide,
                      s.target_slide and string.format("%.2f", s.target_slide) or "-", s.crown, 1e3 * s.shift,
                      s.stress / 1e6, s.rod_stress / 1e6, s.steps))
end

local last = states[#states]
local worst_stress, worst_angle, worst_slide = 0, 0, 0
for _, s in ipairs(states) do
  worst_stress = math.max(worst_stress, s.stress, s.rod_stress)
  if s.target_angle then
    worst_angle = math.max(worst_angle, math.abs(s.angle - s.target_angle))
    worst_slide = math.max(worst_slide, math.abs(s.slide - s.target_slide))
  end
end
local angles = {}
for _, s in ipairs(states) do angles[#angles + 1] = s.angle end
table.sort(angles)
local rows = {
  { "rods", m:count().beams, "", nil, "two arches and a rod" },
  { "joints", "1 rotational, 1 sliding", "", "rotational and sliding" },
  { "readings", readings, "", nil, input_name == "-" and "from stdin" or "from a file" },
  { "equilibrium states", #states, "", nil, "fig. 6.31" },
  { "joint angles reached", string.format("%.0f-%.0f", angles[1], angles[#angles]), "deg" },
  { "largest miss of a joint angle", worst_angle, "deg", nil, "at rest, against the reading" },
  { "largest miss of the sliding joint", worst_slide, "m", nil, "within 0.1 of a segment" },
  { "crown height, first and last state", string.format("%.3f, %.3f", states[1].crown, last.crown), "m" },
  { "largest bending stress", worst_stress / 1e6, "MPa", nil, "of 400 MPa (assumed)" },
}
local text = case.table("Self-Choreographic Networks (thesis 6.5)", rows)
case.write(m, "scn", text, { states = #states, crown = last.crown, angle = last.angle, slide = last.slide },
           { direction = { 0.9, -1, 0.7 }, zoom = 0.6 })

case.expect("rods", m:count().beams, 3, 3)
case.expect("equilibrium states", #states, 5, 1000)
case.expect("largest miss of a joint angle [deg]", worst_angle, 0, 0.5)
local longest = 0
local a1 = m:particles(arch1)
for i = 1, #a1 - 1 do longest = math.max(longest, m:rest_length(a1[i], a1[i + 1])) end
case.expect("largest miss of the sliding joint [m]", worst_slide, 0, slider.fraction * longest + 1e-9)
case.expect("utilisation", worst_stress / case.gfrp.strength, 0, 1)
