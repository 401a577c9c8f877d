-- expect: 5: body name 'B1@home' holds '@', which the formula reads as BODY@REGION: rename the body
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
fixed { name = "wall", center = { 5, 5 }, size = { 1, 4 } }
movable { name = "B1@home", center = { 3, 3 }, size = { 0.5, 0.5 } }
region { name = "dock", rect = { { 7, 7 }, { 8, 8 } } }
task { formula = "F dock" }
