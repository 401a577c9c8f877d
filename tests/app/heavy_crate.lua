-- A crate too heavy to push (0.5 * 12 kg * 9.81 m/s^2 = 58.9 N of floor friction against the robot's
-- 20 N) standing in the vault: `crate@vault` always holds and `crate@dock` never can.
workspace { bounds = { { 0, 0 }, { 8, 5 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, start = { 1, 1 } }
movable { name = "crate", center = { 4, 2.5 }, size = { 0.6, 0.6 }, mass = 12 }
movable { name = "box", center = { 2, 3.5 }, size = { 0.5, 0.5 }, mass = 0.5 }
region { name = "vault", rect = { { 3.5, 2.0 }, { 4.5, 3.0 } } }
region { name = "dock", rect = { { 6.5, 3.5 }, { 7.5, 4.5 } } }
task { formula = "F(crate@vault & box@dock) | F crate@dock" }
