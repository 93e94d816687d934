// Refraction at the edges of the model: glass of ior 1.0 (must vanish but for its reflection),
// ior 4 (total internal reflection almost everywhere inside), and a slab seen near the
// critical angle. (The hollow shell 1e-6 thick is in thin_shell.scad: POV-Ray cannot show it.)
use <../scadray.scad>

camera(location=[0, -12, 4], look_at=[0, 0, 1], fov=55);
point_light(position=[-5, -8, 10], color=[0.8, 0.8, 0.8]);
background(color=[0.3, 0.35, 0.45]);
render_settings(max_trace_level=16);

for (i = [-6:5], j = [-3:6])
    material(color=(i + j) % 2 == 0 ? [0.9, 0.9, 0.85] : [0.2, 0.3, 0.5], ambient=0.3, diffuse=0.6)
        translate([i, j, -0.1]) cube([1, 1, 0.1]);

material(color=[1, 1, 1], transmit=0.95, ior=1.0, ambient=0, diffuse=0, reflection=0.05)
    translate([-4, 0, 1]) sphere(r=1);
material(color=[1, 1, 1], transmit=0.95, ior=4, ambient=0, diffuse=0)
    translate([-1.3, 0, 1]) sphere(r=1);
// A slab tilted so the rays inside it meet its far face near the critical angle (41.8 deg)
material(color=[1, 1, 1], transmit=0.95, ior=1.5, ambient=0, diffuse=0)
    translate([4, 0, 0]) rotate([0, 0, 48]) translate([-0.1, -1.5, 0]) cube([0.2, 3, 2.5]);
