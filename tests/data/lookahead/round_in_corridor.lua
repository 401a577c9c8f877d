-- A cylinder the task names, in a corridor 1.2 m wide: narrower than its width (0.6 m, its diameter) and
-- two robot diameters (1.0 m), so the look-ahead's rule says why it would apply, with the cylinder's
-- width, and why it cannot (the lattice takes boxes standing square).
workspace { bounds = { { 0, 0 }, { 8, 3.2 } } }
robot { radius = 0.25, start = { 0.6, 1.6 } }
fixed { name = "north", center = { 4, 2.6 }, size = { 8, 1.2 } }
fixed { name = "south", center = { 4, 0.6 }, size = { 8, 1.2 } }
movable { name = "drum", shape = "cylinder", center = { 2.5, 1.6 }, radius = 0.3, mass = 0.5 }
region { name = "bay", rect = { { 6.5, 1.2 }, { 7.5, 2.0 } } }
task { formula = "F drum@bay" }
