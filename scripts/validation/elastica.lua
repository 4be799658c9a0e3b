-- Pin-ended strut buckled into an elastica (thesis 5.4.1.2; Adriaenssens &
-- Barnes 2001): L = 10 m, 64 segments, EI = 100 kNm^2, EA = 100 MN.
-- Compared with the exact elastica through complete elliptic integrals.
local L, EI, EA, n = 10, 1e5, 1e8, 64

-- Complete elliptic integrals K(k), E(k) by the arithmetic-geometric mean.
local function ellipke(k)
  -- E/K = 1 - sum 2^(n-1) c_n^2 with c_0 = k, c_n = (a_(n-1) - b_(n-1)) / 2.
  local a, b, sum, pow = 1, math.sqrt(1 - k * k), k * k / 2, 0.5
  for _ = 1, 60 do  -- converges quadratically; 60 rounds is far more than needed
    if math.abs(a - b) <= 1e-15 then break end
    local c = (a - b) / 2
    a, b = (a + b) / 2, math.sqrt(a * b)
    pow = pow * 2
    sum = sum + pow * c * c
  end
  local K = math.pi / (2 * a)
  return K, K * (1 - sum)
end

for _, theta in ipairs{ 30, 60, 90 } do
  local k = math.sin(math.rad(theta) / 2)
  local K, E = ellipke(k)
  local chord = L * (2 * E / K - 1)
  local exact_delta, exact_P = k * L / K, EI * (2 * K / L)^2

  local m = tendril.model()
  local ps = {}
  for i = 0, n do ps[#ps + 1] = m:particle{ L * i / n, 0, 0 } end
  m:beam{ particles = ps, EA = EA, EI = EI }
  -- Bend the straight strut to a half sine of the right chord; the rest
  -- lengths stay straight.
  for i = 0, n do
    local s = i / n
    m:set_position(ps[i + 1], { chord * s, exact_delta * math.sin(math.pi * s), 0 })
    m:lock(ps[i + 1], "z")
  end
  m:lock(ps[1], "xyz")
  m:lock(ps[n + 1], "xyz")
  local r = m:run{ tolerance = 1e-3, max_steps = 1000000 }
  local delta = m:position(ps[n // 2 + 1])[2]
  local P = -m:reaction(ps[n + 1])[1]
  local e_delta, e_P = delta / exact_delta - 1, P / exact_P - 1
  print(string.format("theta0 %3d deg: delta %.4f m (exact %.4f, %+.3f%%)  P %.1f N (exact %.1f, %+.3f%%)  %d steps",
    theta, delta, exact_delta, 100 * e_delta, P, exact_P, 100 * e_P, r.steps))
  assert(r.converged and math.abs(e_delta) < 0.01 and math.abs(e_P) < 0.01, "elastica outside 1%")
end
