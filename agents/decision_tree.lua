-- Decision-tree connection chooser (thesis 5.5.1, fig. 5.22-5.24). The
-- designer picks a sample pattern: one particle on each of several beams,
-- given by its index along its beam. The tree stores the differences of
-- consecutive indexes; a candidate pattern is accepted when every difference
-- matches, node by node. Random candidates that pass become connections: a
-- cable chain or a spline beam through the chosen particles.
local agents = tendril.agents

local Tree = {}
Tree.__index = Tree

-- sample: indexes {i1, i2, ..., ik} along k beams.
function agents.decision_tree(sample)
  assert(type(sample) == "table" and #sample >= 2, "decision_tree: the sample needs at least two indexes")
  local nodes = {}
  for k = 1, #sample - 1 do nodes[k] = sample[k + 1] - sample[k] end
  return setmetatable({ nodes = nodes, size = #sample }, Tree)
end

-- true, or false and the node that rejected the candidate.
function Tree:accepts(candidate)
  if #candidate ~= self.size then return false, 0 end
  for k, difference in ipairs(self.nodes) do
    if candidate[k + 1] - candidate[k] ~= difference then return false, k end
  end
  return true
end

-- options: model, beams = {b1, ..., bk} (disconnected beams, in order),
-- sample = {i1, ..., ik}, tries (random candidates, default 200),
-- connect = "cable" (default) or "beam", section.
-- Returns the accepted index patterns, in the order they were connected.
function agents.choose_connections(options)
  local m = assert(options.model, "choose_connections: 'model' is required")
  local beams = assert(options.beams, "choose_connections: 'beams' is required")
  local tree = agents.decision_tree(assert(options.sample, "choose_connections: 'sample' is required"))
  assert(#beams == tree.size, "choose_connections: one sample index per beam")
  local particles = {}
  for k, b in ipairs(beams) do particles[k] = m:particles(b) end
  local accepted, seen = {}, {}
  for _ = 1, options.tries or 200 do
    local candidate = {}
    for k = 1, #beams do candidate[k] = math.random(#particles[k]) end
    local key = table.concat(candidate, ",")
    if not seen[key] and tree:accepts(candidate) then
      seen[key] = true
      local chosen = {}
      for k, i in ipairs(candidate) do chosen[k] = particles[k][i] end
      local section = options.section or { EA = 1e4 }
      if options.connect == "beam" then
        local o = { particles = chosen }
        for k, v in pairs(section) do o[k] = v end
        m:beam(o)
      else
        for k = 1, #chosen - 1 do m:cable(chosen[k], chosen[k + 1], section) end
      end
      accepted[#accepted + 1] = candidate
    end
  end
  return accepted
end
