// linear_extrude lifted to exact 3D CSG: a square, a circle, a polygon with a hole, a 2D
// difference, a scaled (frustum) and a centred extrusion, a twisted one (triangle mesh with
// OpenSCAD's slices), and an extrusion standing flush on a cube, over a floor, two lights.
use <../scadray.scad>

$fn = 48;
camera(location=[2, -26, 17], look_at=[0, 1, 1.5], fov=52);
point_light(position=[-10, -16, 24]);
point_light(position=[18, -6, 12], color=[0.3, 0.3, 0.3]);
background(color=[0.22, 0.24, 0.3]);

material(color=[0.82, 0.82, 0.78], ambient=0.1, diffuse=0.7)
    translate([-14, -7, -1]) cube([28, 17, 1]);

// Square and circle
material(color="tomato") translate([-11, -4, 0]) linear_extrude(2) square([3, 2]);
material(color="gold", phong=0.4) translate([-5.5, -3, 0]) linear_extrude(height=3) circle(r=1.3);

// Polygon with a hole (paths), non-convex outline
material(color="seagreen") translate([-2, -5, 0]) linear_extrude(1.5)
    polygon([[0, 0], [4, 0], [4, 3.4], [2, 2.8], [0, 3.4], [1, 1], [3, 1], [3, 2.5], [1, 2.5]],
            [[0, 1, 2, 3, 4], [5, 6, 7, 8]]);

// 2D difference: a plate with round holes
material(color="steelblue", specular=0.3) translate([4, -5, 0]) linear_extrude(1)
    difference() {
        square([5, 3.5]);
        for (x = [1.2, 2.5, 3.8]) translate([x, 1.75]) circle(r=0.5);
    }

// Scaled extrusion (a frustum) and a centred one lifted off the floor
material(color="orchid") translate([-9, 4, 0]) linear_extrude(height=4, scale=0.4)
    square(3, center=true);
material(color="darkorange") translate([-3.5, 4, 2]) linear_extrude(height=4, center=true)
    polygon([[-1.5, -1], [1.5, -1], [0, 1.6]]);

// Twisted extrusion: a triangle mesh with OpenSCAD's slices and diagonals
material(color="mediumpurple", phong=0.3) translate([2.5, 4, 0])
    linear_extrude(height=5, twist=120, $fn=16) square(2.4, center=true);

// An extrusion flush on a cube: coincident faces at z = 2
material(color="sandybrown") translate([7.5, 3, 0]) union() {
    cube([3, 3, 2]);
    translate([1.5, 1.5, 2]) linear_extrude(1.5) circle(r=1.2);
}
