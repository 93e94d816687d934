// Benchmark scene (README, vista lists): 2,000 objects, a floor of 1,600 tiles and 400
// spheres on it, so a camera ray's walk down the scene's tree is long.
use <scadray.scad>
camera(location=[30, -60, 40], look_at=[0, 0, 0], fov=50);
point_light(position=[-30, -40, 80], color=[0.9, 0.9, 0.9]);
background(color=[0.6, 0.7, 0.8]);
for (i = [-20:19], j = [-20:19])
    material(color=(i + j) % 2 == 0 ? [0.9, 0.9, 0.9] : [0.3, 0.3, 0.5]) translate([i * 1.5, j * 1.5, 0]) cube([1.5, 1.5, 0.3]);
for (i = [-10:9], j = [-10:9])
    material(color=[0.8, 0.4, 0.2]) translate([i * 3 + 1.5, j * 3 + 1.5, 1.2]) sphere(r=0.9, $fn=24);
