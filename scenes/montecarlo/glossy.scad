// Monte Carlo effects POV-Ray 3.7 lacks: glossy reflection in three spreads and both lobe
// shapes, soft shadows from a jittered area light. Render with several samples per pixel:
//   scadray render scenes/montecarlo/glossy.scad -s 16
use <../scadray.scad>

camera(location=[0, -15, 7], look_at=[0, 0, 1.5], fov=50);
area_light(position=[-4, -6, 12], axis1=[3, 0, 0], axis2=[0, 3, 0], samples=[4, 4], jitter=true,
           color=[0.8, 0.8, 0.8]);
point_light(position=[10, -12, 6], color=[0.2, 0.2, 0.2], shadowless=true);
background(color=[0.55, 0.65, 0.8]);

// Checkered floor, and a bright wall behind the spheres for them to reflect
for (i = [-5:4], j = [-3:4])
    material(color=(i + j) % 2 == 0 ? [0.9, 0.9, 0.88] : [0.3, 0.35, 0.45], ambient=0.15, diffuse=0.7)
        translate([i * 2.5, j * 2.5, -0.5]) cube([2.5, 2.5, 0.5]);
material(color=[0.9, 0.5, 0.2], ambient=0.3, diffuse=0.6) translate([-12, 6, 0]) cube([24, 0.5, 8]);

// Spheres from sharp to rough: 0, 3 and 10 degrees (normal lobe), 10 degrees (phong lobe)
for (k = [0:3])
    material(color=[0.8, 0.8, 0.85], ambient=0, diffuse=0.05, reflection=0.85,
             glossy=[0, 3, 10, 10][k], blur_lobe=k == 3 ? "phong" : "normal", blur_samples=8)
        translate([-6 + 4 * k, 0, 1.5]) sphere(r=1.5);
