// aMarble: raytex's marble with POV-Ray's noise: s = 0.5 + 0.5 sin(pi (q_x + q_y) +
// 6 turb(q, 6)), t = s^3, q = 4 x the solid coordinate = p + 2 (the +2 shifts the stripes by
// whole periods and only moves the noise). turb is Course_Turbulence (granite).
#version 3.7;
#include "course.inc"
Course_Sphere(texture {
    pigment {
        function { pow(0.5 + 0.5 * sin(pi * (x + y) + 6 * Course_Turbulence(x, y, z)), 3) }
        color_map { [0 rgb <0.9, 0.88, 0.85>] [1 rgb <0.15, 0.12, 0.2>] }
    }
    Course_Finish(0.5, 64)
})
