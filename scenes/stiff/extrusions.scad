// Stiff cases of OpenSCAD's 2D subset and extrusions, with every length (the 2D shapes too,
// not only a 3D scale around them) multiplied by S and the scene moved by T, so the picture
// must not change with them (tests/integration/stiff_scenes_test.cpp renders S = 1e-6 and
// 1e6). A 10,000-vertex polygon, collinear and repeated points, a
// 0-height extrusion (empty), scale=0 (a pyramid and a cone to a point), twist=3600, a
// linear_extrude flush with a cube, a horn torus (a circle touching the axis) and a lathe
// with a profile on the axis.
use <../scadray.scad>

S = 1;
T = [0, 0, 0];

translate(T) scale(S) {
    camera(location=[4, -30, 20], look_at=[0, 0, 2], fov=44);
    point_light(position=[-12, -14, 26], color=[0.8, 0.8, 0.8]);
    point_light(position=[18, -6, 10], color=[0.3, 0.3, 0.3], shadowless=true);
    material(color=[0.85, 0.85, 0.8], ambient=0.15, diffuse=0.7) translate([-15, -8, -1]) cube([30, 18, 1]);
}

module placed(p) translate(T) translate(S * p) children();

// 10,000 vertices: a wavy ring
material(color="steelblue", ambient=0.12, diffuse=0.7) placed([-10, -3, 0])
    linear_extrude(S * 2)
        polygon([for (i = [0 : 9999]) let(a = 360 * i / 10000, r = S * (3 + 0.25 * sin(40 * a)))
                 [r * cos(a), r * sin(a)]]);

// Collinear and repeated points. Polygons crossing or touching themselves are left out
// here: OpenSCAD's Clipper pieces of them touch at a point, which its CGAL refuses in a union
// ("The given mesh is not closed!") and drops (tests/importers/scad cover them)
material(color="tomato", ambient=0.12, diffuse=0.7) placed([-4, -6, 0]) linear_extrude(S * 1.5)
    polygon(S * [[0, 0], [1, 0], [1, 0], [2, 0], [3, 0], [3, 3], [3, 3], [1.5, 1.5], [0, 3], [0, 1.5]]);

// Empty (height 0), a pyramid and a cone to a point (scale = 0)
placed([2, -6, 0]) linear_extrude(0) square(S * 2);
material(color="gold", ambient=0.12, diffuse=0.7, phong=0.4) placed([4, -6, 0])
    linear_extrude(height=S * 4, scale=0) square(S * 2.5);
material(color="orchid", ambient=0.12, diffuse=0.7) placed([10, -5, 0])
    linear_extrude(height=S * 5, scale=0) circle(S * 1.5, $fn=40);

// Ten full turns of twist ($fn: a slice count that does not depend on the size, as $fs's does)
material(color="seagreen", ambient=0.12, diffuse=0.7) placed([-8, 5, 0])
    linear_extrude(height=S * 8, twist=3600, $fn=12) square(S * [3, 1.2], center=true);

// Flush with a cube: the extrusion's bottom face lies in the cube's top face
material(color="slategray", ambient=0.12, diffuse=0.7) placed([-2, 4, 0]) {
    cube(S * [4, 4, 1]);
    translate(S * [0, 0, 1]) linear_extrude(S * 2) polygon(S * [[0, 0], [4, 0], [4, 4], [2, 1.5], [0, 4]]);
}

// A horn torus and a lathe whose profile has an edge on the axis (at S = 1e-6 the profile is
// below OpenSCAD's 2D grid, which a warning says)
material(color="chocolate", ambient=0.12, diffuse=0.7, phong=0.3) placed([6, 5, 1.5])
    rotate_extrude() translate(S * [1.5, 0]) circle(S * 1.5);
material(color="darkkhaki", ambient=0.12, diffuse=0.7) placed([11, 4, 0])
    rotate_extrude() polygon(S * [[0, 0], [2, 0], [1, 1.5], [1.8, 3], [0, 3]]);
