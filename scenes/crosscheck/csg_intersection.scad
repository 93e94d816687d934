// Intersections: sphere with cube, a Steinmetz solid of three cylinders, intersection_for of
// rotated slabs, and an intersection under a transform.
use <../scadray.scad>

$fn = 64;
camera(location=[0, -22, 13], look_at=[0, 0, 1.8], fov=50);
point_light(position=[-10, -16, 24]);
point_light(position=[16, -10, 6], color=[0.3, 0.3, 0.3], shadowless=true);
background(color=[0.18, 0.2, 0.22]);

material(color=[0.82, 0.8, 0.76], ambient=0.12) translate([-12, -7, -1]) cube([24, 16, 1]);

material(color="lightcoral", phong=0.4) translate([-6, 0, 2]) intersection() {
    cube(3.2, center=true);
    sphere(r=2.1);
}
material(color="palegreen", specular=0.3) translate([0, 0, 2.1]) intersection() {
    cylinder(r=2, h=5, center=true);
    rotate([90, 0, 0]) cylinder(r=2, h=5, center=true);
    rotate([0, 90, 0]) cylinder(r=2, h=5, center=true);
}
material(color="lightskyblue") translate([6, 0, 2]) rotate([0, 0, 10])
    intersection_for(a = [0, 60, 120]) rotate([0, 0, a]) cube([6, 2.4, 3.6], center=true);
