// Total internal reflection: right-angled prisms whose long face meets inner rays beyond the
// critical angle (41.8 degrees for ior 1.5), and a thick glass block seen at a grazing angle.
use <../scadray.scad>

camera(location=[-2, -14, 6], look_at=[0, 1, 1.5], fov=55);
point_light(position=[-10, -10, 16]);
point_light(position=[10, -10, 6], color=[0.3, 0.3, 0.3], shadowless=true);
background(color=[0.45, 0.55, 0.75]);
render_settings(max_trace_level=10);

for (i = [-4:3], j = [-2:4])
    material(color=(i + j) % 2 == 0 ? [0.95, 0.9, 0.8] : [0.6, 0.1, 0.1], ambient=0.2, diffuse=0.6)
        translate([i * 2.5, j * 2.5, -0.5]) cube([2.5, 2.5, 0.5]);

module prism(s) intersection() {
    cube([s, s, s]);
    rotate([0, 0, 45]) translate([-10, -10, -1]) cube([10 + s / sqrt(2), 20, s + 2]);
}
material(color=[0.95, 1, 0.95], transmit=0.9, ior=1.5, ambient=0, diffuse=0)
    translate([-5, -1, 0.2]) prism(3);
material(color=[1, 0.95, 0.9], transmit=0.9, ior=1.5, ambient=0, diffuse=0)
    translate([1, 0, 0.2]) rotate([0, 0, 180]) translate([-3, -3, 0]) prism(3);
material(color=[0.9, 0.95, 1], transmit=0.9, ior=1.6, ambient=0, diffuse=0)
    translate([3, 2, 0.2]) rotate([0, 0, -35]) cube([5, 1.5, 2]);
