-- A bar of three cells stands in the doorway: pushed out of the way first, then the box goes through.
-- Reference solution (fewest pushes, one body a push): 5 pushes: drrRlluRdddrruruuulDrdddllluuuRR
require "grid" {
  "##########",
  "#    #   #",
  "# @ $A . #",
  "#    A   #",
  "#    #   #",
  "#        #",
  "##########",
}
