-- expect: 2: grid: row 2 is a number, not a string of cells
require "grid" { "#####", 7, "#####" }
