// aSolidChecker: raytex's solid_checker (squares 4 over the solid coordinate p/4 + 0.5):
// unit cubes in world space, (0.9, 0.1, 0.1) red where floor(x) + floor(y) + floor(z) is even,
// 0.9 grey where odd. POV-Ray's checker is the same pattern.
#version 3.7;
#include "course.inc"
Course_Sphere(texture {
    pigment { checker rgb <0.9, 0.1, 0.1>, rgb 0.9 }
    Course_Finish(0.4, 48)
})
