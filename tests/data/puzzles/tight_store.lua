-- Three boxes into a store two cells wide behind a two-cell door, in an order that keeps the door free.
-- Reference solution (the look-ahead's, one push per lattice step): 20 pushes: M1 +x 0.6 m, M3 -y 0.6
-- m, M1 -y 0.6 m, M1 +x 1.8 m, M2 -x 0.6 m, M2 -y 0.6 m, M1 -x 0.6 m, M3 -y 0.6 m, M1 +x 0.6 m, M2 +x
-- 1.2 m, M3 -y 0.6 m, M1 -y 1.2 m, M2 +x 1.2 m, M2 -y 1.2 m.
require "grid" {
  "#########",
  "#   #####",
  "# $ $   #",
  "#  @  $ #",
  "#   ##  #",
  "#   ##..#",
  "######. #",
  "     ####",
}
