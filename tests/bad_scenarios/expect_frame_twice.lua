-- expect: 6: 'frames' lists frame_2s.png twice
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
region { name = "p1", rect = { { 7, 7 }, { 8, 8 } } }
task { formula = "F p1" }
expect { frames = { 2, 5, 2 } }
