-- The CLI scene, saved converged for `tendril export` (tests/cli/export.cmake).
local m = tendril.model()
m:gravity{ 0, 0, -9.81 }
local a, b = m:particle{ -1, 0, 0 }, m:particle{ 1, 0, 0 }
local mass = m:particle{ 0, 0, -0.5 }
m:mass(mass, 1)
m:lock(a, "xyz")
m:lock(b, "xyz")
m:cable(a, mass, { EA = 1e5 })
m:cable(b, mass, { EA = 1e5 })
assert(m:run{ tolerance = 1e-6, max_steps = 100000 }.converged)
m:save(tendril.out("model.xml"))
