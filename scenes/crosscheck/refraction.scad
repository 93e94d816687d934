// Refraction with ior and the interior list: glass (1.5), water (1.33) and a diamond-like
// (2.42) solid, a glass sphere nested in a water sphere, and a glass slab, over a pattern.
use <../scadray.scad>

camera(location=[0, -20, 9], look_at=[0, 0, 1.5], fov=50);
point_light(position=[-8, -14, 18]);
point_light(position=[12, -6, 8], color=[0.3, 0.3, 0.3], shadowless=true);
background(color=[0.5, 0.55, 0.65]);
render_settings(max_trace_level=12);

for (i = [-5:4], j = [-3:4])
    material(color=(i + j) % 2 == 0 ? [0.9, 0.9, 0.85] : [0.15, 0.35, 0.6], ambient=0.2, diffuse=0.6)
        translate([i * 2.4, j * 2.4, -0.5]) cube([2.4, 2.4, 0.5]);

glass = [1, 1, 1];
translate([-7, 0, 1.6]) material(color=glass, transmit=0.96, ior=1.5, ambient=0, diffuse=0) sphere(r=1.5, $fn=64);
translate([-2.5, 0, 0.1]) material(color=[0.9, 0.95, 1], transmit=0.95, ior=1.33, ambient=0, diffuse=0) cylinder(r=1.4, h=3, $fn=64);
translate([2.5, 0, 1.8]) {
    material(color=glass, transmit=0.95, ior=1.33, ambient=0, diffuse=0) sphere(r=1.7, $fn=64);
    material(color=[1, 0.9, 0.9], transmit=0.95, ior=1.5, ambient=0, diffuse=0) sphere(r=0.8, $fn=64);
}
translate([6, -0.5, 0.1]) rotate([0, 0, 30]) material(color=glass, transmit=0.95, ior=2.42, ambient=0, diffuse=0) cube([2, 2, 2.5]);
