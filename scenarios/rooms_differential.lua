-- Paper scenario A (rooms.lua) with a round differential-drive robot, TurtleBot-like: it drives only
-- along its heading (its wheels grip the floor sideways), turns at up to 90 deg/s and starts facing
-- north. Same hall, rooms, boxes and task: visit p1, then p2, then p3 or p4.

params.drive = "differential"
require "rooms"
-- What `physltl-studio test scenarios/` holds this scenario to (docs/testing.md); the goldens are in goldens/rooms_differential/.
expect { max_pushes = 8, max_motion_s = 72, max_bodies_moved = 3, tree = true, frames = { "last" } }
