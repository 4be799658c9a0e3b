-- The scene of tests/faults/faults.sh.
-- mode=loop: saves a 60 x 60 grid's model, journal, OBJ and a note again and
--   again (`rounds`, default until killed), printing "saved" once the first
--   complete set is on disk, so a signal can hit any moment of a save.
-- mode=grow: saves a 2 x 2 grid (first=1), then an 80 x 80 one (second=1) to
--   the same file (what = model, journal, obj or report): with no room for the
--   second the run must fail with the reason and leave the first whole.
local function grid(n)
  local m = tendril.model()
  local ps = {}
  for i = 0, n - 1 do
    for j = 0, n - 1 do ps[#ps + 1] = m:particle{ i, j, 0 } end
  end
  m:quad_grid{ particles = ps, rows = n, cols = n, EA = 1e3 }
  return m
end

local function save(m, what)
  if what == "model" then m:save(tendril.out("model.xml"))
  elseif what == "journal" then m:save_journal(tendril.out("journal.txt"))
  elseif what == "obj" then m:save_obj(tendril.out("model.obj"))
  elseif what == "note" then tendril.write_file(tendril.out("note.txt"), string.rep("x", 100000))
  else tendril.report(m, {}) end
end

if tendril.param("mode", "loop") == "loop" then
  local m = grid(60)
  local rounds = tendril.param("rounds", math.huge)
  local round = 0
  while round < rounds do
    for _, what in ipairs{ "model", "journal", "obj", "note" } do save(m, what) end
    round = round + 1
    if round == 1 then print("saved") io.stdout:flush() end
  end
else
  local what = tendril.param("what", "model")
  if tendril.param("first", 1) == 1 then save(grid(2), what) end
  if tendril.param("second", 1) == 1 then save(grid(80), what) end
end
