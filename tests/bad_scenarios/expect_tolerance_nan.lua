-- expect: 6: 'max_channel_difference' must be a finite number
workspace { bounds = { { 0, 0 }, { 4, 3 } } }
robot { start = { 0.5, 0.5 } }
region { name = "goal", polygon = { { 3, 2 }, { 3.8, 2 }, { 3.8, 2.8 }, { 3, 2.8 } } }
task { formula = "F goal" }
expect { tolerance = { max_channel_difference = 0 / 0 } }
