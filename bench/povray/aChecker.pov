// aChecker on the sphere: raytex's 2D checker (squares 2) over the latitude/longitude map,
// 2 checks around and 2 from pole to pole; 0.9 grey where floor(2u) + floor(2v) is even,
// 0.1 grey where odd. POV-Ray's uv_mapping on a sphere has the same v and the same direction
// of u (from +x towards +z) but starts u at +x where raytex's u is 0.5 (it starts at -x), so
// the pattern is moved by half a turn: the same checks at the same places.
#version 3.7;
#include "course.inc"
Course_Sphere(texture {
    uv_mapping
    pigment { checker rgb 0.9, rgb 0.1 scale 0.5 translate <0.5, 0, 0> }
    Course_Finish(0.1, 20)
})
