-- v1 journal fixture: a model opened from a database, goals, particle rules (generated on 3b364af).
local base = tendril.model{ integrator = "projective" }
local p0, p1 = base:particle{ 0, 0, 0 }, base:particle{ 1.5, 0, 0 }
base:cable(p0, p1, { EA = 1000, rest_length = 1 })
base:lock(p0, "all")
base:save("base.xml")
local m = tendril.load("base.xml")
local ps = m:particles()
local g1 = m:anchor(ps[2], { 3, 0, 0 }, 250)
local q = m:particle{ 1, 1, 0 }
local c = m:cable(ps[2], q, { E = 2e9, A = 1e-6, prestress = 1 })
m:goal{ kind = "plane", particle = q, point = { 0, 0, 1 }, normal = { 0, 0, 1 }, weight = 1e4 }
m:goal{ kind = "line", particle = q, point = { 2, 0, 1 }, direction = { 0, 1, 0 }, weight = 1e3 }
m:goal{ kind = "length", particles = { ps[2], q }, length = 1.5, weight = 1e5 }
m:step(50)
m:goal_weight(g1, 1000)
m:step(50)
m:remove_goal(2)
m:step(10)
-- particle rules on a beam
local bm = m:beam{ points = { {0,5,0}, {1,5,0}, {2,5,0}, {3,5,0} }, EA = 1e5, EI = 1 }
local bp = m:particles(bm)
local mid = m:insert(bp[2], bp[3])
m:remove_from_beam(mid)
local x = m:particle{ 1, 6, 0 }
local y = m:particle{ 2, 6, 0 }
local cab = m:cable(bp[2], x, { EA = 100 })
local parts = m:explode(bp[2])
local joined = m:merge(parts)
local freed = m:explode_from(joined, cab)
m:delete_particle(y)
m:settings{ integrator = "leapfrog" }
m:step(30)
m:save(tendril.out("live.xml"))
m:save_journal(tendril.out("journal.txt"))
