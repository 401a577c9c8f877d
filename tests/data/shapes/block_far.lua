-- A 2x2 block down through a gap and along the lower room to its goal.
-- Reference solution (fewest pushes, one body a push): 20 pushes: dRRurDDDDDllddrRRRRRRRRRRRRR
require "grid" {
  "######################",
  "#                    #",
  "# @                  #",
  "#  CC  ###           #",
  "#  CC  #             #",
  "#      #  ############",
  "####                 #",
  "#                    #",
  "#   #             cc #",
  "#                 cc #",
  "######################",
}
