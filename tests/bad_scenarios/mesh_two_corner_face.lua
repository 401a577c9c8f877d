-- expect: 4: line 8: a face needs at least 3 corners
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
fixed { name = "desk", mesh = "../geometry/data/two_corner_face.obj", center = { 5, 5 } }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
