// hull(): a capsule (two spheres), a cube and a cylinder joined into a ramp, a rotated cube
// with a tetrahedron, and a hull with a bore cut through it, over a floor, two lights.
use <../scadray.scad>

camera(location=[0, -26, 16], look_at=[0, 0, 1.5], fov=48);
point_light(position=[-12, -18, 24]);
point_light(position=[16, -6, 12], color=[0.3, 0.3, 0.3]);
background(color=[0.2, 0.25, 0.35]);

material(color=[0.85, 0.85, 0.8], ambient=0.1, diffuse=0.7) translate([-14, -8, -1]) cube([28, 18, 1]);

// Capsule: the hull of two faceted spheres
material(color="tomato", phong=0.5) translate([-9, -1, 1.6]) hull() {
    sphere(r=1.5, $fn=16);
    translate([0, 5, 1.5]) sphere(r=1.2, $fn=16);
}

// Ramp: a cube and a cylinder, with a colour inside that does not matter
material(color="seagreen") translate([-4, -2, 0.01]) hull() {
    color("blue") cube([3, 3, 0.5]);
    translate([1.5, 6, 0]) cylinder(r=1.5, h=3, $fn=12);
}

// A rotated cube and a tetrahedron
material(color="gold", phong=0.4, specular=0.2) translate([3, 0, 1.2]) hull() {
    rotate([20, 30, 15]) cube(2, center=true);
    translate([2.5, 1, -1.2]) polyhedron(points=[[0, 0, 0], [2, 0, 0], [0, 2, 0], [0, 0, 3]],
                                         faces=[[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);
}

// A hull in CSG: an octagonal frustum with a round bore
material(color="steelblue", specular=0.3) translate([10, 2, 0.01]) difference() {
    hull() {
        cylinder(r=2.2, h=0.5, $fn=8);
        translate([0, 0, 3]) cylinder(r=1.2, h=0.5, $fn=8);
    }
    translate([0, 0, -1]) cylinder(r=0.7, h=6, $fn=48);
}
