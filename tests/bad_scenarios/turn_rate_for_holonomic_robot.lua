-- expect: 3: 'max_turn_rate_deg' is for drive = "differential"
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 }, max_turn_rate_deg = 45 }
region { name = "p1", rect = { { 7, 7 }, { 8, 8 } } }
task { formula = "F p1" }
