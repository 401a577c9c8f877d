-- expect: 6: 'frames' lists seconds of motion (0 to 1e6) or "last"
workspace { bounds = { { 0, 0 }, { 4, 3 } } }
robot { start = { 0.5, 0.5 } }
region { name = "goal", polygon = { { 3, 2 }, { 3.8, 2 }, { 3.8, 2.8 }, { 3, 2.8 } } }
task { formula = "F goal" }
expect { frames = { 0, "end" } }
