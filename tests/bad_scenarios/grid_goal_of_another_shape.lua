-- expect: 2: grid: the cells of goal 'a' are not the shape of body 'A'
require "grid" {
  "#########",
  "#@ AA   #",
  "#  A  a #",
  "#     aa#",
  "#########",
}
