// Every primitive: sphere, cube (corner and centred, rotated), cylinder, cone (apex up and
// down) and frustum, over a floor, with two lights.
use <../scadray.scad>

camera(location=[0, -26, 14], look_at=[0, 0, 2], fov=50);
point_light(position=[-12, -18, 24]);
point_light(position=[20, -10, 10], color=[0.3, 0.3, 0.3]);
background(color=[0.2, 0.25, 0.35]);

material(color=[0.85, 0.85, 0.8], ambient=0.1, diffuse=0.7) translate([-14, -8, -1]) cube([28, 18, 1]);

material(color="tomato", phong=0.5) translate([-8, 0, 2]) sphere(r=2);
material(color="gold") translate([-4.5, -1.5, 0.01]) cube([3, 3, 3]);
material(color="orchid") translate([0, 4, 1.8]) rotate([20, 30, 40]) cube(2.5, center=true);
material(color="seagreen", specular=0.4) translate([1, -1, 0.01]) cylinder(r=1.5, h=4);
material(color="steelblue") translate([5, 1, 0.01]) cylinder(r1=1.8, r2=0, h=4.5);
material(color="darkorange") translate([9, -1, 0.01]) cylinder(r1=0.6, r2=1.8, h=3.5);
material(color="slategray") translate([5.5, 6, 0.01]) cylinder(r1=0, r2=1.5, h=3);
