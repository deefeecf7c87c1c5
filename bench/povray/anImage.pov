// anImage: textures/earth.jpg on the sphere's latitude/longitude map, bilinear (interpolate 2),
// decoded from sRGB to linear as raytex does. POV-Ray's spherical map (map_type 1) has north up
// but runs longitude the other way round than raytex, whose image (read at column 1 - u, with
// u from atan2(z, x)) is not mirrored seen from outside in its right-handed world; mirroring
// x in the pigment gives the same longitude everywhere (0 towards +x, 90 E towards -z).
#version 3.7;
#include "course.inc"
Course_Sphere(texture {
    pigment {
        image_map { jpeg "../../textures/earth.jpg" gamma srgb map_type 1 interpolate 2 }
        scale <-1, 1, 1>
    }
    Course_Finish(0.3, 32)
})
