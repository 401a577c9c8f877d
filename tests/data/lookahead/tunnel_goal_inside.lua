-- A box in a one-cell passage with its goal inside the passage: the tunnel macro must stop there, not
-- push the box on past it (where, the robot behind it and no way round, it could never come back).
-- Imported from the level drawn below with `physltl-studio import sokoban`.
--   #########
--   #@$  .  #
--   #########
workspace { bounds = { { 0, 0 }, { 5.4000, 1.8000 } } }
robot { radius = 0.25, start = { 0.9000, 0.9000 } }
fixed { name = "wall1", center = { 2.7000, 1.5000 }, size = { 5.4000, 0.6000 } }
fixed { name = "wall2", center = { 0.3000, 0.9000 }, size = { 0.6000, 0.6000 } }
fixed { name = "wall3", center = { 5.1000, 0.9000 }, size = { 0.6000, 0.6000 } }
fixed { name = "wall4", center = { 2.7000, 0.3000 }, size = { 5.4000, 0.6000 } }
movable { name = "M1", center = { 1.5000, 0.9000 }, size = { 0.5, 0.5 }, mass = 0.5 }
region { name = "goal1", polygon = { { 3.0000, 0.6000 }, { 3.6000, 0.6000 }, { 3.6000, 1.2000 }, { 3.0000, 1.2000 } } }
group { name = "boxes", bodies = { "M1" } }
group { name = "goals", regions = { "goal1" } }
task { formula = "F G(boxes@goals)" }
