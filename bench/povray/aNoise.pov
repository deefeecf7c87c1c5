// aNoise: raytex's noise, t = 0.5 + 0.5 noise(q), q = 8 x the solid coordinate = 2 p + 4:
// two noise lattice cells per world unit. POV-Ray's bozo is the same: one noise value mapped
// to [0, 1], here scaled by 1/2 (the +4 only moves the noise).
#version 3.7;
#include "course.inc"
Course_Sphere(texture {
    pigment {
        bozo
        color_map { [0 rgb <0.05, 0.1, 0.4>] [1 rgb <0.9, 0.9, 0.8>] }
        scale 0.5
    }
    Course_Finish(0.3, 32)
})
