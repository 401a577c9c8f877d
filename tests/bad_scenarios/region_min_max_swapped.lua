-- expect: 4: region 'p1': 'rect' must go from the smaller corner to the larger one
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
region { name = "p1", rect = { { 8, 8 }, { 7, 7 } } }
task { formula = "F p1" }
