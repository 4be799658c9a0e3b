-- Used by the cli-error tests: line 4 has a misspelled key.
local m = tendril.model()
local p = m:particle{ 0, 0, 0 }
m:beam{ from = p, direction = { 1, 0, 0 }, segmnts = 4, EA = 1, EI = 1 }
