-- Flocking parents (thesis 5.5.1, fig. 5.20-5.21; Reynolds 1987): parent
-- particles steer through space — seeking targets, avoiding obstacles,
-- keeping apart from, aligned with and close to other parents — and drop a
-- child every `spacing` metres. A parent's children become a spline beam as
-- soon as there are three (rule 9) while the parent, tied to the last child
-- by a tether cable, keeps flocking; the first and last child are pinned.
local agents = tendril.agents
local vec = agents.vec

local Flock = {}
Flock.__index = Flock

local defaults = {
  max_speed = 0.05,     -- m per step
  max_force = 0.01,     -- m per step^2
  perception = 1.0,     -- m: parents closer than this flock together
  separation = 0.5,     -- m: parents closer than this push apart
  weights = { seek = 1.0, avoid = 3.0, separation = 1.5, alignment = 0.5, cohesion = 0.3 },
  spacing = 0.25,       -- m between children
  every = 0,            -- steps between children instead (when > 0)
  children = 20,        -- per parent (option name; stored as per_parent)
  reach = 0.3,          -- m: a target this close counts as reached
  tether = { EA = 1e4 },
}

-- options: model, parents = { {position = {x,y,z}, velocity = {..}, targets = {{..}, ..}}, ... },
-- obstacles = { {centre = {..}, radius = r}, ... }, section = beam section
-- (EA, EI or E, A, I), and any key of `defaults`.
function agents.flock(options)
  local m = assert(options.model, "flock: 'model' is required")
  assert(options.section, "flock: 'section' (the children's beam section) is required")
  local self = setmetatable({ model = m, section = options.section, obstacles = options.obstacles or {},
                              parents = {} }, Flock)
  for k, v in pairs(defaults) do self[k] = options[k] or v end
  self.per_parent, self.children = self.children, nil  -- `children` is a method
  assert(self.per_parent >= 3, "flock: 'children' must be at least 3 (a beam needs three particles)")
  for i, spec in ipairs(assert(options.parents, "flock: 'parents' is required")) do
    local p = m:particle(spec.position)
    m:role(p, "parent")
    m:lock(p, "all")  -- moved by its steering, never by the solver
    self.parents[i] = { particle = p, velocity = spec.velocity or { 0, 0, 0 }, targets = spec.targets or {},
                        target = 1, travelled = 0, children = {}, beam = nil, tether = nil, done = false }
  end
  self.rule = tendril.rule{ name = "flock", production = function(model) self:step() end }
  return self
end

function Flock:done()
  for _, a in ipairs(self.parents) do
    if not a.done then return false end
  end
  return true
end

-- All children of all parents, with the index of their parent.
function Flock:children()
  local out = {}
  for i, a in ipairs(self.parents) do
    for k, c in ipairs(a.children) do out[#out + 1] = { particle = c, parent = i, index = k } end
  end
  return out
end

function Flock:steering(i)
  local m, a = self.model, self.parents[i]
  local x = m:position(a.particle)
  local w = self.weights
  local force = { 0, 0, 0 }
  -- Seek the current target; move on when it is reached.
  local target = a.targets[a.target]
  if target and vec.distance(x, target) < self.reach and a.target < #a.targets then
    a.target = a.target + 1
    target = a.targets[a.target]
  end
  if target then
    local desired = vec.scale(vec.normalize(vec.sub(target, x)), self.max_speed)
    force = vec.add(force, vec.scale(vec.sub(desired, a.velocity), w.seek))
  end
  -- Avoid obstacles: push away from any sphere we are about to enter.
  for _, o in ipairs(self.obstacles) do
    local away = vec.sub(x, o.centre)
    local gap = vec.length(away) - o.radius
    if gap < self.perception then
      force = vec.add(force, vec.scale(vec.normalize(away), w.avoid * self.max_force * (1 - gap / self.perception)))
    end
  end
  -- Separation, alignment and cohesion among the other parents.
  local sep, align, centre, n = { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 }, 0
  for j, b in ipairs(self.parents) do
    if j ~= i and not b.done then
      local y = m:position(b.particle)
      local d = vec.distance(x, y)
      if d < self.perception then
        n = n + 1
        align = vec.add(align, b.velocity)
        centre = vec.add(centre, y)
        if d < self.separation and d > 0 then sep = vec.add(sep, vec.scale(vec.normalize(vec.sub(x, y)), 1 / d)) end
      end
    end
  end
  if n > 0 then
    force = vec.add(force, vec.scale(vec.limit(sep, self.max_force), w.separation))
    local mean_v = vec.scale(align, 1 / n)
    force = vec.add(force, vec.scale(vec.limit(vec.sub(mean_v, a.velocity), self.max_force), w.alignment))
    local to_centre = vec.sub(vec.scale(centre, 1 / n), x)
    force = vec.add(force, vec.scale(vec.limit(to_centre, self.max_force), w.cohesion))
  end
  return vec.limit(force, self.max_force)
end

function Flock:drop(a)
  local m = self.model
  local c = m:particle(m:position(a.particle))
  m:role(c, "child")
  local n = #a.children + 1
  a.children[n] = c
  if n == 1 then m:lock(c, "all") end            -- the first child is pinned
  if n == 3 then                                  -- three children: a beam (rule 9)
    local options = { particles = { a.children[1], a.children[2], c } }
    for k, v in pairs(self.section) do options[k] = v end
    a.beam = m:beam(options)
  elseif n > 3 then
    m:extend(a.beam, a.children[n - 1], c)
  end
  -- The tether moves to the new last child once the beam exists; deleting
  -- the old one after tying the new keeps the parent alive (rule 7 deletes
  -- particles left isolated).
  local old = a.tether
  a.tether = nil
  if n >= self.per_parent then                       -- the last child is pinned; the parent retires
    m:lock(c, "all")
    a.done = true
  elseif n >= 3 then
    a.tether = m:cable(a.particle, c, { EA = self.tether.EA, rest_length = self.spacing / 4 })
  end
  if old then m:delete(old) end                    -- at retirement this deletes the parent too
  if a.done and not old then m:delete_particle(a.particle) end
end

function Flock:step()
  local m = self.model
  local forces = {}
  for i, a in ipairs(self.parents) do
    if not a.done then forces[i] = self:steering(i) end
  end
  for i, a in ipairs(self.parents) do
    if not a.done then
      a.velocity = vec.limit(vec.add(a.velocity, forces[i]), self.max_speed)
      m:set_position(a.particle, vec.add(m:position(a.particle), a.velocity))
      a.travelled = a.travelled + vec.length(a.velocity)
      a.steps = (a.steps or 0) + 1
      local due = self.every > 0 and a.steps >= self.every or self.every <= 0 and a.travelled >= self.spacing
      if #a.children == 0 or due then
        a.steps = 0
        a.travelled = 0
        self:drop(a)
      end
    end
  end
end
