-- Paper scenario A (rooms.lua) with a round differential-drive robot, TurtleBot-like: it drives only
-- along its heading (its wheels grip the floor sideways), turns at up to 90 deg/s and starts facing
-- north. Same hall, rooms, boxes and task: visit p1, then p2, then p3 or p4.

params.drive = "differential"
require "rooms"
