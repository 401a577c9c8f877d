-- expect: 4: 'shape' is "box", "cylinder" or "polygon", got "sphere"
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
movable { name = "ball", shape = "sphere", center = { 5, 5 }, radius = 0.3 }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
