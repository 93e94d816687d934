// Coincident faces as OpenSCAD users write them: a difference sharing the top face, unions of
// touching boxes, an intersection that is only a plane (empty), and coplanar tops in a union.
// The comparison masks what is a convention rather than geometry.
use <../scadray.scad>

camera(location=[3, -20, 14], look_at=[0, 0, 1], fov=50);
point_light(position=[-9, -15, 22]);
point_light(position=[16, -8, 9], color=[0.3, 0.3, 0.3], shadowless=true);
background(color=[0.22, 0.24, 0.28]);

material(color=[0.85, 0.85, 0.82], ambient=0.12) translate([-12, -7, -1]) cube([24, 16, 1]);

// Pocket flush with the top face
material(color="salmon") translate([-8, -1.5, 0]) difference() {
    cube([4, 3, 2]);
    translate([1, 0.5, 1]) cube([2, 2, 1]);
}
// Touching boxes: they fuse without a seam
material(color="lightseagreen") translate([-2.5, -1.5, 0]) union() {
    cube([2, 3, 2]);
    translate([2, 0, 0]) cube([2, 3, 2]);
    translate([0, 0, 2]) cube([4, 3, 1]);
}
// Two boxes meeting in a plane intersect in nothing
material(color="red") translate([3, -1.5, 0]) intersection() {
    cube([2, 3, 2]);
    translate([2, 0, 0]) cube([2, 3, 2]);
}
// Coplanar tops of different colours
translate([4, -1.5, 0]) union() {
    color("plum") cube([2, 3, 1.5]);
    color("wheat") translate([1, 1, 0]) cube([3, 2, 1.5]);
}
