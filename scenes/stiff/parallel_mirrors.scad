// Deep recursion between two parallel mirrors facing each other (an infinite corridor): every
// bounce must leave its mirror cleanly (no acne, no lost rays) up to max_trace_level 64.
use <../scadray.scad>

camera(location=[0.2, -2, 1.3], look_at=[-2, -1.7, 1.25], fov=60);
point_light(position=[0, -2, 4], color=[0.9, 0.9, 0.9]);
background(color=[0.2, 0.25, 0.3]);
render_settings(max_trace_level=64, adc_bailout=0.001);

material(color=[0.8, 0.8, 0.8], ambient=0.05, diffuse=0.05, reflection=0.95)
    translate([-2, -50, 0]) cube([0.1, 100, 3]);
material(color=[0.8, 0.8, 0.8], ambient=0.05, diffuse=0.05, reflection=0.95)
    translate([1.9, -50, 0]) cube([0.1, 100, 3]);
material(color=[0.7, 0.3, 0.2], ambient=0.2, diffuse=0.7) translate([-0.3, 0, 0.5]) sphere(r=0.4);
material(color=[0.85, 0.85, 0.8], ambient=0.2, diffuse=0.6) translate([-2, -50, -0.1]) cube([4, 100, 0.1]);
