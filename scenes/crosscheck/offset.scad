// 2D shapes through OpenSCAD's Clipper engine, extruded: offset(r) with round joins,
// offset(delta) with mitred and chamfered corners, a negative offset that removes a thin bar
// and grows a hole, a self-intersecting star filled even-odd (a 2D union with discs over its
// crossings), and a twisted union of two
// overlapping squares (swept as one outline), over a floor, two lights.
use <../scadray.scad>

camera(location=[2, -26, 17], look_at=[0, 1, 1.5], fov=52);
point_light(position=[-10, -16, 24]);
point_light(position=[18, -6, 12], color=[0.3, 0.3, 0.3]);
background(color=[0.22, 0.24, 0.3]);

material(color=[0.82, 0.82, 0.78], ambient=0.1, diffuse=0.7)
    translate([-14, -7, -1]) cube([28, 17, 1]);

// offset(r): a rounded L
material(color="tomato") translate([-11, -5, 0]) linear_extrude(2)
    offset(r=0.6, $fn=24) polygon([[0, 0], [4, 0], [4, 1], [1, 1], [1, 3.4], [0, 3.4]]);

// offset(delta): mitred, and chamfered
material(color="gold", phong=0.4) translate([-4.5, -4.5, 0]) linear_extrude(1.6)
    offset(delta=0.5) polygon([[0, 0], [3, 0.4], [1.2, 2.6]]);
material(color="seagreen") translate([1, -4.5, 0]) linear_extrude(1.2)
    offset(delta=0.5, chamfer=true) square([3, 2.4]);

// A negative offset: the thin bar goes, the hole grows
material(color="steelblue", specular=0.3) translate([6, -5, 0]) linear_extrude(1)
    offset(delta=-0.3) difference() {
        union() { square([5, 3.5]); translate([0, 3.5]) square([0.5, 1.5]); }
        translate([1.5, 1]) square([2, 1.5]);
    }

// A self-intersecting pentagram, filled even-odd: five points around an empty middle. Its
// pieces meet only at the crossings, which CGAL cannot take into the scene's union (OpenSCAD
// drops the mesh: "The given mesh is not closed!"), so small discs cover the crossings.
material(color="orchid") translate([-7, 5, 0]) linear_extrude(2.5) union() {
    polygon([for (i = [0:4]) 2.8 * [cos(90 + 144 * i), sin(90 + 144 * i)]]);
    for (i = [0:4]) rotate(126 + 72 * i) translate([1.07, 0]) circle(r=0.3, $fn=20);
}

// A twisted union: OpenSCAD sweeps the one outline of the two squares
material(color="mediumpurple", phong=0.3) translate([1, 5, 0])
    linear_extrude(height=4.5, twist=90, $fn=16) {
        square(2.6, center=true);
        translate([1, 1]) square(2, center=true);
    }

// Offset of an offset, flush on a cube: coincident faces at z = 2
material(color="sandybrown") translate([7.5, 3, 0]) union() {
    cube([3, 3, 2]);
    translate([1.5, 1.5, 2]) linear_extrude(1.5)
        offset(r=-0.4, $fn=16) offset(r=0.6, $fn=16) square(1.6, center=true);
}
