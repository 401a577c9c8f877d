-- A box in a one-cell passage, its goal at the passage's far end: the tunnel macro pushes it on from each
-- place of the passage to the next without settling the arrangements between (push_search.cpp, in_tunnel).
-- Imported from the level drawn below with `physltl-studio import sokoban`.
--   #########
--   #@$    .#
--   #########
workspace { bounds = { { 0, 0 }, { 5.4000, 1.8000 } } }
robot { radius = 0.25, start = { 0.9000, 0.9000 } }
fixed { name = "wall1", center = { 2.7000, 1.5000 }, size = { 5.4000, 0.6000 } }
fixed { name = "wall2", center = { 0.3000, 0.9000 }, size = { 0.6000, 0.6000 } }
fixed { name = "wall3", center = { 5.1000, 0.9000 }, size = { 0.6000, 0.6000 } }
fixed { name = "wall4", center = { 2.7000, 0.3000 }, size = { 5.4000, 0.6000 } }
movable { name = "M1", center = { 1.5000, 0.9000 }, size = { 0.5, 0.5 }, mass = 0.5 }
region { name = "goal1", polygon = { { 4.2000, 0.6000 }, { 4.8000, 0.6000 }, { 4.8000, 1.2000 }, { 4.2000, 1.2000 } } }
group { name = "boxes", bodies = { "M1" } }
group { name = "goals", regions = { "goal1" } }
task { formula = "F G(boxes@goals)" }
