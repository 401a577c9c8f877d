-- expect: 4: movable 'B1': uncertainty 'mass' is too large (2 > 0.9)
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
movable { name = "B1", center = { 3, 3 }, size = { 0.5, 0.5 }, uncertainty = { mass = 2 } }
region { name = "p1", rect = { { 7, 7 }, { 8, 8 } } }
task { formula = "F p1" }
