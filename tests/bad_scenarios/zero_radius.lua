-- expect: 4: 'radius' must be greater than 0
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
movable { name = "bin", shape = "cylinder", center = { 5, 5 }, radius = 0 }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
