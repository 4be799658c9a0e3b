-- Small 3-vector helpers shared by the agents (tables {x, y, z}).
local agents = tendril.agents or {}
tendril.agents = agents

local vec = {}
function vec.add(a, b) return { a[1] + b[1], a[2] + b[2], a[3] + b[3] } end
function vec.sub(a, b) return { a[1] - b[1], a[2] - b[2], a[3] - b[3] } end
function vec.scale(a, s) return { a[1] * s, a[2] * s, a[3] * s } end
function vec.dot(a, b) return a[1] * b[1] + a[2] * b[2] + a[3] * b[3] end
function vec.length(a) return math.sqrt(vec.dot(a, a)) end
function vec.distance(a, b) return vec.length(vec.sub(a, b)) end
function vec.normalize(a)
  local l = vec.length(a)
  if l == 0 then return { 0, 0, 0 } end
  return vec.scale(a, 1 / l)
end
-- The vector shortened to at most `limit` long.
function vec.limit(a, limit)
  local l = vec.length(a)
  if l <= limit then return a end
  return vec.scale(a, limit / l)
end
agents.vec = vec
