// A classic OpenSCAD-style parametric model with no ray-tracing metadata at all: it renders
// with the automatic camera (OpenSCAD's default view), default lights and OpenSCAD's default
// colour, and colours set with color().

teeth = 12;
thickness = 6;
radius = 20;
hole = 6;

module tooth(r, w, h) {
    translate([r, 0, 0]) rotate([0, 0, 45]) cube([w, w, h], center=true);
}

module wheel() {
    difference() {
        union() {
            cylinder(r=radius, h=thickness, center=true, $fn=96);
            for (i = [0:teeth - 1]) rotate([0, 0, i * 360 / teeth]) tooth(radius, 6, thickness);
        }
        cylinder(r=hole, h=thickness + 2, center=true, $fn=48);
        for (i = [0:5]) rotate([0, 0, i * 60 + 30]) translate([radius * 0.55, 0, 0])
            cylinder(r=3.5, h=thickness + 2, center=true, $fn=32);
    }
}

wheel();
color("silver") translate([0, 0, -12]) cylinder(r=hole - 0.5, h=24, $fn=48);
color([0.3, 0.45, 0.8]) translate([0, 0, -12]) difference() {
    cube([60, 30, 4], center=true);
    for (x = [-24, 24]) translate([x, 0, 0]) cylinder(r=3, h=6, center=true, $fn=32);
}
