-- expect: 4: line 8: a face corner '100000000000000000000' names no vertex
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
fixed { name = "desk", mesh = "../geometry/data/huge_face_index.obj", center = { 5, 5 } }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
