-- Reach the goal and never enter the hazard: "F goal & G !hazard", the most common robot task in the LTL
-- planning literature. The hazard lies across the direct way; the robot goes round it through the
-- north lane, or through the south one, where a box stands in the way. A plan ends with the robot at rest
-- in the goal (docs/ltl.md: tasks that are not co-safe are read as "the robot stops and stays").
-- `--set task='!hazard U goal'` plans the same task written as a co-safe formula.
--
--   +------------------------------------------+
--   |                 north lane                |
--   |              +-------+                    |
--   |   robot      |hazard |          goal      |
--   |              +-------+                    |
--   |                 [B1]  south lane          |
--   +------------------------------------------+

local P = require "physltl"

workspace { bounds = { { 0, 0 }, { 10, 6 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 1, 3 } }
P.boundary { min = { 0, 0 }, max = { 10, 6 }, thickness = 0.2 }

P.area("hazard", { 4.5, 1.2 }, { 5.5, 4.8 })
P.area("goal", { 8.3, 2.5 }, { 9.3, 3.5 })
P.box { name = "B1", at = { 5.0, 0.7 }, size = 0.5, mass = 0.5 }

task { formula = params.task or "F goal & G !hazard" }
planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
-- What `physltl-studio test scenarios/` holds this scenario to (docs/testing.md); the goldens are in goldens/avoid/.
expect { max_pushes = 0, max_motion_s = 12, tree = true, frames = { "last" } }
