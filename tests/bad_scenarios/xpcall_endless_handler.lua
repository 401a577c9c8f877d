-- expect: 4: instruction budget
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
-- Lua runs a message handler again for every error raised in it: the budget's error must still end this.
xpcall(function() error("first") end, function(message) while true do end end)
robot { radius = 0.25, start = { 1, 1 } }
task { formula = "F p1" }
