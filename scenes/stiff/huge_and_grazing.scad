// A ground that is a sphere of radius 1e7 (its top at z = 0), seen at grazing angles towards the
// horizon, with shadows of unit objects on it; a huge sphere is the classic source of acne when
// the intersection is solved with the textbook quadratic. Tangent spheres and a box grazed by
// the light complete it. FLAT = true swaps the ground for a box: the pictures must agree below
// the horizon (the metamorphic test renders both).
use <../scadray.scad>

FLAT = false;

camera(location=[0, -12, 0.6], look_at=[0, 0, 0.4], fov=60);
point_light(position=[-20, -6, 3], color=[0.85, 0.85, 0.85]);
point_light(position=[10, -10, 8], color=[0.25, 0.25, 0.25], shadowless=true);
background(color=[0.45, 0.55, 0.7]);

material(color=[0.8, 0.78, 0.7], ambient=0.15, diffuse=0.75)
    if (FLAT) translate([-1e3, -1e3, -1]) cube([2e3, 2e3, 1]);
    else translate([0, 0, -1e7]) sphere(r=1e7);
material(color=[0.8, 0.3, 0.2], ambient=0.15, diffuse=0.7) {
    translate([-2, 0, 1]) sphere(r=1);
    translate([0, 0, 1]) sphere(r=1);
}
material(color=[0.3, 0.5, 0.8], ambient=0.15, diffuse=0.7, phong=0.4) translate([2, -1, 0]) cube([2, 2, 1.5]);
