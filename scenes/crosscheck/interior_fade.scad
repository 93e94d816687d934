// Interior fade: light travelling inside tinted glass fades with distance
// (fade_distance, fade_power, fade_color), in what the camera sees and in shadows.
use <../scadray.scad>

camera(location=[0, -16, 8], look_at=[0, 0, 1.5], fov=50);
point_light(position=[-5, -8, 16]);
background(color=[0.8, 0.85, 0.9]);
render_settings(max_trace_level=8);

material(color=[0.95, 0.95, 0.95], ambient=0.15, diffuse=0.7) translate([-10, -6, -1]) cube([20, 14, 1]);
material(color=[1, 1, 1], transmit=1, ior=1.3, ambient=0, diffuse=0, fade_distance=1.5, fade_power=2, fade_color=[0.2, 0.6, 1])
    translate([-4, 0, 1.8]) sphere(r=1.8, $fn=64);
material(color=[1, 1, 1], transmit=1, ior=1.4, ambient=0, diffuse=0, fade_distance=2, fade_power=1001, fade_color=[1, 0.4, 0.1])
    translate([1, -1, 0.05]) cube([3.5, 2.5, 2.5]);
