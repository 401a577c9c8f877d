-- expect: 4: 'push_from' faces of a polygon are 1 to 3
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
movable { name = "wedge", shape = "polygon", center = { 5, 5 },
          points = { { 0, 0 }, { 1, 0 }, { 0.5, 1 } }, push_from = { 1, 4 } }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
