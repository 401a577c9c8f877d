-- expect: 6: 'parts' must join into one piece without holes
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
movable { name = "ok", shape = "polygon", center = { 3, 3 },
          parts = { { { 0, 0 }, { 1, 0 }, { 1, 0.3 }, { 0, 0.3 } }, { { 0, 0.3 }, { 0.3, 0.3 }, { 0.3, 1 }, { 0, 1 } } } }
movable { name = "apart", shape = "polygon", center = { 6, 6 },
          parts = { { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } }, { { 1, 1 }, { 2, 1 }, { 2, 2 }, { 1, 2 } } } }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
