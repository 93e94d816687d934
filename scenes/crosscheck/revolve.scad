// rotate_extrude as exact solids of revolution: a torus, a horn torus, a vase whose profile
// touches the axis (a lathe), a ring with a hole in its profile at 90, 180 and 270 degrees,
// a profile on the -X side, a clockwise sweep, a cube with a torus groove, a glass torus, and a
// faceted ($fn=6) ring, over a floor, two lights.
use <../scadray.scad>

camera(location=[3, -30, 19], look_at=[0, 1, 1.2], fov=50);
point_light(position=[-10, -16, 24]);
point_light(position=[18, -6, 12], color=[0.3, 0.3, 0.3]);
background(color=[0.22, 0.24, 0.3]);

material(color=[0.82, 0.82, 0.78], ambient=0.1, diffuse=0.7)
    translate([-15, -8, -1]) cube([30, 18, 1]);

// Tori
material(color="tomato", phong=0.4) translate([-11, -4, 0.7]) rotate_extrude() translate([1.6, 0]) circle(0.7);
material(color="gold", phong=0.3) translate([-6.5, -4, 1.2]) rotate_extrude() translate([1.2, 0]) circle(1.2);

// A vase: a lathe whose profile runs along the axis
material(color="seagreen", specular=0.3)
    translate([-2, -4, 0]) rotate_extrude()
        polygon([[0, 0], [1.6, 0], [1.8, 0.6], [1.1, 1.8], [1.0, 2.6], [1.5, 3.4], [1.3, 3.5],
                 [0.8, 2.7], [0.9, 1.8], [0, 1.2]]);

// Rings with a hole in the profile, partial turns
for (k = [0 : 2]) material(color=["steelblue", "orchid", "chocolate"][k])
    translate([3 + 4.2 * k, -4, 0]) rotate_extrude(angle=90 * (k + 1))
        polygon([[0.8, 0], [1.8, 0], [1.8, 1.4], [0.8, 1.4], [1.1, 0.3], [1.5, 0.3], [1.5, 1.1],
                 [1.1, 1.1]], [[0, 1, 2, 3], [4, 5, 6, 7]]);

// A profile on the -X side and a clockwise sweep
material(color="slateblue") translate([-10, 4, 0]) rotate_extrude(angle=200) translate([-2, 0]) square([0.8, 1.5]);
material(color="darkkhaki") translate([-5, 4, 0]) rotate_extrude(angle=-120) translate([0.6, 0]) square([1.4, 2]);

// A cube with a groove cut by a torus (the torus is flush with nothing), and a glass torus
material(color="lightslategray") translate([0, 4, 1.5]) difference() {
    cube(3, center=true);
    translate([0, 0, 1.5]) rotate_extrude() translate([1, 0]) circle(0.45);
}
material(color=[1, 1, 1], transmit=0.85, ior=1.5, ambient=0, diffuse=0.05, reflection=[0, 1], fresnel=true)
    translate([5, 4, 0.5]) rotate_extrude() translate([1.4, 0]) circle(0.5);

// Faceted: $fn = 6 at the rotate_extrude and the circle (drawn as OpenSCAD's mesh by --facets auto)
material(color="sandybrown") translate([10.5, 4, 0.8]) rotate_extrude($fn=6) translate([1.6, 0]) circle(0.8, $fn=6);
