// hull() of 2D children, extruded: a stadium (two circles), a circle joined to a square, a
// hull of rotated and scaled children with a nested hull, a hull of a polygon with a hole
// (the hole does not matter), and a top-level 2D hull drawn as a preview plate, over a floor,
// two lights.
use <../scadray.scad>

$fn = 40;
camera(location=[0, -26, 16], look_at=[0, 0, 1.5], fov=48);
point_light(position=[-12, -18, 24]);
point_light(position=[16, -6, 12], color=[0.3, 0.3, 0.3]);
background(color=[0.2, 0.25, 0.35]);

material(color=[0.85, 0.85, 0.8], ambient=0.1, diffuse=0.7)
    translate([-14, -8, -1]) cube([28, 18, 1]);

// Stadium: the hull of two circles
material(color="tomato", phong=0.5) translate([-10, -4, 0]) linear_extrude(2) hull() {
    circle(r=1.5);
    translate([0, 5]) circle(r=1);
}

// A circle and a translated square
material(color="seagreen") translate([-5, -3, 0]) linear_extrude(1.5) hull() {
    circle(r=1.6);
    translate([2, 1]) square(2.5);
}

// Rotated and scaled children, one of them a nested hull; extruded to a frustum
material(color="gold", phong=0.4, specular=0.2) translate([2, -3, 0])
    linear_extrude(height=3, scale=0.6) hull() {
        rotate(30) square([3, 1]);
        translate([1, 3]) scale([1.5, 0.6]) circle(r=1, $fn=10);
        hull() { translate([4, 0]) square(0.5); translate([4, 2]) circle(r=0.4, $fn=8); }
    }

// A polygon with a hole: the hull fills it
material(color="steelblue", specular=0.3) translate([7, -4, 0]) linear_extrude(1) hull() {
    polygon([[0, 0], [4, 0], [4, 4], [0, 4], [1, 1], [3, 1], [3, 3], [1, 3]],
            [[0, 1, 2, 3], [4, 5, 6, 7]]);
    translate([2, 5]) circle(r=0.8);
}

// A top-level 2D hull: a plate 1 unit thick, centred on z = 3
material(color="orchid") translate([-4, 5, 3]) hull() {
    square(2);
    translate([5, 1]) circle(r=1.2);
}
