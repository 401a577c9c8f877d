-- expect: 6: 'infeasible' is the text the reason must contain, and may not be empty
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
region { name = "p1", rect = { { 7, 7 }, { 8, 8 } } }
task { formula = "F p1" }
expect { solved = false, infeasible = "" }
