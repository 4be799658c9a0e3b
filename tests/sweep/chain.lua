-- The sweep tests' scene: a chain of cables hung between two pins, its
-- particles started off the line by the seed, relaxed under its own weight.
-- Parameters: segments, span; fail_seed makes that seed's run fail on
-- purpose (a scene error). After it has reported, a run stays busy for `hold`
-- seconds, and while the file `hold_while` exists when its seed is
-- `hold_seed` (0: any), so that a test can signal runs in progress.
local segments = tendril.param("segments", 12)
local span = tendril.param("span", 4)
local fail_seed = tendril.param("fail_seed", 0)
local hold = tendril.param("hold", 0)
local hold_while = tendril.param("hold_while", "")
local hold_seed = tendril.param("hold_seed", 0)
if tendril.seed == fail_seed then error("seed " .. fail_seed .. " fails on purpose") end

local m = tendril.model()
m:gravity{ 0, 0, -9.81 }
local ps = {}
for i = 0, segments do
  local x = span * i / segments
  local off = (i == 0 or i == segments) and 0 or 0.05 * (math.random() - 0.5)
  ps[#ps + 1] = m:particle{ x, off, -0.1 * math.sin(math.pi * i / segments) }
end
for i = 1, segments do m:cable(ps[i], ps[i + 1], { EA = 1e4, line_mass = 0.5, rest_length = 1.1 * span / segments }) end
m:lock(ps[1], "xyz")
m:lock(ps[#ps], "xyz")
local r = m:run{ tolerance = 1e-5, max_steps = 200000 }
local sag = -m:position(ps[segments // 2 + 1])[3]
print(string.format("sag %.6f m after %d steps", sag, r.steps))
tendril.report(m, { sag = sag, label = "chain, " .. segments .. " cables" })
m:save(tendril.out("chain.xml"))
local t = os.clock()
while os.clock() - t < hold do end
local function exists(path)
  local f = io.open(path)
  if f then f:close() end
  return f ~= nil
end
if hold_while ~= "" and (hold_seed == 0 or hold_seed == tendril.seed) then
  while exists(hold_while) do
    local t0 = os.clock()
    while os.clock() - t0 < 0.05 do end
  end
end
