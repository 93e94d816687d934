// A glass shell 1e-6 thick (a soap bubble): light crosses four surfaces and is shifted by about
// a millionth, so the checks behind it must show through undistorted, only dimmed by the four
// crossings. POV-Ray cannot show this: it drops intersections closer than 1e-6 to a ray's
// origin, misses the inner surface and refracts as through a solid ball. SHELL_IOR = 1 gives
// the same picture exactly (the metamorphic test renders both).
use <../scadray.scad>

SHELL_IOR = 1.5;
THICKNESS = 1e-6;

camera(location=[0, -8, 3], look_at=[0, 0, 1], fov=40);
point_light(position=[-5, -8, 10], color=[0.8, 0.8, 0.8]);
background(color=[0.3, 0.35, 0.45]);
render_settings(max_trace_level=16);

for (i = [-4:3], j = [-2:5])
    material(color=(i + j) % 2 == 0 ? [0.9, 0.9, 0.85] : [0.2, 0.3, 0.5], ambient=0.3, diffuse=0.6)
        translate([i, j, -0.1]) cube([1, 1, 0.1]);
material(color=[1, 1, 1], transmit=0.9, ior=SHELL_IOR, ambient=0, diffuse=0)
    translate([0, 0, 1.2]) difference() { sphere(r=1); sphere(r=1 - THICKNESS); }
