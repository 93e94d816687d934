// A plain OpenSCAD model with no ray-tracing data: automatic camera (OpenSCAD's default view,
// vertical field of view), default lights and OpenSCAD's default colour.
$fn = 48;
difference() {
    union() {
        cube([20, 12, 4]);
        translate([10, 6, 4]) cylinder(r=5, h=8);
    }
    translate([10, 6, -1]) cylinder(r=2.5, h=14);
    for (x = [3, 17]) translate([x, 6, -1]) cylinder(r=1.2, h=6);
}
color("steelblue") translate([-4, 2, 0]) sphere(r=2.5);
