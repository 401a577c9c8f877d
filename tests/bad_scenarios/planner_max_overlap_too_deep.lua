-- expect: 6: planner: 'max_overlap' is too large (0.05 > 0.02)
workspace { bounds = { { 0, 0 }, { 4, 3 } } }
robot { start = { 0.5, 0.5 } }
region { name = "goal", polygon = { { 3, 2 }, { 3.8, 2 }, { 3.8, 2.8 }, { 3, 2.8 } } }
task { formula = "F goal" }
planner { max_overlap = 0.05 }
