// Soft shadows from a jittered area light: every grid point moves by up to half a cell. POV-Ray
// draws the jitter from its own table and scadray from each sample's seeded stream, so the two
// agree only statistically: the penumbra is the mean over many samples per pixel (the check
// supersamples POV-Ray 3 x 3 and averages scadray's batches).
use <../scadray.scad>

camera(location=[0, -15, 10], look_at=[0, 0, 1], fov=48);
area_light(position=[1, -1, 10], axis1=[5, 0, 0], axis2=[0, 5, 0], samples=[6, 6], jitter=true,
           color=[0.8, 0.8, 0.8]);
point_light(position=[-12, -12, 8], color=[0.15, 0.15, 0.15], shadowless=true);
background(color=[0.1, 0.1, 0.12]);

material(color=[0.9, 0.9, 0.88], ambient=0.1, diffuse=0.8) translate([-10, -7, -1]) cube([20, 15, 1]);
material(color=[0.9, 0.7, 0.2], ambient=0.1, diffuse=0.7) translate([-2, 0, 2]) sphere(r=1.4);
material(color=[0.3, 0.6, 0.9], ambient=0.1, diffuse=0.7) translate([2.5, -0.5, 0]) cube([1, 3, 3]);
