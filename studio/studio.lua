-- The studio's view of a scene (studio/session.cpp), run before the agents
-- and the scene: it notes the models the scene makes (the studio watches the
-- last one that stepped, else the last one made), the rules it defines (the
-- palette offers them beside tendril.rules) and the parameters it reads (the
-- page's sliders). It changes nothing the scene sees.
local studio = { params = {}, rules = {} }
tendril.studio = studio

local model, load, rule, param = tendril.model, tendril.load, tendril.rule, tendril.param

function tendril.model(...)
  local m = model(...)
  studio.last = m
  return m
end

function tendril.load(...)
  local m = load(...)
  studio.last = m
  return m
end

function tendril.rule(def)
  local r = rule(def)
  studio.rules[#studio.rules + 1] = r
  return r
end

function tendril.param(name, default)
  local value = param(name, default)
  if studio.params[name] == nil then studio.params[#studio.params + 1] = name end
  studio.params[name] = { default = default, value = value }
  return value
end

-- The palette: every rule with its arguments, named as its production names
-- them (after the model). Built-in rules by their key in tendril.rules,
-- the scene's by "scene:N".
local function entry(key, r)
  local args = {}
  local f = r.production
  local info = debug.getinfo(f, "u")
  for i = 2, info.nparams do args[#args + 1] = debug.getlocal(f, i) end
  return { key = key, name = r.name, args = args, axiom = r.axiom ~= nil }
end

function studio.palette()
  local out, keys = {}, {}
  for key in pairs(tendril.rules) do keys[#keys + 1] = key end
  table.sort(keys, function(a, b)
    local na = tonumber(tendril.rules[a].name:match("^rule (%d+)")) or 1000
    local nb = tonumber(tendril.rules[b].name:match("^rule (%d+)")) or 1000
    if na ~= nb then return na < nb end
    return a < b
  end)
  for _, key in ipairs(keys) do out[#out + 1] = entry(key, tendril.rules[key]) end
  for i, r in ipairs(studio.rules) do out[#out + 1] = entry("scene:" .. i, r) end
  return out
end

-- The parameters the scene read, in the order it read them.
function studio.parameters()
  local out = {}
  for i, name in ipairs(studio.params) do
    local p = studio.params[name]
    out[i] = { name = name, default = p.default, value = p.value }
  end
  return out
end

function studio.rule(key)
  local i = key:match("^scene:(%d+)$")
  if i then return studio.rules[tonumber(i)] end
  return tendril.rules[key]
end
