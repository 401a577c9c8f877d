-- expect: 4: line 3: a vertex coordinate 'nan' is not a finite number
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
fixed { name = "desk", mesh = "../geometry/data/nan_vertex.obj", center = { 5, 5 } }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
