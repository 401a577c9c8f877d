-- expect: 8: more than 2000 fixed bodies
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
fixed { name = "wall", center = { 5, 5 }, size = { 1, 4 } }
movable { name = "B1", center = { 3, 3 }, size = { 0.5, 0.5 } }
region { name = "p1", rect = { { 7, 7 }, { 8, 8 } } }
task { formula = "F p1" }
for i = 1, 3000 do fixed { name = 'post' .. i, center = { 0.1 + (i % 90) * 0.1, 5 + (i // 90) * 0.1 }, size = { 0.05, 0.05 } } end
