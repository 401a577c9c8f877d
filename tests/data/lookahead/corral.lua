-- A room below the robot's, reached only through a door one box wide. M2 stands in it under the door,
-- its goal beside it; M1 stands above the door, its goal two places west. Pushed down into the door, M1
-- closes the lower room off: from there it can be pushed down once more, M2 below it holds it, and the
-- robot never gets into the lower room again to push M2 onto its goal. No box is then frozen (from inside
-- the room the robot could push either) nor stands where it could never be pushed to its goal: the lower
-- room is a corral deadlock. The way: M1 west onto its goal, then into the lower room, M2 onto its goal.
require "grid" {
  "#######",
  "#   @ #",
  "#     #",
  "#. $  #",
  "### ###",
  "#     #",
  "# .$  #",
  "#######",
}
