// aTurbulence: raytex's turbulence, t = 1.25 turb(q, 6), turb(q, n) = sum over i < n of
// |noise(q 2^i)| / 2^i, q = 6 x the solid coordinate = 1.5 p + 3. POV-Ray's granite pattern is
// that sum (6 octaves of |2 noise - 1|, each clamped to 0.5) at 4 x its point, so it is scaled
// by 4 / 1.5; the color_map reaches color2 at 1 / 1.25 = 0.8, where raytex's t is clamped to 1.
#version 3.7;
#include "course.inc"
Course_Sphere(texture {
    pigment {
        granite
        color_map { [0 rgb <0.95, 0.85, 0.6>] [0.8 rgb <0.3, 0.1, 0.05>] [1 rgb <0.3, 0.1, 0.05>] }
        scale 8 / 3
    }
    Course_Finish(0.3, 32)
})
