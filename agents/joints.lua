-- Sliding joints (thesis 6.5.2, fig. 6.33-6.34): a connection (a cable or
-- another block) attached to a beam particle slides along the beam. The
-- connection sits on a volatile particle inserted between two consecutive
-- beam particles (rule 13); sliding changes the rest lengths of its two
-- segments, keeping their sum. When the volatile particle comes within
-- `fraction` of a segment of a neighbour, the connection is handed to that
-- neighbour (rule 5 on the beam, rule 11 on the beam's copy, rule 3) and a
-- new volatile particle starts in the next segment when it moves on.
local agents = tendril.agents

local Joint = {}
Joint.__index = Joint

-- options: model, beam (an open beam), at (the beam particle the connection
-- is attached to), connection (that block), fraction (0.1), rate (metres per
-- application of .rule, default 0) or drive = function(m) return ds end.
function agents.sliding_joint(options)
  local m = assert(options.model, "sliding_joint: 'model' is required")
  local self = setmetatable({
    model = m,
    beam = assert(options.beam, "sliding_joint: 'beam' is required"),
    at = assert(options.at, "sliding_joint: 'at' is required"),
    connection = assert(options.connection, "sliding_joint: 'connection' is required"),
    fraction = options.fraction or 0.1,
    rate = options.rate or 0,
    drive = options.drive,
    volatile = false,
  }, Joint)
  assert(not m:closed(self.beam), "sliding_joint: the beam must be open")
  assert(self.fraction > 0 and self.fraction < 0.5, "sliding_joint: 'fraction' must lie in (0, 0.5)")
  local on = {}
  for _, b in ipairs(m:blocks(self.at)) do on[b.id] = true end
  assert(on[self.beam.id] and on[self.connection.id],
         "sliding_joint: 'at' must be on both the beam and the connection")
  self.target = self:position()
  self.rule = tendril.rule{ name = "sliding joint", production = function(model)
    self:slide(self.drive and self.drive(model) or self.rate)
  end }
  return self
end

-- Index of particle p in list ps.
local function index_of(ps, p)
  for i, x in ipairs(ps) do
    if x == p then return i end
  end
end

local function lerp(x, y, t)
  return { x[1] + t * (y[1] - x[1]), x[2] + t * (y[2] - x[2]), x[3] + t * (y[3] - x[3]) }
end

-- The attachment's arc length from the beam's start, in rest lengths.
function Joint:position()
  local m, ps = self.model, self.model:particles(self.beam)
  local s = 0
  for i = 1, #ps do
    if ps[i] == self.at then return s end
    s = s + m:rest_length(ps[i], ps[i + 1])
  end
  error("sliding_joint: the attachment left the beam")
end

-- The connection moves from particle p (on the beam and the connection) onto
-- beam particle n.
function Joint:hop(p, n)
  local m = self.model
  local c = m:explode_from(p, self.connection)
  m:set_position(c, m:position(n))
  self.at = m:merge{ c, n }
end

-- The volatile particle leaves the beam; the connection goes to n.
function Joint:transfer(n)
  local m, v = self.model, self.at
  m:role(v, "none")
  local copy = m:explode_from(v, self.beam)  -- v keeps only the connection
  m:remove_from_beam(copy)                   -- the two segments become one
  m:set_position(v, m:position(n))
  self.at = m:merge{ v, n }
  self.volatile = false
end

-- One move towards the target; false when no progress is possible.
function Joint:advance()
  local m = self.model
  local ps = m:particles(self.beam)
  local i = index_of(ps, self.at)
  local need = self.target - self:position()
  if not self.volatile then
    local dir = need > 0 and 1 or -1
    local n = ps[i + dir]
    if n == nil then
      self.target = self:position()  -- at the beam's end: stop there
      return false
    end
    local L = m:rest_length(self.at, n)
    local d = math.abs(need)
    if d >= (1 - self.fraction) * L then
      self:hop(self.at, n)
    elseif d <= self.fraction * L then
      return false  -- too small a step: kept in the target for later
    else
      local p = self.at
      local v = m:insert(p, n)
      m:rest_length(p, v, d)
      m:rest_length(v, n, L - d)
      m:set_position(v, lerp(m:position(p), m:position(n), d / L))
      local c = m:explode_from(p, self.connection)
      m:set_position(c, m:position(v))
      self.at = m:merge{ c, v }
      m:role(self.at, "volatile")
      self.volatile = true
    end
    return true
  end
  local a, b, v = ps[i - 1], ps[i + 1], self.at
  local la, lb = m:rest_length(a, v), m:rest_length(v, b)
  local total = la + lb
  local x = la + need
  if x >= (1 - self.fraction) * total then
    self:transfer(b)
  elseif x <= self.fraction * total then
    self:transfer(a)
  else
    m:rest_length(a, v, x)
    m:rest_length(v, b, total - x)
    m:set_position(v, lerp(m:position(a), m:position(b), x / total))
  end
  return true
end

-- Moves the connection ds metres along the beam (positive towards its end).
function Joint:slide(ds)
  self.target = self.target + ds
  for _ = 1, 10000 do
    if math.abs(self.target - self:position()) < 1e-12 or not self:advance() then return self end
  end
  return self
end

function Joint:particle() return self.at end
