// color(): names, hex, vectors, alpha (transmit without refraction), and the outermost colour
// winning over inner ones, with overlapping translucent solids.
use <../scadray.scad>

camera(location=[0, -22, 11], look_at=[0, 0, 1.5], fov=50);
point_light(position=[-8, -16, 20]);
point_light(position=[14, -10, 8], color=[0.35, 0.35, 0.35]);
background(color=[0.3, 0.3, 0.3]);

color([0.9, 0.9, 0.85]) translate([-12, -7, -1]) cube([24, 16, 1]);

color("cornflowerblue") translate([-8, 0, 1.5]) sphere(r=1.5, $fn=48);
color("#c71585") translate([-4, 0, 0]) cube([3, 3, 3]);
color([0.2, 0.8, 0.3]) translate([1, 1, 0]) cylinder(r=1.5, h=3, $fn=48);
// Outermost colour wins: the box is orange, not green
color("orange") color("green") translate([4, -1, 0]) cube([2, 2, 2]);
// Translucent solids over each other and over the floor
color([1, 0.2, 0.2, 0.5]) translate([-2, -4, 1.2]) sphere(r=1.2, $fn=48);
color("yellow", 0.4) translate([-1.2, -4.5, 0]) cube([2, 2, 2]);
color("#3060ff80") translate([6, -3, 0]) cylinder(r=1.2, h=3, $fn=48);
