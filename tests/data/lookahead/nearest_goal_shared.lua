-- Two boxes in a row, both nearer the west goal than the east one, any box on any goal: the look-ahead's
-- estimate must give the goals one box each (M1 west 1 push, M2 east 4: 5), not count the west goal
-- twice (1 + 2 = 3). Imported from the level drawn below with `physltl-studio import sokoban`.
--   ##########
--   #        #
--   #        #
--   #.$$   . #
--   #        #
--   #@       #
--   ##########
workspace { bounds = { { 0, 0 }, { 6.0000, 4.2000 } } }
robot { radius = 0.25, start = { 0.9000, 0.9000 } }
fixed { name = "wall1", center = { 3.0000, 3.9000 }, size = { 6.0000, 0.6000 } }
fixed { name = "wall2", center = { 0.3000, 2.1000 }, size = { 0.6000, 3.0000 } }
fixed { name = "wall3", center = { 5.7000, 2.1000 }, size = { 0.6000, 3.0000 } }
fixed { name = "wall4", center = { 3.0000, 0.3000 }, size = { 6.0000, 0.6000 } }
movable { name = "M1", center = { 1.5000, 2.1000 }, size = { 0.5, 0.5 }, mass = 0.5 }
movable { name = "M2", center = { 2.1000, 2.1000 }, size = { 0.5, 0.5 }, mass = 0.5 }
region { name = "goal1", polygon = { { 0.6000, 1.8000 }, { 1.2000, 1.8000 }, { 1.2000, 2.4000 }, { 0.6000, 2.4000 } } }
region { name = "goal2", polygon = { { 4.2000, 1.8000 }, { 4.8000, 1.8000 }, { 4.8000, 2.4000 }, { 4.2000, 2.4000 } } }
task { formula = "F G((M1@goal1 | M2@goal1) & (M1@goal2 | M2@goal2))" }
