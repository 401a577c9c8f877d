-- expect: 6: a tolerance for tree is given, but tree.png is not compared
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
region { name = "p1", rect = { { 7, 7 }, { 8, 8 } } }
task { formula = "F p1" }
expect { tolerance = { tree = { max_channel_difference = 20 } } }
