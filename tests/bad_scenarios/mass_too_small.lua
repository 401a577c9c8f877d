-- expect: 5: 'mass' is too small for the physics
workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }
-- 1e-20 kg: ODE's inertia underflows and it aborts the process when the robot touches the box.
movable { name = "B1", center = { 5, 5 }, size = { 0.5, 0.5 }, mass = 1e-20 }
region { name = "p1", rect = { { 8, 8 }, { 9, 9 } } }
task { formula = "F p1" }
