// A machined part in the OpenSCAD style: a rounded block minus a sphere, with through holes,
// a counterbored slot and an intersection-shaped boss; CSG nested under transforms.
use <scadray.scad>

$fn = 64;

camera(location=[55, -70, 60], look_at=[0, 0, 6], fov=38);
point_light(position=[60, -40, 120], color=[0.85, 0.85, 0.85]);
point_light(position=[-80, -60, 40], color=[0.3, 0.3, 0.35], shadowless=true);
background(color=[0.2, 0.22, 0.25]);

module hole(d, h) translate([0, 0, -1]) cylinder(d=d, h=h + 2);

material(color="lightsteelblue", ambient=0.15, diffuse=0.65, specular=0.4, roughness=0.02, metallic=0.5)
difference() {
    // Block with rounded vertical edges
    hull_free_block();
    // Spherical pocket
    translate([0, 0, 22]) sphere(r=14);
    // Four holes in the corners
    for (x = [-16, 16], y = [-11, 11]) translate([x, y, 0]) hole(5, 12);
    // Slot, counterbored
    translate([0, -14, 6]) rotate([90, 0, 0]) hole(6, 4);
}

// The boss: a cylinder intersected with a rotated cube, on a mirrored pair of arms
material(color="darkorange", phong=0.6, phong_size=60)
translate([0, 0, 12]) intersection() {
    cylinder(r=6, h=10);
    rotate([0, 0, 45]) translate([-5, -5, 0]) cube([10, 10, 10]);
}
for (m = [0, 1]) mirror([m, 0, 0])
    material(color="gray", ambient=0.2) translate([20, -3, 0]) cube([8, 6, 3]);

module hull_free_block() {
    r = 4;
    union() {
        translate([-20 + r, -15, 0]) cube([40 - 2 * r, 30, 12]);
        translate([-20, -15 + r, 0]) cube([40, 30 - 2 * r, 12]);
        for (x = [-20 + r, 20 - r], y = [-15 + r, 15 - r]) translate([x, y, 0]) cylinder(r=r, h=12);
    }
}

material(color=[0.5, 0.5, 0.5], ambient=0.3, diffuse=0.6) translate([-60, -60, -2]) cube([120, 120, 2]);
