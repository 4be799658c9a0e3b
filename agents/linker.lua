-- Tensile linkers (thesis 5.5.1, fig. 5.21b): a child of one parent ties a
-- cable (rule 6) to a child of another parent within `distance`, when the
-- link lies within `view` degrees of the plane normal to the child's beam
-- (links run across the beams, not along them), up to `max_links` cables per
-- particle.
local agents = tendril.agents
local vec = agents.vec

local Linker = {}
Linker.__index = Linker

-- options: model, flock (from agents.flock), distance [m], view [deg],
-- max_links, section (cable: EA, prestress...), shrink (rest length as a
-- fraction of the gap, default 1: the cable ties, 0.9 pulls).
function agents.linker(options)
  local self = setmetatable({
    model = assert(options.model, "linker: 'model' is required"),
    flock = assert(options.flock, "linker: 'flock' is required"),
    distance = options.distance or 1.0,
    view = options.view or 45,
    max_links = options.max_links or 2,
    section = options.section or { EA = 1e4 },
    shrink = options.shrink or 1.0,
    links = {},   -- particle id -> number of cables
    linked = {},  -- "a:b" -> true
    cables = 0,
  }, Linker)
  self.rule = tendril.rule{ name = "link children", production = function(model) return self:step() end }
  return self
end

-- The beam's direction at a child, from its neighbours along the beam.
local function tangent(m, a, k)
  local prev, next = a.children[math.max(1, k - 1)], a.children[math.min(#a.children, k + 1)]
  return vec.normalize(vec.sub(m:position(next), m:position(prev)))
end

function Linker:step()
  local m, made = self.model, 0
  local owner = {}
  for _, c in ipairs(self.flock:children()) do owner[c.particle.id] = c end
  local limit = math.sin(math.rad(self.view))
  for _, c in ipairs(self.flock:children()) do
    local a = self.flock.parents[c.parent]
    if #a.children >= 3 and (self.links[c.particle.id] or 0) < self.max_links then
      local x = m:position(c.particle)
      local t = tangent(m, a, c.index)
      for _, n in ipairs(m:neighbours(c.particle, self.distance)) do
        local other = owner[n.id]
        local key = math.min(c.particle.id, n.id) .. ":" .. math.max(c.particle.id, n.id)
        if other and other.parent ~= c.parent and not self.linked[key]
           and (self.links[n.id] or 0) < self.max_links and (self.links[c.particle.id] or 0) < self.max_links
           and #self.flock.parents[other.parent].children >= 3 then
          local d = vec.sub(m:position(n), x)
          local gap = vec.length(d)
          if gap > 0 and math.abs(vec.dot(d, t)) / gap <= limit then
            local section = { rest_length = gap * self.shrink }
            for k, v in pairs(self.section) do section[k] = v end
            m:cable(c.particle, n, section)
            self.linked[key] = true
            self.links[c.particle.id] = (self.links[c.particle.id] or 0) + 1
            self.links[n.id] = (self.links[n.id] or 0) + 1
            self.cables = self.cables + 1
            made = made + 1
          end
        end
      end
    end
  end
  return made
end
