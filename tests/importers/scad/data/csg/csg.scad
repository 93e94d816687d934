// CSG operations and the null-vs-empty child rule of difference().
difference() { cube(10, center = true); sphere(6); }
translate([20, 0, 0]) union() { cube(5); translate([2, 2, 2]) sphere(3); }
translate([40, 0, 0]) intersection() { cube(5, center = true); sphere(3.2); }
translate([0, 20, 0]) difference() { if (false) cube(5); sphere(1); }
translate([0, 40, 0]) difference() { for (i = []) cube(5); sphere(1); }
translate([0, 60, 0]) difference() { echo("x"); sphere(1); }
translate([0, 80, 0]) difference() { union() {} sphere(1); }
translate([0, 100, 0]) difference() { cube(0); sphere(1); }
translate([0, 120, 0]) difference() { %cube(3); sphere(1); }
translate([0, 140, 0]) difference() { *cube(3); sphere(1); }
translate([20, 20, 0]) render() difference() { cube(4); #translate([1, 1, -1]) cylinder(h = 6, r = 1); }
translate([40, 40, 0]) group() { cube(1); sphere(1); }
