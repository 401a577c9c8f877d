-- expect: 7: an error was raised with a table instead of a message
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
region { name = "p1", rect = { { 7, 7 }, { 8, 8 } } }
task { formula = "F p1" }
local object = setmetatable({}, { __tostring = function() while true do end end })
error(object)
