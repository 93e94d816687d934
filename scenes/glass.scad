// Glass: a refracting sphere, a prism that totally reflects light inside it, and a tinted
// glass slab, over a checkered floor; shadows through glass are filtered, not black.
use <scadray.scad>

camera(location=[0, -24, 10], look_at=[0, 0, 2], fov=48);
point_light(position=[-8, -12, 20]);
point_light(position=[15, -20, 8], color=[0.3, 0.3, 0.3], shadowless=true);
background(color=[0.55, 0.65, 0.8]);
render_settings(max_trace_level=10);

for (i = [-7:6], j = [-4:6])
    material(color=(i + j) % 2 == 0 ? [0.95, 0.95, 0.9] : [0.7, 0.15, 0.1], ambient=0.15, diffuse=0.7)
        translate([i * 2, j * 2, -0.5]) cube([2, 2, 0.5]);

// Clear glass sphere with Fresnel reflection
material(color=[1, 1, 1], filter=0, transmit=0.95, ior=1.5, ambient=0, diffuse=0,
         reflection=[0, 1], fresnel=true, phong=0.8, phong_size=200)
    translate([-5, 0, 2.5]) sphere(r=2.5, $fn=64);

// Right-angled prism: light entering one short face meets the long face at 45 degrees and is
// totally reflected (the critical angle for ior 1.5 is 41.8 degrees)
material(color=[0.9, 1, 0.95], filter=0.1, transmit=0.85, ior=1.5, ambient=0, diffuse=0)
    translate([1, -1, 0]) intersection() {
        cube([4, 4, 4]);
        rotate([0, 0, 45]) translate([-10, -10, -1]) cube([10 + 4 / sqrt(2), 20, 6]);
    }

// Tinted slab: filter tints what is seen through it and the shadow it casts
material(color=[0.3, 0.5, 1], filter=0.8, transmit=0.1, ior=1.3, ambient=0, diffuse=0)
    translate([6, 1, 0]) rotate([0, 0, -20]) cube([0.6, 5, 4]);
