// Circular and oriented area lights (POV-Ray's `circular` and `orient`): the grid is mapped onto
// a disc, and an oriented light turns its disc to face every shaded point, so a spherical lamp
// casts the same penumbra in every direction. No jitter: both renderers sample the same points.
use <../scadray.scad>

camera(location=[0, -16, 11], look_at=[0, 0, 1], fov=50);
area_light(position=[-4, 0, 9], axis1=[3, 0, 0], axis2=[0, 3, 0], samples=[5, 5], circular=true,
           color=[0.5, 0.5, 0.5]);
area_light(position=[7, -4, 4], axis1=[2, 0, 0], axis2=[0, 2, 0], samples=[4, 4], orient=true,
           color=[0.45, 0.4, 0.35]);
background(color=[0.1, 0.1, 0.12]);

material(color=[0.9, 0.9, 0.88], ambient=0.1, diffuse=0.8) translate([-10, -7, -1]) cube([20, 15, 1]);
material(color=[0.85, 0.85, 0.85], ambient=0.1, diffuse=0.7) translate([-4, 0, 3]) cylinder(r=0.4, h=1.2);
material(color=[0.9, 0.4, 0.3], ambient=0.1, diffuse=0.7) translate([1.5, 0.5, 1.2]) sphere(r=1.2);
material(color=[0.3, 0.7, 0.4], ambient=0.1, diffuse=0.7) translate([-5, -3, 0]) cube([1.5, 1.5, 1.5]);
