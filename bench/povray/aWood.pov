// aWood: raytex's wood with POV-Ray's noise: g = 8 r + 0.25 turb((q_x, q_y / 4, q_z), 4),
// t = fract(g)^2, q = 8 x the solid coordinate = 2 p + 4, r = |solid.xz - (0.5, 0.5)| = |p.xz| / 4:
// rings around the y axis, 2 per world unit of radius (the +4 only moves the noise). turb is
// Course_Turbulence (granite: 6 octaves where raytex sums 4; the two finest add at most
// 0.25 * (1/16 + 1/32) * 0.5 = 0.012 to g).
#version 3.7;
#include "course.inc"
#declare Wood_Profile = function(G) { pow(G - floor(G), 2) }  // fract(g)^2
Course_Sphere(texture {
    pigment {
        function { Wood_Profile(2 * sqrt(x * x + z * z) + 0.25 * Course_Turbulence(2 * x, 0.5 * y, 2 * z)) }
        color_map { [0 rgb <0.75, 0.5, 0.25>] [1 rgb <0.35, 0.18, 0.07>] }
    }
    Course_Finish(0.3, 24)
})
