-- expect: 3: 'drive' is "holonomic" or "differential", got "omni"
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { drive = "omni", radius = 0.25, start = { 1, 1 } }
region { name = "p1", rect = { { 7, 7 }, { 8, 8 } } }
task { formula = "F p1" }
