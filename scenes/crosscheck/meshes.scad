// Meshes from .scad: a polyhedron (faces clockwise from outside, as OpenSCAD wants), an STL
// torus imported and cut by a sphere, an OFF frustum with heptagonal faces, and a glass torus
// refracting what is behind it.
use <../scadray.scad>

camera(location=[0, -16, 9], look_at=[0, 0, 0.8], fov=55);
point_light(position=[-6, -10, 14]);
point_light(position=[10, -6, 6], color=[0.3, 0.3, 0.3], shadowless=true);
background(color=[0.2, 0.22, 0.28]);
render_settings(max_trace_level=8);

material(color=[0.85, 0.85, 0.8], ambient=0.12) translate([-10, -6, -1]) cube([20, 14, 1]);

// Square pyramid
material(color="gold", phong=0.5, phong_size=40)
    translate([-6, 0, 0.01]) polyhedron(
        points=[[-1.2, -1.2, 0], [1.2, -1.2, 0], [1.2, 1.2, 0], [-1.2, 1.2, 0], [0, 0, 2.4]],
        faces=[[4, 1, 0], [4, 2, 1], [4, 3, 2], [4, 0, 3], [3, 0, 1], [3, 1, 2]]);

// Imported torus, cut open by a sphere
material(color="steelblue", specular=0.3, roughness=0.03)
    translate([-1.5, 0, 0.61]) difference() {
        import("assets/torus.stl");
        translate([1.4, -1.4, 0.3]) sphere(r=1.1, $fn=48);
    }

// Heptagonal frustum from OFF
material(color="indianred") translate([2.5, 2, 0.01]) import("assets/frustum.off");

// Glass torus
material(color=[1, 1, 1], transmit=0.92, ior=1.45, ambient=0, diffuse=0, reflection=[0, 1], fresnel=true)
    translate([4.5, -1.5, 0.61]) rotate([0, 0, 30]) import("assets/torus.stl");
