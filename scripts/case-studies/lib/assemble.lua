-- Assembly by hand, as a designer does it in the studio (thesis 6.2): drag a
-- rod's end to where it should connect (a goal, as the studio's drag),
-- connect it there (rule 3), let go, and keep every equilibrium of the
-- sequence. Each operation is a rule application, so the journal is the
-- assembly sequence.
local assemble = {}

local R = tendril.rules

-- A new sequence on model m: settle options for every equilibrium, the
-- goals' weight [N/m] while dragging.
function assemble.new(m, options)
  return setmetatable({ m = m, steps = {}, settle = options.settle, weight = options.weight or 1e4 },
                      { __index = assemble })
end

-- Runs to equilibrium; the scene stops, naming the stage, if it cannot.
function assemble:relax(stage)
  local r = self.m:run(self.settle)
  if not r.converged then
    error(string.format("%s: no equilibrium after %d steps (residual %.3g N)", stage, r.steps, r.residual), 2)
  end
  return r
end

-- Drags particles to targets (pairs {p, q}: p towards q's position, or
-- {p, {x, y, z}}) on goals, relaxes, and lets go.
function assemble:drag(pairs, stage)
  local m, goals = self.m, {}
  for _, pq in ipairs(pairs) do
    local to = type(pq[2]) == "table" and pq[2].id == nil and pq[2] or m:position(pq[2])
    goals[#goals + 1] = m:anchor(pq[1], to, self.weight)
  end
  self:relax(stage .. ": dragging")
  for k = #goals, 1, -1 do m:remove_goal(goals[k]) end
end

-- Connects each pair {p, q} by rule 3; returns the merged particles.
function assemble:connect(pairs, stage)
  local out = {}
  for _, pq in ipairs(pairs) do
    local ok, joint = self.m:apply(R.merge, { pq[1], pq[2] })
    if not ok then error(stage .. ": " .. joint, 2) end
    out[#out + 1] = joint
  end
  return out
end

-- Drag, connect, relax: one step of the assembly. `record` is called on the
-- equilibrium and its result kept with the stage's name.
function assemble:step(stage, pairs, record)
  self:drag(pairs, stage)
  local joints = self:connect(pairs, stage)
  local r = self:relax(stage)
  self:keep(stage, r, record)
  return joints
end

-- Drags a particle to a point and pins it there (a support on the floor),
-- then relaxes: one step of the assembly.
function assemble:support(stage, p, point, axes, record)
  self:drag({ { p, point } }, stage)
  self.m:set_position(p, point)
  self.m:lock(p, axes or "xyz")
  self:keep(stage, self:relax(stage), record)
end

-- Keeps the equilibrium just reached as a step of the sequence.
function assemble:keep(stage, r, record)
  local entry = { stage = stage, at = self.m:steps(), steps = r.steps, residual = r.residual,
                  particles = self.m:count().particles, beams = self.m:count().beams }
  if record then for k, v in pairs(record(self.m)) do entry[k] = v end end
  self.steps[#self.steps + 1] = entry
  return entry
end

-- Reverts a connection (rule 4: every end back where it was relative to
-- the joint) and relaxes.
function assemble:revert(joint, stage, record)
  local ok, parts = self.m:apply(R.explode, joint)
  if not ok then error(stage .. ": " .. parts, 2) end
  self:keep(stage, self:relax(stage), record)
  return parts
end

return assemble
