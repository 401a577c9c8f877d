-- expect: 4: a mesh collides as its own footprint
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
fixed { name = "desk", mesh = "../geometry/data/l_desk.obj", center = { 5, 5 }, size = { 2, 1.5 } }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
