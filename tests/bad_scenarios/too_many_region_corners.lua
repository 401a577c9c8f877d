-- expect: 8: more than 10000 corners together
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
fixed { name = "wall", center = { 5, 5 }, size = { 1, 4 } }
movable { name = "B1", center = { 3, 3 }, size = { 0.5, 0.5 } }
region { name = "p1", rect = { { 7, 7 }, { 8, 8 } } }
task { formula = "F p1" }
for r = 1, 20 do local corners = {} for k = 1, 1000 do local a = 2 * math.pi * k / 1000 corners[k] = { 5 + 0.1 * math.cos(a), 0.2 * r + 0.05 * math.sin(a) } end region { name = 'ring' .. r, polygon = corners } end
