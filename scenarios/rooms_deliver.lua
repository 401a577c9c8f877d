-- Paper scenario A (rooms.lua) with a task about an object: bring box B4, which blocks room 4's doorway,
-- into p4 in the room's far corner, and then visit p1 (through room 1's corridor, where B1 stands).
-- Purposeful manipulation: B4 is pushed to where the task needs it, not only out of the way.

params.task = params.task or "F(B4@p4 & F p1)"
require "rooms"
-- What `physltl-studio test scenarios/` holds this scenario to (docs/testing.md); the goldens are in goldens/rooms_deliver/.
expect { max_pushes = 4, max_motion_s = 28, max_bodies_moved = 2, tree = true, frames = { "last" } }
