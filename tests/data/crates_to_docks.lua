-- Three crates, three docks, and a task about them all at once through groups (docs/scenarios.md#groups):
-- every crate in some dock in the end, whichever dock each takes.
workspace { bounds = { { 0, 0 }, { 8, 6 } } }
robot { radius = 0.25, start = { 1, 1 } }
movable { name = "C1", center = { 2.5, 1.5 }, size = { 0.5, 0.5 }, mass = 0.5 }
movable { name = "C2", center = { 2.5, 3.0 }, size = { 0.5, 0.5 }, mass = 0.5 }
movable { name = "C3", center = { 2.5, 4.5 }, size = { 0.5, 0.5 }, mass = 0.5 }
region { name = "dock1", rect = { { 5.6, 1.1 }, { 6.4, 1.9 } } }
region { name = "dock2", rect = { { 5.6, 2.6 }, { 6.4, 3.4 } } }
region { name = "dock3", rect = { { 5.6, 4.1 }, { 6.4, 4.9 } } }
group { name = "crates", bodies = { "C1", "C2", "C3" } }
group { name = "docks", regions = { "dock1", "dock2", "dock3" } }
task { formula = "F G(crates@docks)" }
planner { time_limit = 60, seed = 1 }
