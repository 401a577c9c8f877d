-- expect: 5: expect: 'robustness' needs an uncertainty { ... } block (or a body's own): in the model itself every world is the same and the plan succeeds in all
workspace { bounds = { { 0, 0 }, { 4, 3 } } }
robot { start = { 0.5, 0.5 } }
region { name = "goal", polygon = { { 3, 2 }, { 3.8, 2 }, { 3.8, 2.8 }, { 3, 2.8 } } }
expect { robustness = { worlds = 10, at_least = 0.5 } }
task { formula = "F goal" }
