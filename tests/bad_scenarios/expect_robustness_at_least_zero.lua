-- expect: 6: 'at_least' is the share of worlds the plan must succeed in, more than 0 and at most 1, got 0
workspace { bounds = { { 0, 0 }, { 4, 3 } } }
robot { start = { 0.5, 0.5 } }
region { name = "goal", polygon = { { 3, 2 }, { 3.8, 2 }, { 3.8, 2.8 }, { 3, 2.8 } } }
task { formula = "F goal" }
expect { robustness = { at_least = 0 } }
uncertainty { start = 0.02 }
