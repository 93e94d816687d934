// The lecture's CSG example: spheres A (centre (0,0,8), r 5), B ((0,0,9), r 3) and
// C ((0,-3,8), r 2), and four combinations of them side by side, each cut open at y < 0
// so the insides show: A+B+C, A-B (a hidden cavity), (B-A)*C (empty: B lies inside A),
// and A+(B*C).
use <scadray.scad>

$fn = 96;

camera(location=[21, -50, 30], look_at=[21, 0, 5], fov=62);
point_light(position=[-30, -60, 80], color=[0.9, 0.9, 0.9]);
point_light(position=[90, -60, 40], color=[0.35, 0.35, 0.35], shadowless=true);
background(color=[0.62, 0.72, 0.85]);

module A() sphere(r=5, $fn=$fn);
module B() translate([0, 0, 9]) sphere(r=3);
module C() translate([0, -3, 8]) sphere(r=2);
module spheresAt(z=0) translate([0, 0, z - 8]) children();

// Removes the half y < 0 so internal surfaces are visible
module cutaway() difference() {
    children();
    translate([-10, -20, -10]) cube([20, 20, 30]);
}

module showcase(x, c) translate([x, 0, 0]) material(color=c, phong=0.4, phong_size=30) cutaway() children();

spheresAt(8) {
    showcase(0, "tomato") union() { translate([0, 0, 8]) A(); B(); C(); }
    showcase(14, "gold") difference() { translate([0, 0, 8]) A(); B(); }
    showcase(28, "seagreen") intersection() { difference() { B(); translate([0, 0, 8]) A(); } C(); }
    showcase(42, "steelblue") union() { translate([0, 0, 8]) A(); intersection() { B(); C(); } }
}

// Floor
material(color=[0.9, 0.9, 0.88], ambient=0.2, diffuse=0.7)
    translate([-30, -40, -1]) cube([110, 80, 1]);
