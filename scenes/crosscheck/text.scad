// text() through the 2D machinery: a plate with a label engraved into it (its letters'
// counters left standing as islands) and a label embossed on a block, in Liberation Sans as
// OpenSCAD 2021.01 draws it, centred by halign and valign; a floor, two lights.
use <../scadray.scad>

camera(location=[0, -30, 26], look_at=[0, 1, 0], fov=48);
point_light(position=[-12, -18, 30]);
point_light(position=[20, -8, 14], color=[0.3, 0.3, 0.3]);
background(color=[0.2, 0.22, 0.28]);

material(color=[0.8, 0.8, 0.76], ambient=0.1, diffuse=0.7)
    translate([-16, -10, -1]) cube([32, 22, 1]);

// Engraved: the plate minus the text, 1 unit deep
material(color="steelblue", specular=0.3) translate([0, 4.5, 0]) difference() {
    translate([-13, -4, 0]) cube([26, 8, 2]);
    translate([0, 0, 1]) linear_extrude(2)
        text("scadray", size=5, halign="center", valign="center");
}

// Embossed: bold text standing 1.2 units on a block
material(color="goldenrod", phong=0.4) translate([0, -5, 0]) union() {
    translate([-11, -3.5, 0]) cube([22, 7, 1.5]);
    translate([0, 0, 1.5]) linear_extrude(1.2)
        text("TEXT 2D", size=4.2, font="Liberation Sans:style=Bold", halign="center",
             valign="center", spacing=1.1);
}
