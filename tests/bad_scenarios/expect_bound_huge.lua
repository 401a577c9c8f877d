-- expect: 6: 'max_pushes' must be a whole number from 0 to 1e9, got 1.2e+308
workspace { bounds = { { 0, 0 }, { 4, 3 } } }
robot { start = { 0.5, 0.5 } }
region { name = "goal", polygon = { { 3, 2 }, { 3.8, 2 }, { 3.8, 2.8 }, { 3, 2.8 } } }
task { formula = "F goal" }
expect { max_pushes = 1.2e308 }
