// The pinhole camera: primary rays through film positions (pixel units, row 0 at the top).
#ifndef RAYTEX_CAMERA_GLSL
#define RAYTEX_CAMERA_GLSL

// Direction (not unit length) of the primary ray through `film`: enough for intersecting
// a plane, which only needs the ray's line.
vec3 primaryRayUnnormalized(vec2 film) {
  vec2 ndc = vec2(film.x / float(frame.width) * 2.0 - 1.0, 1.0 - film.y / float(frame.height) * 2.0);
  return frame.cameraForward.xyz + ndc.x * frame.cameraRight.xyz + ndc.y * frame.cameraUp.xyz;
}

// Unit direction of the primary ray through `film`.
vec3 primaryRay(vec2 film) { return normalize(primaryRayUnnormalized(film)); }

#endif  // RAYTEX_CAMERA_GLSL
