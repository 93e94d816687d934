// conserve_energy: transmitted light is scaled by (1 - reflectivity), with and without it,
// on reflective glass spheres.
use <../scadray.scad>

camera(location=[0, -16, 6], look_at=[0, 0, 1.6], fov=45);
point_light(position=[-6, -10, 14]);
background(color=[0.6, 0.7, 0.8]);

for (i = [-4:3], j = [-2:3])
    material(color=(i + j) % 2 == 0 ? [0.9, 0.9, 0.9] : [0.2, 0.6, 0.3], ambient=0.2, diffuse=0.6)
        translate([i * 2, j * 2, -0.5]) cube([2, 2, 0.5]);
translate([-2.2, 0, 1.6]) material(color=[1, 1, 1], transmit=0.9, ior=1.5, ambient=0, diffuse=0, reflection=0.4) sphere(r=1.6, $fn=64);
translate([2.2, 0, 1.6]) material(color=[1, 1, 1], transmit=0.9, ior=1.5, ambient=0, diffuse=0, reflection=0.4, conserve_energy=true) sphere(r=1.6, $fn=64);
