// User modules, children(), $fn passing and recursion.
module post(h = 3, r = 0.5) cylinder(h = h, r = r);
module row(n) for (i = [0:n - 1]) translate([i * 2, 0, 0]) children();
module twice() { children(0); translate([0, 0, 5]) children(0); }
module tree(depth) {
    cylinder(h = 2, r = depth * 0.2);
    if (depth > 1) translate([0, 0, 2]) { rotate([30, 0, 0]) tree(depth - 1); rotate([-30, 0, 0]) tree(depth - 1); }
}
module smooth() children();
row(3) post();
translate([0, 5, 0]) twice() post(h = 1);
translate([0, -5, 0]) tree(4);
smooth($fn = 24) sphere(2);
translate([10, 0, 0]) sphere(1, $fn = 7);
translate([10, 5, 0]) sphere(3, $fa = 5, $fs = 0.5);
module pick() children([0, 2]);
translate([-10, 0, 0]) pick() { cube(1); sphere(1); cylinder(h = 1, r = 1); }
