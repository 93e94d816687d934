// The default scene: OpenSCAD's classic logo solid (a cube intersected with a sphere, minus
// three cylinders), a glass sphere and a chrome sphere on a checkered floor.
use <scadray.scad>

camera(location=[17, -27, 13], look_at=[0, 0, 3.2], fov=46);
point_light(position=[-14, -22, 30], color=[0.85, 0.85, 0.85]);
point_light(position=[26, -6, 12], color=[0.3, 0.3, 0.3], shadowless=true);
background(color=[0.58, 0.68, 0.84]);
render_settings(max_trace_level=8);

// Floor of alternating tiles
for (i = [-8:7], j = [-6:7])
    material(color=(i + j) % 2 == 0 ? [0.92, 0.92, 0.9] : [0.25, 0.3, 0.4], ambient=0.15, diffuse=0.7)
        translate([i * 3, j * 3, -0.5]) cube([3, 3, 0.5]);

// The logo solid
material(color=[0.98, 0.84, 0.17], phong=0.5, phong_size=50)
translate([0, 0, 4]) rotate([0, 0, 20]) difference() {
    intersection() {
        cube(8, center=true);
        sphere(r=5.3, $fn=96);
    }
    for (r = [[0, 0, 0], [90, 0, 0], [0, 90, 0]]) rotate(r) cylinder(r=2.4, h=10, center=true, $fn=64);
}

// Glass sphere with Fresnel reflection
material(color=[1, 1, 1], transmit=0.95, ior=1.5, ambient=0, diffuse=0,
         reflection=[0, 1], fresnel=true, phong=0.9, phong_size=200)
    translate([-8, -3, 2.8]) sphere(r=2.8);

// Chrome sphere
material(color=[0.75, 0.75, 0.8], ambient=0, diffuse=0.1, reflection=0.8, phong=1, phong_size=150)
    translate([7.5, 4, 2.5]) sphere(r=2.5);
