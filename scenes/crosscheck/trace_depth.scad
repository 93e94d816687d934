// Trace depth: two parallel mirrors facing each other; max_trace_level cuts the series of
// reflections (refused rays are black, not background) and adc_bailout stops faint ones.
use <../scadray.scad>

camera(location=[0, -3.8, 2.5], look_at=[0.6, 4, 1.8], fov=60);
point_light(position=[0, -2, 5]);
background(color=[0.3, 0.4, 0.5]);
render_settings(max_trace_level=4, adc_bailout=0.05);

material(color=[0.8, 0.8, 0.8], ambient=0.15, diffuse=0.6) translate([-6, -6, -1]) cube([12, 12, 1]);
material(color=[0.05, 0.05, 0.05], ambient=0, diffuse=0, reflection=0.85) {
    translate([-3.2, -5, 0]) cube([0.2, 10, 4]);
    translate([3, -5, 0]) cube([0.2, 10, 4]);
}
material(color="tomato", phong=0.5) translate([0, 1, 1]) sphere(r=1, $fn=48);
material(color="royalblue") translate([1.2, -1, 0]) cylinder(r=0.4, h=2.5, $fn=32);
