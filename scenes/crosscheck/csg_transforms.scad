// CSG under transforms: a difference under a non-uniform scale, a mirrored asymmetric part, a
// negative scale, a sheared multmatrix, and transforms inside CSG operands.
use <../scadray.scad>

$fn = 48;
camera(location=[2, -24, 14], look_at=[0, 0, 2], fov=50);
point_light(position=[-12, -18, 22]);
point_light(position=[18, -12, 10], color=[0.35, 0.35, 0.35]);
background(color=[0.2, 0.2, 0.25]);

material(color=[0.8, 0.82, 0.85], ambient=0.12) translate([-13, -8, -1]) cube([26, 18, 1]);

module part() difference() {
    cube([3, 2, 2]);
    translate([2.2, 1, 2]) sphere(r=1.2);
    translate([0.8, -1, 0.8]) rotate([-90, 0, 0]) cylinder(r=0.5, h=4);
}
material(color="goldenrod", phong=0.5) translate([-10, -1, 0]) scale([1.6, 1, 0.7]) part();
material(color="indianred") translate([-2, -1, 0]) mirror([1, 0, 0]) part();
material(color="cadetblue") translate([1, -1, 0]) scale([1, -1, 1]) translate([0, -2, 0]) part();
material(color="darkkhaki", specular=0.3)
    translate([6, 0, 0]) multmatrix([[1, 0, 0.6, 0], [0, 1, 0, 0], [0, 0, 1, 0]])
        difference() {
            translate([-1.5, -1.5, 0]) cube([3, 3, 3]);
            translate([0, 0, 1.5]) scale([1.5, 0.6, 1]) sphere(r=1.2);
        }
