// Coincident faces as OpenSCAD users write them: a difference sharing the minuend's face, an
// intersection that is only a plane (empty), a union of touching boxes (no seams), a pocket
// flush with the top, and tangent spheres.
use <../scadray.scad>

camera(location=[3, -11, 7], look_at=[0, 0, 0.5], fov=50);
point_light(position=[-4, -6, 9], color=[0.8, 0.8, 0.8]);
point_light(position=[8, -3, 4], color=[0.3, 0.3, 0.3], shadowless=true);
background(color=[0.15, 0.15, 0.2]);

material(color=[0.85, 0.85, 0.8], ambient=0.15, diffuse=0.7) translate([-6, -4, -1]) cube([12, 9, 1]);
material(color=[0.9, 0.5, 0.2], ambient=0.15, diffuse=0.7) difference() {
    translate([-5, -1, 0]) cube([2, 2, 2]);
    translate([-5, -1, 0]) cube([1, 1, 2]);        // shares three faces
    translate([-4.5, -0.5, 1]) cube([1, 1, 1]);    // pocket flush with the top
}
material(color=[0.3, 0.6, 0.9], ambient=0.15, diffuse=0.7)
    intersection() { translate([-2, -1, 0]) cube(1); translate([-1, -1, 0]) cube(1); }  // a plane: nothing
material(color=[0.4, 0.8, 0.4], ambient=0.15, diffuse=0.7, phong=0.3)
    union() for (i = [0:3], j = [0:1]) translate([-1 + i * 0.5, -1 + j * 0.5, 0]) cube([0.5, 0.5, 1]);
material(color=[0.8, 0.3, 0.6], ambient=0.15, diffuse=0.7) {
    translate([2.5, 0, 0.8]) sphere(r=0.8);
    translate([4.1, 0, 0.8]) sphere(r=0.8);
    translate([3.3, 0, 0.8 + 0.8 * sqrt(3)]) sphere(r=0.8);
}
