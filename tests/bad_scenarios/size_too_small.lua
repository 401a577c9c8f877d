-- expect: 5: 'size' x is too small for the physics
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
-- A millimetre's box pressed between others makes ODE's contact matrix singular, which it asserts on.
movable { name = "B1", center = { 5, 5 }, size = { 0.001, 0.5 } }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
