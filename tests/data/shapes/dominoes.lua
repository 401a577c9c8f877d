-- Two dominoes, one upright and one lying, and a box, each to its goal.
-- Reference solution (fewest pushes, one body a push): 20 pushes:
-- dddrRRluuurDrRRRRRurDDDDllllluulDDuLLuulDDDD
require "grid" {
  "###############",
  "#@            #",
  "#   D EE      #",
  "#   D  #      #",
  "#  $   #      #",
  "#  ##         #",
  "#    .     ee #",
  "# d           #",
  "# d           #",
  "###############",
}
