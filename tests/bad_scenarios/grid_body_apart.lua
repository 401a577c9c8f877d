-- expect: 2: grid: the cells of body 'B' do not join side to side
require "grid" {
  "#########",
  "#@ B  b #",
  "#   B  b#",
  "#########",
}
