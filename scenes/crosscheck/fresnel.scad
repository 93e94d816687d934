// Fresnel reflection (reflection [0, 1] with fresnel): weak facing the camera, strong at
// grazing angles, on opaque spheres of different ior and on a glossy floor.
use <../scadray.scad>

camera(location=[0, -18, 4], look_at=[0, 0, 1.5], fov=50);
point_light(position=[-6, -12, 14]);
background(color=[0.55, 0.7, 0.9]);

material(color=[0.2, 0.22, 0.25], ambient=0.1, diffuse=0.5, reflection=[0, 1], fresnel=true, ior=1.5)
    translate([-12, -8, -1]) cube([24, 20, 1]);
translate([-4, 0, 1.5]) material(color=[0.8, 0.1, 0.1], ambient=0.1, diffuse=0.6, reflection=[0, 1], fresnel=true, ior=1.33) sphere(r=1.5, $fn=64);
translate([0, 1, 1.5]) material(color=[0.1, 0.5, 0.1], ambient=0.1, diffuse=0.6, reflection=[0, 1], fresnel=true, ior=1.8) sphere(r=1.5, $fn=64);
translate([4, 0, 1.5]) material(color=[0.1, 0.2, 0.7], ambient=0.1, diffuse=0.6, reflection=[0.05, 1], fresnel=true, ior=2.5) sphere(r=1.5, $fn=64);
material(color="white", ambient=0.6, diffuse=0.3) translate([-2, 6, 0]) cube([4, 1, 3]);
