-- expect: 6: 'width' must be a whole number from -1e9 to 1e9, got 1e+300
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
region { name = "p1", rect = { { 7, 7 }, { 8, 8 } } }
task { formula = "F p1" }
render { width = 1e300 }
