-- An L-shaped desk (a mesh, solid to the floor) in a room, and a region in the desk's inner corner: the
-- mesh collides as its L, not as the rectangle round it, so the corner is reachable.
workspace { bounds = { { 0, 0 }, { 6, 6 } } }
robot { radius = 0.25, start = { 5, 1 } }
fixed { name = "desk", mesh = "../geometry/data/l_block.obj", center = { 2, 2 } }
region { name = "corner", rect = { { 2.9, 2.9 }, { 3.4, 3.4 } } }
task { formula = "F corner" }
