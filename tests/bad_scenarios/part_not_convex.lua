-- expect: 4: part 2 of 'parts' must be a convex polygon
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
movable { name = "dart", shape = "polygon", center = { 5, 5 }, parts = { { { 0, 0 }, { 1, 0 }, { 0, 1 } }, { { 0, 0 }, { 2, 0 }, { 1, 0.5 }, { 1, 2 } } } }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
