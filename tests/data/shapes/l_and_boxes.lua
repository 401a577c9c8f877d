-- An L-shaped body of three cells and two boxes to their goals.
-- Reference solution (fewest pushes, one body a push): 25 pushes:
-- dRddRRRRRRRRurDlllllllluRRRRRRuurDldllllllluRRRRRRRR
require "grid" {
  "##############",
  "#@   #       #",
  "# $ LL     . #",
  "#   L     ll #",
  "#  $      l  #",
  "#   #      . #",
  "##############",
}
