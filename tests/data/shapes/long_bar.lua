-- A bar of five cells along the top, down through a gap of its width and back along the bottom.
-- Reference solution (fewest pushes, one body a push): 20 pushes: dRRRRRRRRRurDDDDrrrrrdLLLLLLL
require "grid" {
  "###################",
  "#@                #",
  "# AAAAA           #",
  "#                 #",
  "###########     ###",
  "#                 #",
  "#   aaaaa         #",
  "#                 #",
  "###################",
}
