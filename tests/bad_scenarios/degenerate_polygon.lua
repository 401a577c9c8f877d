-- expect: 4: a polygon needs 3 to 1000 corners, a positive area and no crossing edges
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
fixed { name = "flat", shape = "polygon", polygon = { { 5, 5 }, { 6, 5 }, { 7, 5 } } }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
