// Several coloured point lights close to a floor, with POV-Ray's fade (2 / (1 + (d/D)^p)),
// one of them shadowless (no shadow, no highlights).
use <../scadray.scad>

camera(location=[0, -18, 12], look_at=[0, 0, 0], fov=55);
point_light(position=[-5, -2, 3], color=[1, 0.3, 0.2], fade_distance=3, fade_power=2);
point_light(position=[5, -1, 2.5], color=[0.2, 0.5, 1], fade_distance=4, fade_power=1);
point_light(position=[0, 4, 4], color=[0.3, 1, 0.4], fade_distance=2, fade_power=3, shadowless=true);
point_light(position=[0, -12, 20], color=[0.15, 0.15, 0.15]);
background(color=[0, 0, 0]);

material(color=[0.9, 0.9, 0.9], ambient=0.05, diffuse=0.8) translate([-12, -8, -1]) cube([24, 18, 1]);
material(color=[1, 1, 1], ambient=0.05, diffuse=0.7, phong=0.6, phong_size=30) {
    translate([-2, 0, 1]) sphere(r=1, $fn=48);
    translate([2, 0.5, 0]) cylinder(r=0.8, h=2.5, $fn=48);
    translate([0, 3, 0]) cube([1.2, 1.2, 1.2]);
}
