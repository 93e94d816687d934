// Metamorphic stability scene: the whole scene (camera and lights included) is scaled by S and
// moved by T; the picture must not change. Render with -D S=1e-6, -D S=1e6, -D 'T=[1e6,1e6,0]'.
// Exercises CSG with coincident faces, tangent spheres, glass (refraction and total internal
// reflection), mirrors and shadows.
use <../scadray.scad>

S = 1;
T = [0, 0, 0];

translate(T) scale(S) {
    camera(location=[6, -14, 8], look_at=[0, 0, 1], fov=45);
    point_light(position=[-6, -8, 12], color=[0.8, 0.8, 0.8]);
    point_light(position=[10, -4, 5], color=[0.3, 0.3, 0.3], shadowless=true);

    material(color=[0.85, 0.85, 0.8], ambient=0.15, diffuse=0.7) translate([-8, -6, -1]) cube([16, 12, 1]);
    // A pocket flush with the top face, and a cut sharing a face with the block
    material(color=[0.9, 0.5, 0.2], ambient=0.15, diffuse=0.7, phong=0.4) difference() {
        translate([-5, -1, 0]) cube([4, 3, 2]);
        translate([-4, 0, 1]) cube([2, 1, 1]);
        translate([-5, -1, 0]) cube([1, 1, 2]);
    }
    // Tangent spheres
    material(color=[0.3, 0.5, 0.9], ambient=0.1, diffuse=0.7) {
        translate([1, 0, 1]) sphere(r=1);
        translate([3, 0, 1]) sphere(r=1);
    }
    // Glass and a mirror
    material(color=[1, 1, 1], transmit=0.9, ior=1.5, ambient=0, diffuse=0, reflection=[0, 1], fresnel=true)
        translate([0, -3, 1]) sphere(r=1);
    material(color=[0.8, 0.8, 0.8], ambient=0, diffuse=0.1, reflection=0.8) translate([5, 2, 0]) cube([0.2, 3, 3]);
}
