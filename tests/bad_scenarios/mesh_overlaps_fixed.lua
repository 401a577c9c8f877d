-- expect: 5: fixed 'desk' overlaps fixed 'pillar'
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
fixed { name = "pillar", shape = "cylinder", center = { 5.3, 5.2 }, radius = 0.15 }
fixed { name = "desk", mesh = "../geometry/data/l_block.obj", center = { 5, 5 } }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
