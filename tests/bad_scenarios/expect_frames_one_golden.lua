-- expect: 6: 'frames' lists frame_12.5s.png twice (12.5 s and 12.5000000001 s name one golden
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
region { name = "p1", rect = { { 7, 7 }, { 8, 8 } } }
task { formula = "F p1" }
expect { frames = { 12.5, 12.5000000001 } }
