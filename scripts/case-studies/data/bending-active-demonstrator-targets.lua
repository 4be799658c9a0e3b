-- The Bending-Active Demonstrator's rough strip targets (thesis 6.1.2: the
-- designers sculpted each strip in Maya and Rhino, a structured quad mesh
-- that is not developable), as the OBJ files its scene imports:
-- bending-active-demonstrator-12.obj (the quick variant, 12 quads along a
-- strip) and -32.obj (the full one), 2 quads across, 0.3 m wide.
-- A strip's centre line is the parabola through its two feet and the joint
-- where it crosses the others (at its middle); its width turns about the
-- centre line from twist0 to twist1 [rad]. Each strip is a group (A1-A3,
-- B1-B2: assembly A, three strips over one joint 5.4 m up; B, two over one
-- 3.2 m up), its vertices row by row, its quads row by row; the joints are
-- the first two vertices, shared by the strips that cross there.
-- Run as a test (every scene under scripts/ is one), it checks that the
-- files beside it are what it draws. To change the targets, edit it and run
--   tendril run scripts/case-studies/data/bending-active-demonstrator-targets.lua --param write=1
local here = debug.getinfo(1, "S").source:match("^@(.*)/") or "."
package.path = here .. "/../?.lua;" .. package.path
local case = require("lib.case")
local sub, cross, unit = case.sub, case.cross, case.unit
local function lerp(a, b, t) return { a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2]), a[3] + t * (b[3] - a[3]) } end
local across, width = 2, 0.3

local function rough(along, foot0, joint, foot1, twist0, twist1)
  local control = { 2 * joint[1] - 0.5 * (foot0[1] + foot1[1]), 2 * joint[2] - 0.5 * (foot0[2] + foot1[2]),
                    2 * joint[3] - 0.5 * (foot0[3] + foot1[3]) }
  local grid = {}
  for r = 0, across do grid[r + 1] = {} end
  for c = 0, along do
    local s = c / along
    local x = lerp(lerp(foot0, control, s), lerp(control, foot1, s), s)
    local tangent = unit(sub(lerp(control, foot1, s), lerp(foot0, control, s)))
    local side = unit(cross({ 0, 0, 1 }, tangent))                -- horizontal, across the arch
    local up = cross(tangent, side)
    local phi = twist0 + s * (twist1 - twist0)
    local w = { math.cos(phi) * side[1] + math.sin(phi) * up[1], math.cos(phi) * side[2] + math.sin(phi) * up[2],
                math.cos(phi) * side[3] + math.sin(phi) * up[3] }
    for r = 0, across do
      local o = (r / across - 0.5) * width
      grid[r + 1][c + 1] = { x[1] + o * w[1], x[2] + o * w[2], x[3] + o * w[3] }
    end
  end
  return grid
end

-- Feet on the ground z = 0.
local designs = {
  { assembly = "A", feet = { { 0.0, 0.4, 0 }, { 5.2, 4.9, 0 } }, joint = { 2.6, 2.6, 5.4 }, twist = { -0.6, 0.8 } },
  { assembly = "A", feet = { { 0.2, 4.6, 0 }, { 4.8, 0.2, 0 } }, joint = { 2.6, 2.6, 5.4 }, twist = { 0.7, -0.5 } },
  { assembly = "A", feet = { { 0.0, 2.5, 0 }, { 5.4, 2.8, 0 } }, joint = { 2.6, 2.6, 5.4 }, twist = { 0.3, -0.3 } },
  { assembly = "B", feet = { { 5.6, 0.0, 0 }, { 7.7, 5.4, 0 } }, joint = { 6.7, 2.7, 3.2 }, twist = { 0.2, -0.2 } },
  { assembly = "B", feet = { { 7.7, 0.3, 0 }, { 5.6, 5.1, 0 } }, joint = { 6.7, 2.7, 3.2 }, twist = { -0.3, 0.3 } },
}

local function obj(along)
  local lines = { string.format("# Bending-Active Demonstrator (thesis 6.1): rough strip targets, %d x %d quads each", along, across),
                  "# drawn by bending-active-demonstrator-targets.lua" }
  local joint_vertex = {}
  for _, d in ipairs(designs) do
    if not joint_vertex[d.assembly] then
      lines[#lines + 1] = string.format("v %.17g %.17g %.17g", d.joint[1], d.joint[2], d.joint[3])
      joint_vertex[d.assembly] = #lines - 2
    end
  end
  local vertices, count = {}, 2
  local named = {}
  for _, d in ipairs(designs) do
    named[d.assembly] = (named[d.assembly] or 0) + 1
    lines[#lines + 1] = "o " .. d.assembly .. named[d.assembly]
    local target = rough(along, d.feet[1], d.joint, d.feet[2], d.twist[1], d.twist[2])
    local index = {}
    for r, row in ipairs(target) do
      index[r] = {}
      for c, x in ipairs(row) do
        if r == across / 2 + 1 and c == along / 2 + 1 then
          index[r][c] = joint_vertex[d.assembly]
        else
          count = count + 1
          index[r][c] = count
          lines[#lines + 1] = string.format("v %.17g %.17g %.17g", x[1], x[2], x[3])
        end
      end
    end
    for r = 1, across do
      for c = 1, along do
        lines[#lines + 1] = string.format("f %d %d %d %d", index[r][c], index[r][c + 1], index[r + 1][c + 1], index[r + 1][c])
      end
    end
  end
  return table.concat(lines, "\n") .. "\n"
end

for _, along in ipairs{ 12, 32 } do
  local name = string.format("%s/bending-active-demonstrator-%d.obj", here, along)
  local text = obj(along)
  if tendril.param("write", 0) == 1 then
    tendril.write_file(name, text)
    print("wrote " .. name)
  else
    local file = assert(io.open(name, "rb"))
    local kept = file:read("a")
    file:close()
    assert(kept == text, name .. " is not what this scene draws: run it with --param write=1")
    print(name .. ": as drawn")
  end
end
