// import() of a DXF drawing and an SVG page, extruded, and surface() of a height map, over a
// floor, two lights: POV-Ray sees them as prisms and a mesh2 (assets/README.md).
use <../scadray.scad>

camera(location=[0, -34, 26], look_at=[0, 2, 1], fov=50);
point_light(position=[-12, -18, 24]);
point_light(position=[16, -6, 12], color=[0.3, 0.3, 0.3]);
background(color=[0.2, 0.25, 0.35]);

material(color=[0.85, 0.85, 0.8], ambient=0.1, diffuse=0.7) translate([-18, -10, -1]) cube([36, 24, 1]);

// The DXF's square less its hole, and its triangles
material(color="tomato", phong=0.4) translate([-16, -3, 0.01]) {
    linear_extrude(1.5) difference() {
        import("assets/shapes.dxf", layer="square");
        import("assets/shapes.dxf", layer="hole");
    }
    translate([0, -6]) linear_extrude(1) import("assets/shapes.dxf", layer="tri");
}

// An SVG page (unitless, 72 dpi), scaled down
material(color="gold", specular=0.2) translate([-3, 9, 0.01]) linear_extrude(1.2)
    scale(0.3) import("assets/basic.svg");

// A height map: 12 x 10 heights, centred, flattened
material(color="steelblue", phong=0.3) translate([11, -4.6, 0.01]) scale([1, 1, 0.8])
    surface("assets/bumps.dat", center=true);
