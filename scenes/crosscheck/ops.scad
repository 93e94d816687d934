// resize(), minkowski() and projection(): a resized faceted sphere, a box rounded by a
// Minkowski sum with a sphere, a 2D frame rounded by a circle and extruded, and the shadow
// and section of a drilled ball extruded into plates, a rounded plate with a bore, over a floor,
// two lights.
use <../scadray.scad>

camera(location=[0, -30, 20], look_at=[0, 0, 1.5], fov=50);
point_light(position=[-12, -18, 24]);
point_light(position=[16, -6, 12], color=[0.3, 0.3, 0.3]);
background(color=[0.2, 0.25, 0.35]);

material(color=[0.85, 0.85, 0.8], ambient=0.1, diffuse=0.7) translate([-16, -9, -1]) cube([32, 20, 1]);

// An egg: a $fn=10 sphere resized to its tessellated box, auto-scaled in y
material(color="tomato", phong=0.5) translate([-11, -3, 2.5]) resize([4, 0, 5], auto=[false, true, false])
    sphere(r=1, $fn=10);

// A rounded box: cube plus sphere
material(color="seagreen", phong=0.3) translate([-5, -4, 1]) minkowski() {
    cube([4, 3, 1.5]);
    sphere(r=1, $fn=12);
}

// A rounded frame: a 2D Minkowski sum with a circle, extruded
material(color="gold", specular=0.2) translate([3, -4, 0.01]) linear_extrude(1.5) minkowski() {
    difference() { square([6, 5]); translate([1.5, 1.5]) square([3, 2]); }
    circle(r=0.6, $fn=10);
}

module drilled() difference() {
    sphere(r=3, $fn=14);
    rotate([0, 90, 0]) cylinder(r=1.2, h=8, center=true, $fn=10);
    cylinder(r=1, h=8, center=true, $fn=10);
}

// The ball's shadow seen nearly along its bore, and its section, as plates
material(color="steelblue", specular=0.3) translate([-6, 6, 0.01]) linear_extrude(0.8)
    projection() rotate([8, 5, 0]) drilled();
material(color="orchid", specular=0.3) translate([5, 6, 0.01]) linear_extrude(1.2)
    projection(cut=true) rotate([30, 0, 0]) drilled();

// A rounded plate with a bore: a non-convex operand, summed as the plate moved by a point of
// the sphere and the hulls of the sphere with each convex piece of the plate's boundary
material(color="slategray", phong=0.4) translate([10.5, 2, 0.4]) minkowski() {
    difference() {
        cube([4, 3, 0.6]);
        translate([2, 1.5, -1]) cylinder(r=0.8, h=3, $fn=10);
    }
    sphere(r=0.4, $fn=8);
}
