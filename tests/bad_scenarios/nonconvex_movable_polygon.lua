-- expect: 5: a movable polygon must be convex
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
movable { name = "ok", shape = "polygon", points = { { 0, 0 }, { 1, 0 }, { 0.5, 1 } }, center = { 3, 3 } }
movable { name = "dart", shape = "polygon", polygon = { { 5, 5 }, { 7, 5 }, { 6, 5.5 }, { 6, 7 } } }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
