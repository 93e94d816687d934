// A closed mesh (polyhedron) as the subtrahend of a difference(): the cut face it leaves must
// be lit like any other, as a cube() cut is. Left: cut by a 40 mm polyhedron cube; right:
// the same cut by cube(40). Key light above.
use <../scadray.scad>

camera(location=[0, -60, 40], look_at=[0, 0, 2], fov=45);
point_light(position=[-10, -20, 60]);
point_light(position=[30, -30, 20], color=[0.25, 0.25, 0.25]);
background(color=[0.2, 0.22, 0.28]);

module box40() polyhedron(
    points=[[0, 0, 0], [40, 0, 0], [40, 40, 0], [0, 40, 0],
            [0, 0, 40], [40, 0, 40], [40, 40, 40], [0, 40, 40]],
    faces=[[0, 1, 2, 3], [4, 5, 1, 0], [7, 6, 5, 4], [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3]]);

material(color=[0.85, 0.85, 0.8], ambient=0.1) translate([-40, -20, -13]) cube([80, 40, 1]);

material(color="steelblue", phong=0.3) translate([-14, 0, 0]) difference() {
    sphere(12, $fn=64);
    translate([-20, -20, 4]) box40();
}
material(color="steelblue", phong=0.3) translate([14, 0, 0]) difference() {
    sphere(12, $fn=64);
    translate([-20, -20, 4]) cube(40);
}
