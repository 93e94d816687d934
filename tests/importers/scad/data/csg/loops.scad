// for / intersection_for / if / let in the module context.
for (i = [0:3]) translate([i * 2, 0, 0]) cube(1);
for (p = [[0, 0, 5], [1, 2, 5], [3, 1, 5]]) translate(p) sphere(0.5);
for (i = [0:1], j = [0:2]) translate([i, j, 10]) cube(0.5);
for (a = [0:45:359]) rotate(a) translate([5, 0, 0]) cylinder(h = 1, r = 0.3);
intersection_for (n = [0:2]) rotate([0, 0, n * 60]) cube([4, 1, 1], center = true);
for (i = [0:4]) if (i % 2 == 0) translate([0, i, -5]) cube(1); else translate([0, i, -5]) sphere(0.5);
let (s = 3, t = s * 2) translate([t, t, t]) cube(s);
for (i = []) cube(100);
for (i = [0:9999]) cube(100);
