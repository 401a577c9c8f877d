-- A room of four goals behind a door one box wide, four boxes before it: a box pushed onto the door, into
-- the room, is pushed on at once to the deepest goal still free (the goal macro, push_search.cpp,
-- into_room). Imported from the level drawn below with `physltl-studio import sokoban`.
--    #######
--    #.. ..#
--    #     #
--    #     #
--    ### ###
--    #     #
--    # $$$ #
--    #  $  #
--    #  @  #
--    #######
workspace { bounds = { { 0, 0 }, { 4.8000, 6.0000 } } }
robot { radius = 0.25, start = { 2.7000, 0.9000 } }
fixed { name = "wall1", center = { 2.7000, 5.7000 }, size = { 4.2000, 0.6000 } }
fixed { name = "wall2", center = { 0.9000, 4.5000 }, size = { 0.6000, 1.8000 } }
fixed { name = "wall3", center = { 4.5000, 4.5000 }, size = { 0.6000, 1.8000 } }
fixed { name = "wall4", center = { 1.5000, 3.3000 }, size = { 1.8000, 0.6000 } }
fixed { name = "wall5", center = { 3.9000, 3.3000 }, size = { 1.8000, 0.6000 } }
fixed { name = "wall6", center = { 0.9000, 1.8000 }, size = { 0.6000, 2.4000 } }
fixed { name = "wall7", center = { 4.5000, 1.8000 }, size = { 0.6000, 2.4000 } }
fixed { name = "wall8", center = { 2.7000, 0.3000 }, size = { 4.2000, 0.6000 } }
movable { name = "M1", center = { 2.1000, 2.1000 }, size = { 0.5, 0.5 }, mass = 0.5 }
movable { name = "M2", center = { 2.7000, 2.1000 }, size = { 0.5, 0.5 }, mass = 0.5 }
movable { name = "M3", center = { 3.3000, 2.1000 }, size = { 0.5, 0.5 }, mass = 0.5 }
movable { name = "M4", center = { 2.7000, 1.5000 }, size = { 0.5, 0.5 }, mass = 0.5 }
region { name = "goal1", polygon = { { 1.2000, 4.8000 }, { 1.8000, 4.8000 }, { 1.8000, 5.4000 }, { 1.2000, 5.4000 } } }
region { name = "goal2", polygon = { { 1.8000, 4.8000 }, { 2.4000, 4.8000 }, { 2.4000, 5.4000 }, { 1.8000, 5.4000 } } }
region { name = "goal3", polygon = { { 3.0000, 4.8000 }, { 3.6000, 4.8000 }, { 3.6000, 5.4000 }, { 3.0000, 5.4000 } } }
region { name = "goal4", polygon = { { 3.6000, 4.8000 }, { 4.2000, 4.8000 }, { 4.2000, 5.4000 }, { 3.6000, 5.4000 } } }
group { name = "boxes", bodies = { "M1", "M2", "M3", "M4" } }
group { name = "goals", regions = { "goal1", "goal2", "goal3", "goal4" } }
task { formula = "F G(boxes@goals)" }
planner { time_limit = 60, seed = 1 }
