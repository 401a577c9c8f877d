-- expect: 4: 'push_from' is for boxes and polygons
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
movable { name = "bin", shape = "cylinder", center = { 5, 5 }, radius = 0.3, push_from = { "-x" } }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
