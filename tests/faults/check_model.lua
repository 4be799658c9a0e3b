-- Loads a model database and checks its particle count (faults.sh).
local m = tendril.load(tendril.param("file", ""))
m:check()
local want = tendril.param("particles", -1)
assert(m:count().particles == want, "expected " .. want .. " particles, got " .. m:count().particles)
