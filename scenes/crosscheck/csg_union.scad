// Unions: overlapping solids of different colours fused into one solid, a union nested under
// a rotation, and a union of a union.
use <../scadray.scad>

camera(location=[4, -24, 12], look_at=[1, 0, 2], fov=45);
point_light(position=[-10, -20, 25]);
point_light(position=[18, -6, 8], color=[0.3, 0.3, 0.3], shadowless=true);
background(color=[0.15, 0.15, 0.2]);

material(color=[0.8, 0.8, 0.8], ambient=0.12) translate([-12, -8, -1]) cube([26, 18, 1]);

translate([-5, 0, 2]) union() {
    color("crimson") sphere(r=2);
    color("orange") translate([1.2, -0.5, 0.8]) sphere(r=1.5);
    color("khaki") translate([-1.5, 0, -1.9]) cube([3, 1.5, 1.5]);
}
translate([3, 1, 2.2]) rotate([0, 25, 35]) union() {
    color("royalblue") cube([4, 1.5, 1.5], center=true);
    color("skyblue") cube([1.5, 4, 1.5], center=true);
    union() {
        color("navy") cube([1.2, 1.2, 4], center=true);
        color("teal") translate([0, 0, 2.2]) sphere(r=0.8);
    }
}
