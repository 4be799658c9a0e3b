-- A 1 kg mass hung from two pins by cables: the CLI tests' scene. It declares
-- two parameters; `max_steps = 10` stops it before equilibrium (--strict).
local sag = tendril.param("sag", 0.5)
local max_steps = tendril.param("max_steps", 100000)
local m = tendril.model()
m:gravity{ 0, 0, -9.81 }
local a, b = m:particle{ -1, 0, 0 }, m:particle{ 1, 0, 0 }
local mass = m:particle{ 0, 0, -sag }
m:mass(mass, 1)
m:lock(a, "xyz")
m:lock(b, "xyz")
m:cable(a, mass, { EA = 1e5 })
m:cable(b, mass, { EA = 1e5 })
local r = m:run{ tolerance = 1e-6, max_steps = max_steps }
print(string.format("converged %s after %d steps", tostring(r.converged), r.steps))
