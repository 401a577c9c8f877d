-- expect: 11: B1 is named both as B1 and as crates
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
movable { name = "B1", center = { 3, 3 }, size = { 0.5, 0.5 } }
movable { name = "B2", center = { 4, 3 }, size = { 0.5, 0.5 } }
region { name = "dock1", rect = { { 7, 7 }, { 8, 8 } } }
region { name = "dock2", rect = { { 8, 7 }, { 9, 8 } } }
region { name = "safe", rect = { { 1, 7 }, { 2, 8 } } }
group { name = "crates", bodies = { "B1", "B2" } }
group { name = "docks", regions = { "dock1", "dock2" } }
task { formula = "F crates@docks & G !B1@safe" }
