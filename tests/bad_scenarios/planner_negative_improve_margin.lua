-- expect: 6: planner: 'improve_margin' must be at least 0, got -0.05
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
region { name = "p1", rect = { { 7, 7 }, { 8, 8 } } }
task { formula = "F p1" }
planner { improve_margin = -0.05 }
