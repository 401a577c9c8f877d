-- Grid push puzzles: rows of characters, '#' a wall cell, '$' a box, '.' a goal, '*' a box on a goal,
-- 'o' an obstacle box the task does not name, '@' the robot, '+' the robot on a goal, anything else floor.
-- Cells `cell` metres (0.6), boxes `box` metres (0.5); the k-th box from the top left is Mk, the k-th
-- obstacle Ok and the k-th goal goalk, and the task puts every box on its goal and keeps it there:
-- F G(M1@goal1 & M2@goal2 & ...), unless the scenario's parameters give a task; the robot is holonomic
-- unless they give a drive (--set drive=differential).
--   require "grid" { "#####", "#@$.#", "#####" }
local P = require "physltl"
return function(rows, cell, box)
  cell, box = cell or 0.6, box or 0.5
  local height, width = #rows, 0
  for _, row in ipairs(rows) do width = math.max(width, #row) end
  workspace { bounds = { { 0, 0 }, { width * cell, height * cell } }, floor_friction = 0.5 }
  local boxes, obstacles, goals, terms = 0, 0, 0, {}
  for r, row in ipairs(rows) do
    local y0 = (height - r) * cell
    local run = nil  -- first column of the wall cells being merged into one block
    for c = 1, #row + 1 do
      local ch = row:sub(c, c)
      local x0 = (c - 1) * cell
      if ch == "#" then
        run = run or c
      elseif run then
        P.block { name = string.format("wall_%d_%d", r, run), min = { (run - 1) * cell, y0 }, max = { x0, y0 + cell } }
        run = nil
      end
      local centre = { x0 + cell / 2, y0 + cell / 2 }
      if ch == "$" or ch == "*" then
        boxes = boxes + 1
        P.box { name = "M" .. boxes, at = centre, size = box, mass = 0.5 }
      end
      if ch == "o" then
        obstacles = obstacles + 1
        P.box { name = "O" .. obstacles, at = centre, size = box, mass = 0.5 }
      end
      if ch == "." or ch == "*" or ch == "+" then
        goals = goals + 1
        P.area("goal" .. goals, { x0, y0 }, { x0 + cell, y0 + cell })
      end
      if ch == "@" or ch == "+" then
        robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = centre, drive = params.drive or "holonomic" }
      end
    end
  end
  for k = 1, boxes do terms[#terms + 1] = string.format("M%d@goal%d", k, k) end
  task { formula = params.task or ("F G(" .. table.concat(terms, " & ") .. ")") }
  planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
end
