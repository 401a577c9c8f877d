-- 20 boxes beside 20 goals, 12 of them wanted on their goal: the pictures of a task of many object facts
-- (docs/rendering.md, "The legend" and "Labels"; `physltl-studio check` draws its preview.png).
workspace { bounds = { { 0, 0 }, { 7.2, 5.4 } } }
robot { radius = 0.25, start = { 0.6, 0.6 } }
local P = require "physltl"
P.boundary { min = { 0, 0 }, max = { 7.2, 5.4 } }
movable { name = "M1", center = { 1.80, 1.20 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal1", rect = { { 0.90, 0.90 }, { 1.50, 1.50 } } }
movable { name = "M2", center = { 3.00, 1.20 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal2", rect = { { 2.10, 0.90 }, { 2.70, 1.50 } } }
movable { name = "M3", center = { 4.20, 1.20 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal3", rect = { { 3.30, 0.90 }, { 3.90, 1.50 } } }
movable { name = "M4", center = { 5.40, 1.20 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal4", rect = { { 4.50, 0.90 }, { 5.10, 1.50 } } }
movable { name = "M5", center = { 6.60, 1.20 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal5", rect = { { 5.70, 0.90 }, { 6.30, 1.50 } } }
movable { name = "M6", center = { 1.80, 2.40 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal6", rect = { { 0.90, 2.10 }, { 1.50, 2.70 } } }
movable { name = "M7", center = { 3.00, 2.40 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal7", rect = { { 2.10, 2.10 }, { 2.70, 2.70 } } }
movable { name = "M8", center = { 4.20, 2.40 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal8", rect = { { 3.30, 2.10 }, { 3.90, 2.70 } } }
movable { name = "M9", center = { 5.40, 2.40 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal9", rect = { { 4.50, 2.10 }, { 5.10, 2.70 } } }
movable { name = "M10", center = { 6.60, 2.40 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal10", rect = { { 5.70, 2.10 }, { 6.30, 2.70 } } }
movable { name = "M11", center = { 1.80, 3.60 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal11", rect = { { 0.90, 3.30 }, { 1.50, 3.90 } } }
movable { name = "M12", center = { 3.00, 3.60 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal12", rect = { { 2.10, 3.30 }, { 2.70, 3.90 } } }
movable { name = "M13", center = { 4.20, 3.60 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal13", rect = { { 3.30, 3.30 }, { 3.90, 3.90 } } }
movable { name = "M14", center = { 5.40, 3.60 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal14", rect = { { 4.50, 3.30 }, { 5.10, 3.90 } } }
movable { name = "M15", center = { 6.60, 3.60 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal15", rect = { { 5.70, 3.30 }, { 6.30, 3.90 } } }
movable { name = "M16", center = { 1.80, 4.80 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal16", rect = { { 0.90, 4.50 }, { 1.50, 5.10 } } }
movable { name = "M17", center = { 3.00, 4.80 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal17", rect = { { 2.10, 4.50 }, { 2.70, 5.10 } } }
movable { name = "M18", center = { 4.20, 4.80 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal18", rect = { { 3.30, 4.50 }, { 3.90, 5.10 } } }
movable { name = "M19", center = { 5.40, 4.80 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal19", rect = { { 4.50, 4.50 }, { 5.10, 5.10 } } }
movable { name = "M20", center = { 6.60, 4.80 }, size = { 0.4, 0.4 }, mass = 0.5 }
region { name = "goal20", rect = { { 5.70, 4.50 }, { 6.30, 5.10 } } }

task { formula = "F(M1@goal1 | M2@goal2 | M3@goal3 | M4@goal4 | M5@goal5 | M6@goal6 | M7@goal7 | M8@goal8 | M9@goal9 | M10@goal10 | M11@goal11 | M12@goal12)" }
