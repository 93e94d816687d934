// Exported by scadray from golden.scad
// The scene is right-handed with +Z up, as OpenSCAD's. Geometry is written in
// its own coordinates; the camera's negative `right` vector makes POV-Ray's
// look_at construction right-handed too.
// Render: povray <this file> +W640 +H480 -A +FN16 File_Gamma=1.0 -D -V -GR
// (or the .ini written beside it).
#version 3.7;

global_settings {
    assumed_gamma 1.0
    ambient_light rgb <1, 1, 1>
    max_trace_level 7
    adc_bailout 0.001
}

background { rgb <0.1, 0.2, 0.3> }

// camera: golden.scad:3:1
camera {
    perspective
    location <10, -20, 8>
    look_at <0, 0, 1>
    sky <0, 0, 1>
    up <0, 1, 0>
    right <-image_width / image_height, 0, 0>
    angle 35
}

// light: golden.scad:4:1
light_source {
    <5, -5, 10>, rgb <0.9, 0.8, 0.7>
    fade_distance 10
    fade_power 2
}
// light: golden.scad:5:1
light_source {
    <-5, -5, 5>, rgb <1, 1, 1>
    shadowless
}

// Materials: pigment explicit; finish terms that have an effect (ambient and diffuse
// always: POV-Ray's defaults differ)
// golden.scad:8:1
#declare Material_0 = texture {
    pigment { rgbft <1, 0, 0, 0, 0> }
    finish {
        ambient 0.15
        diffuse 0.75
        phong 0.5
        reflection {
            rgb <0.1, 0.1, 0.1>, rgb <0.6, 0.6, 0.6>
            fresnel on
        }
    }
}
// golden.scad:13:1
#declare Material_1 = texture {
    pigment { rgbft <1, 1, 1, 0, 0.9> }
    finish {
        ambient 0.15
        diffuse 0.75
    }
}

// Objects
difference {  // golden.scad:9:5
    box { <-1, -1, -1>, <1, 1, 1>  texture { Material_0 } }  // golden.scad:10:9
    cone { <0, 0, -1.5>, 0.5, <0, 0, 1.5>, 0.5  texture { Material_0 }
        matrix <0.7071067811865476, 0.7071067811865476, 0,  -0.7071067811865476, 0.7071067811865476, 0,  0, 0, 1,  0, 0, 0> }  // golden.scad:11:28
    interior { ior 1.3 }
}

merge {  // golden.scad:14:26
    sphere { <0, 0, 0>, 1  texture { Material_1 } }  // golden.scad:14:36
    sphere { <0, 0, 0>, 0.7  texture { Material_1 }
        translate <0, 0, 1> }  // golden.scad:14:68
    interior { ior 1.5 fade_distance 2 fade_power 1 fade_color rgb <0, 0, 0> }
    translate <3, 0, 1>
}

