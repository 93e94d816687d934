// Soft shadows from POV-Ray area lights without jitter: a 7 x 7 grid averaged recursively
// (adaptive 100, every grid point), and a 5 x 3 grid with adaptive 1 that subdivides only
// where neighbouring samples differ. Both renderers sample the same points, so the penumbrae
// must agree to rounding; a glass block shows filtered light in the penumbra.
use <../scadray.scad>

camera(location=[0, -17, 12], look_at=[0, 0, 1], fov=50);
area_light(position=[-3, -2, 12], axis1=[4, 0, 0], axis2=[0, 4, 0], samples=[7, 7], color=[0.7, 0.7, 0.7]);
area_light(position=[9, -6, 7], axis1=[0, 3, 0], axis2=[0, 0, 1.5], samples=[5, 3], adaptive=1,
           color=[0.35, 0.3, 0.25]);
background(color=[0.1, 0.1, 0.12]);

material(color=[0.9, 0.9, 0.88], ambient=0.1, diffuse=0.8) translate([-10, -7, -1]) cube([20, 15, 1]);
material(color=[0.8, 0.3, 0.2], ambient=0.1, diffuse=0.7) translate([-3, 1, 1.5]) sphere(r=1.5);
material(color=[0.3, 0.5, 0.9], ambient=0.1, diffuse=0.7) translate([2, -1, 0]) cylinder(r=0.6, h=4);
material(color=[0.4, 1, 0.5], filter=0.8, ior=1, ambient=0, diffuse=0.05)
    translate([4.5, 1.5, 0]) cube([1.5, 1.5, 2.5]);
