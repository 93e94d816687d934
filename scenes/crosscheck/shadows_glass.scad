// Shadows through transparent solids: every surface crossed multiplies the light by
// colour*filter + transmit, so filtered glass casts coloured shadows and clear glass light ones;
// an opaque solid casts a black shadow. No refraction in shadow rays.
use <../scadray.scad>

camera(location=[0, -16, 14], look_at=[0, 0, 0.5], fov=52);
point_light(position=[2, -3, 16]);
point_light(position=[-14, -10, 8], color=[0.2, 0.2, 0.2], shadowless=true);
background(color=[0.1, 0.1, 0.12]);

material(color=[0.95, 0.95, 0.95], ambient=0.1, diffuse=0.8) translate([-10, -7, -1]) cube([20, 15, 1]);

material(color=[1, 0.3, 0.3], filter=0.9, ior=1, ambient=0, diffuse=0.1) translate([-5, 0, 3]) sphere(r=1.3, $fn=48);
material(color=[0.3, 0.5, 1], filter=0.6, transmit=0.3, ior=1.4, ambient=0, diffuse=0.05) translate([-1, 0, 2]) cube([2, 2, 2]);
material(color=[1, 1, 1], transmit=0.7, ior=1, ambient=0.02, diffuse=0.1) translate([3, 1, 3]) sphere(r=1.2, $fn=48);
material(color="dimgray", ambient=0.1) translate([5.5, -1, 2]) cube([1.5, 1.5, 0.5]);
