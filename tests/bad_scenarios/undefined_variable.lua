-- expect: 7: undefined variable 'robot_raduis' (did you mean 'robot_radius'?)
local robot_radius = 0.25
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
region { name = "p1", rect = { { 7, 7 }, { 8, 8 } } }
task { formula = "F p1" }
-- A misspelt variable: nil, and so the default radius, before the strict globals.
robot { radius = robot_raduis, start = { 1, 1 } }
