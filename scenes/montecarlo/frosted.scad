// Frosted glass: refraction spread about the sharp refracted direction, beside clear glass of
// the same ior, in front of a striped wall; a glossy floor and soft shadows from a jittered
// circular area light. Render with several samples per pixel:
//   scadray render scenes/montecarlo/frosted.scad -s 16
use <../scadray.scad>

camera(location=[0, -14, 5], look_at=[0, 0, 2], fov=45);
area_light(position=[3, -8, 10], axis1=[2.5, 0, 0], axis2=[0, 2.5, 0], samples=[4, 4], jitter=true,
           circular=true, color=[0.85, 0.85, 0.85]);
background(color=[0.2, 0.2, 0.25]);
render_settings(max_trace_level=8);

// Stripes to look through
for (i = [-6:6])
    material(color=i % 2 == 0 ? [0.95, 0.95, 0.9] : [0.15, 0.2, 0.5], ambient=0.4, diffuse=0.5)
        translate([i * 1.2, 5, 0]) cube([1.2, 0.3, 7]);
material(color=[0.5, 0.5, 0.55], ambient=0.1, diffuse=0.6, reflection=0.3, glossy=6)
    translate([-10, -8, -0.5]) cube([20, 14, 0.5]);

// Clear, lightly frosted and heavily frosted slabs of glass (ior 1.5)
for (k = [0:2])
    material(color=[1, 1, 1], transmit=0.95, ior=1.5, ambient=0, diffuse=0, frosted=[0, 2, 8][k],
             blur_samples=8, phong=0.5, phong_size=100)
        translate([-5 + 3.5 * k, -1, 0]) cube([2.5, 0.8, 4]);
