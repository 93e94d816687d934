// Parts laid out for printing, as OpenSCAD users write it: one union() of a grid of nuts and
// pins, each a small CSG solid, none touching another. The render plan splits the union into
// its parts, so rays pay for span merging only inside the part they meet. A filament spool
// stands behind the camera: no ray can reach it (nothing reflects, the light is in front), so
// the plan drops it. `scadray render --plan scenes/print_plate.scad` shows both.
use <scadray.scad>

$fn = 32;

camera(location=[0, -125, 95], look_at=[0, 0, 0], fov=45);
point_light(position=[40, -30, 120], color=[0.85, 0.85, 0.85]);
point_light(position=[-80, -60, 40], color=[0.3, 0.3, 0.35], shadowless=true);
background(color=[0.2, 0.22, 0.25]);

module nut() difference() {
    cylinder(r=5, h=4);
    translate([0, 0, -1]) cylinder(r=2.6, h=6);
    // Chamfered top: a cone cut off the corners
    translate([0, 0, 2]) difference() {
        cylinder(r=6, h=3);
        translate([0, 0, -0.01]) cylinder(r1=6, r2=3.5, h=2.5);
    }
}

module pin() union() {
    cylinder(r=4.5, h=3.5);
    cylinder(r=2.5, h=18);
}

material(color="goldenrod", ambient=0.15, diffuse=0.65, phong=0.5, phong_size=50)
union() {
    for (i = [0:7], j = [0:5])
        translate([(i - 3.5) * 14, (j - 2.5) * 14, 0.5])
            if ((i + j) % 2 == 0) nut(); else pin();
}

// The build plate
material(color=[0.3, 0.3, 0.32], ambient=0.3, diffuse=0.6) translate([-62, -45, -2]) cube([124, 90, 2.5]);

// A filament spool behind the camera
material(color="steelblue", ambient=0.15, diffuse=0.7)
translate([0, -215, 100]) rotate([0, 90, 0]) difference() {
    cylinder(r=30, h=40, center=true);
    cylinder(r=10, h=42, center=true);
    for (s = [-1, 1]) translate([0, 0, s * 12]) difference() {
        cylinder(r=31, h=14, center=true);
        cylinder(r=20, h=16, center=true);
    }
}
