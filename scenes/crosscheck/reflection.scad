// Reflection: a full mirror, a mirror with reflection falloff between [min, max], a coloured
// reflection, reflection_exponent, and reflections of reflections.
use <../scadray.scad>

camera(location=[8, -16, 8], look_at=[0, 1, 2], fov=55);
point_light(position=[-8, -12, 18]);
point_light(position=[12, 4, 10], color=[0.3, 0.3, 0.3], shadowless=true);
background(color=[0.35, 0.45, 0.6]);
render_settings(max_trace_level=6);

material(color=[0.8, 0.8, 0.75], ambient=0.15, diffuse=0.65) translate([-10, -8, -1]) cube([20, 18, 1]);
material(color=[0, 0, 0], ambient=0, diffuse=0, reflection=1) translate([-8, 5, 0]) cube([16, 0.3, 6]);
material(color=[0.1, 0.1, 0.1], ambient=0, diffuse=0.1, reflection=[0.1, 0.9], reflection_falloff=2)
    translate([-3, 0, 1.6]) sphere(r=1.6, $fn=64);
material(color=[0.9, 0.6, 0.2], ambient=0.05, diffuse=0.2, reflection=0.6, reflection_exponent=2)
    translate([2, -1, 1.3]) sphere(r=1.3, $fn=64);
material(color="mediumseagreen", phong=0.4) translate([-1, -4, 0]) cylinder(r=0.8, h=2.5, $fn=48);
