-- expect: 4: 'mesh' must name an OBJ file, got an empty string
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
fixed { name = "desk", mesh = "", center = { 5, 5 } }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
