// Differences, nested: a block minus a sphere minus through holes, a tube (cylinder minus
// cylinder) cut by a rotated slab, and a difference inside a difference.
use <../scadray.scad>

$fn = 64;
camera(location=[10, -22, 16], look_at=[1, 0, 1.5], fov=48);
point_light(position=[-8, -18, 26]);
point_light(position=[20, 5, 10], color=[0.35, 0.35, 0.35]);
background(color=[0.25, 0.22, 0.2]);

material(color=[0.75, 0.78, 0.8], ambient=0.12) translate([-12, -8, -1]) cube([24, 18, 1]);

material(color="sandybrown", phong=0.3) translate([-5, 0, 0]) difference() {
    translate([-2.5, -2.5, 0]) cube([5, 5, 5]);
    translate([0, 0, 5]) sphere(r=2.6);
    translate([0, 0, 2]) rotate([90, 0, 0]) cylinder(r=0.8, h=8, center=true);
    translate([0, 0, 2]) rotate([0, 90, 0]) cylinder(r=0.8, h=8, center=true);
}
material(color="mediumpurple") translate([3, 0, 0]) difference() {
    cylinder(r=2.5, h=5);
    translate([0, 0, -1]) cylinder(r=1.6, h=7);
    translate([0, 0, 3.5]) rotate([30, 0, 20]) translate([-4, -4, 0]) cube([8, 8, 3]);
    difference() {
        translate([-3, -3.5, -1]) cube([2.5, 2, 3]);
        translate([-1.7, -2.5, 0.5]) sphere(r=1.1);
    }
}
