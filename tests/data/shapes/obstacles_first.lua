-- An L and a domino the task does not name stand in the box's row: both parked first.
-- Reference solution (fewest pushes, one body a push): 20 pushes: drRurDRRddrUdrUllullldRRRRRRRRRRRRRR
require "grid" {
  "###################",
  "#@   #            #",
  "#  $ XX           #",
  "#    X  YY        .",
  "#   ##            #",
  "#     #############",
  "#    #             ",
  "######             ",
}
