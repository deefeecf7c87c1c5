// aDturbulence: raytex's derivative turbulence with POV-Ray's noise: t = 2.5 dturb(q, 6),
// q = 6 x the solid coordinate = 1.5 p + 3, dturb(q, n) = sum over i < n of
// (|noise(q 2^i)| / 2^i) / (1 + |D_i|^2), D_i = sum over j <= i of grad noise(q 2^j).
// POV-Ray has no noise gradient, so each octave takes it by forward differences: 4 noise values
// per octave where raytex computes the value and the gradient together.
#version 3.7;
#include "course.inc"
#include "functions.inc"   // f_noise3d: POV-Ray's noise, in [0, 1]

#declare DT_Noise = function(x, y, z) { 2 * f_noise3d(x, y, z) - 1 }
#declare DT_H = 1e-3;  // difference step, in noise cells

// One octave at amplitude Amp, in front of Next (the octaves after it): its noise value N and
// the slope sum D with its gradient, then Next at twice the frequency. (POV-Ray functions have no
// local variables: each intermediate value is a parameter of the next function.)
#macro DT_Octave(Next, Amp)
    #local Add = function(x, y, z, Dx, Dy, Dz, Acc, N) {
        Next(2 * x, 2 * y, 2 * z, Dx, Dy, Dz, Acc + Amp * abs(N) / (1 + Dx * Dx + Dy * Dy + Dz * Dz))
    }
    #local Slope = function(x, y, z, Dx, Dy, Dz, Acc, N) {
        Add(x, y, z, Dx + (DT_Noise(x + DT_H, y, z) - N) / DT_H, Dy + (DT_Noise(x, y + DT_H, z) - N) / DT_H,
            Dz + (DT_Noise(x, y, z + DT_H) - N) / DT_H, Acc, N)
    }
    function(x, y, z, Dx, Dy, Dz, Acc) { Slope(x, y, z, Dx, Dy, Dz, Acc, DT_Noise(x, y, z)) }
#end

// The octaves from i on: DT_i(q 2^i, D_(i-1), sum so far); the sum is complete after octave 5.
#declare DT_6 = function(x, y, z, Dx, Dy, Dz, Acc) { Acc }
#declare DT_5 = DT_Octave(DT_6, 1 / 32)
#declare DT_4 = DT_Octave(DT_5, 1 / 16)
#declare DT_3 = DT_Octave(DT_4, 1 / 8)
#declare DT_2 = DT_Octave(DT_3, 1 / 4)
#declare DT_1 = DT_Octave(DT_2, 1 / 2)
#declare DT_0 = DT_Octave(DT_1, 1)

Course_Sphere(texture {
    pigment {
        function { min(2.5 * DT_0(1.5 * x, 1.5 * y, 1.5 * z, 0, 0, 0, 0), 1) }  // clamped: above 1 it would wrap
        color_map { [0 rgb <0.95, 0.85, 0.6>] [1 rgb <0.3, 0.1, 0.05>] }
    }
    Course_Finish(0.3, 32)
})
