-- expect: 5: movable 'bin' overlaps movable 'hexagon'
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
movable { name = "hexagon", shape = "polygon", center = { 5, 5 }, points = { { 0.5, 0 }, { 0.25, 0.43 }, { -0.25, 0.43 }, { -0.5, 0 }, { -0.25, -0.43 }, { 0.25, -0.43 } } }
movable { name = "bin", shape = "cylinder", center = { 5.8, 5 }, radius = 0.35 }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
