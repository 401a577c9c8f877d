-- expect: 4: 'mass' is too small for the physics
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
movable { name = "B1", center = { 5, 5 }, size = { 0.5, 0.5 }, mass = 4.9e-324 }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
