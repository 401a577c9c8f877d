-- expect: 6: undefined variable 'widht'
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
region { name = "p1", rect = { { 7, 7 }, { 8, 8 } } }
task { formula = "F p1" }
local function box_size(width) return widht * 2 end
movable { name = "B1", center = { 3, 3 }, size = { box_size(0.25), 0.5 } }
