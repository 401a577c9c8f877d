-- expect: 2: grid: the box size (0.6) must be a number above 0 and below the cell size (0.5)
require "grid" ({ "#####", "#@$.#", "#####" }, 0.5, 0.6)
