-- expect: 7: 'view' is "perspective" or "top", got "topdown"
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
movable { name = "B1", center = { 3, 3 }, size = { 0.5, 0.5 } }
region { name = "dock", rect = { { 7, 7 }, { 8, 8 } } }
task { formula = "F dock" }
render { view = "topdown" }
