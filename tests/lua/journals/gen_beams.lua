-- v1 journal fixture: beams, 6 DOF, frames, joints, settings (generated on 3b364af).
local m = tendril.model{ damping = "kinetic", dt = 0.9 }
m:gravity{ 0, 0, -9.81 }
local ps = {}
for i = 0, 8 do ps[#ps + 1] = m:particle{ i * 0.25, 0, 0.01 * i } end
local b = m:beam{ particles = ps, EA = 1e6, EI = 10, GJ = 8, EIy = 9, EIz = 11, dofs = 6, line_mass = 0.5 }
m:lock(ps[1], "full")
m:torque(ps[9], { 0, 0, 0.3 })
m:orientation(ps[5], { 0, 1, 0 }, { -1, 0, 0 }, { 0, 0, 1 })
m:step(30)
m:formulation(b, 3)
m:step(20)
local q, nb = m:split(b, ps[5])
m:rest_length(ps[2], ps[3], 0.3)
m:role(ps[4], "parent")
m:passive(ps[7], true)
m:step(5)
m:passive(ps[7], false)
m:mass(ps[8], 0.25)
m:load(ps[6], { 0, 1, 0 })
local start = m:particle{ 0, 1, 0 }
local bf = m:beam{ from = start, direction = { 2, 0, 0 }, segments = 4, EA = 1e5, EI = 5 }
local tip = m:particles(bf)[5]
local far = m:particle{ 2.5, 1, 0 }
m:extend(bf, tip, far)
local ring = m:beam{ points = { {0,3,0}, {1,3,0}, {1,4,0}, {0,4,0} }, closed = true, EA = 1e5, EI = 5 }
m:unlock(ps[1], "rz")
m:lock(start, "xyz")
m:settings{ integrator = "vie", vie_iterations = 6, vie_dt = 0.5 }
m:step(25)
m:settings{ integrator = "mixed", mixed_switch = 0.05, mixed_implicit = "projective", mass_factor = 2 }
m:step(25)
m:set_position(far, { 2.6, 1.1, 0 })
m:delete(ring)
-- a joint at the crossing of two rods
local a, c = {}, {}
for i = -4, 4 do a[#a + 1] = m:particle{ 5 + i * 0.25, 0, 0 } end
for i = -4, 4 do
  if i == 0 then c[#c + 1] = a[5] else c[#c + 1] = m:particle{ 5, i * 0.25, 0 } end
end
m:beam{ particles = a, EA = 1e6, EI = 50 }
m:beam{ particles = c, EA = 1e6, EI = 50 }
local j = m:joint(a[5], { stiffness = 1e4 })
m:joint_angle(j, 60)
m:settings{ integrator = "leapfrog", damping = "viscous", viscous = 0.1 }
m:step(40)
m:save(tendril.out("live.xml"))
m:save_journal(tendril.out("journal.txt"))
