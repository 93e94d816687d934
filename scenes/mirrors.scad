// Mirrors: a flat mirror and a chrome sphere reflecting coloured solids and a checkered floor,
// with reflections of reflections up to max_trace_level.
use <scadray.scad>

camera(location=[14, -22, 9], look_at=[0, 2, 2.5], fov=50);
point_light(position=[10, -15, 25]);
point_light(position=[-20, -10, 10], color=[0.25, 0.25, 0.25], shadowless=true);
background(color=[0.05, 0.05, 0.12]);
render_settings(max_trace_level=8);

// Checkered floor made of tiles
for (i = [-6:5], j = [-6:5])
    material(color=(i + j) % 2 == 0 ? [0.9, 0.9, 0.9] : [0.15, 0.15, 0.2], ambient=0.1, diffuse=0.7)
        translate([i * 2, j * 2, -0.5]) cube([2, 2, 0.5]);

// A flat mirror standing at the back
material(color=[0.1, 0.1, 0.1], ambient=0, diffuse=0.05, reflection=0.9)
    translate([-9, 8, 0]) cube([18, 0.4, 9]);

// A chrome sphere
material(color=[0.8, 0.8, 0.85], ambient=0, diffuse=0.1, reflection=0.75, phong=1, phong_size=120)
    translate([2.5, 0, 2.5]) sphere(r=2.5, $fn=64);

// Coloured solids
material(color="crimson", phong=0.5, phong_size=40) translate([-4, -2, 0]) cylinder(r=1.5, h=4, $fn=48);
material(color="dodgerblue", specular=0.5, roughness=0.03) translate([-2, -6, 0]) rotate([0, 0, 30]) cube([2.5, 2.5, 2.5]);
material(color="limegreen", brilliance=2) translate([6, -5, 0]) cylinder(r1=1.5, r2=0, h=3.5, $fn=48);
