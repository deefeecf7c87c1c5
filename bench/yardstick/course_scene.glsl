// The yardstick tracer of the course scene (scenes/textures.cfg), written plainly to be the
// measure of raytex's kernel (bench/yardstick.cpp): everything the scene file says is a
// constant here, the sphere's texture is the including kernel's sphereAlbedo. One pixel per
// invocation, SAMPLES_PER_SIDE x SAMPLES_PER_SIDE samples at sub-pixel cell centres, box
// averaged; primary ray, closest of sphere and plane, Phong with one light and one shadow ray
// (sphere and plane tested). Shares no code with shaders/; the image is the one raytex renders
// for the same scene (same camera, mapping, texture and shading formulas), up to rounding.
//
// The including kernel declares, before #include:
//   const float SPHERE_KS, SPHERE_SHININESS;  // the sphere material's specular and exponent
// and defines after it:
//   vec3 sphereAlbedo(vec3 n);  // texture colour at unit outward normal n
#ifndef SAMPLES_PER_SIDE
#define SAMPLES_PER_SIDE 1
#endif

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0, rgba32f) uniform writeonly image2D outputImage;

const float PI = 3.14159265358979;

// scenes/textures.cfg
const vec3 EYE = vec3(0.0, 3.0, 12.0);
const vec3 LOOKAT = vec3(0.0, -0.5, 0.0);
const vec3 UP = vec3(0.0, 1.0, 0.0);
const float FOV_Y = 35.0;  // vertical, degrees; the aspect is the image's
const vec3 LIGHT_POSITION = vec3(-6.0, 10.0, 6.0);
const vec3 LIGHT_COLOR = vec3(1.0);
const vec3 BACKGROUND = vec3(0.05, 0.05, 0.08);
const vec3 AMBIENT_LIGHT = vec3(1.0);
const vec3 SPHERE_CENTER = vec3(0.0);
const float SPHERE_RADIUS = 2.0;
const float PLANE_Y = -2.0;  // normal (0, 1, 0), distance -2: tangent x, binormal z
const float TEX_SCALE = 5.0;

// Materials (scenes/texture_include.cfg): every one has ambient 0.15. The floor is aChecker:
// the checker kind's defaults (host/reference/texture.cpp), 0.9 and 0.1 grey, 2 x 2 checks per tile.
const float KA = 0.15;
const vec3 CHECKER_COLOR1 = vec3(0.9);
const vec3 CHECKER_COLOR2 = vec3(0.1);
const float CHECKER_SQUARES = 2.0;
const float PLANE_KS = 0.1;
const float PLANE_SHININESS = 20.0;

// Shadow rays start this far off the surface along the normal: every hit point here is within
// a few units of the origin or has a small rounding error along y (the plane), far below it.
const float SHADOW_OFFSET = 1.0e-3;

vec3 sphereAlbedo(vec3 n);

// Unit direction through `film` (pixels, row 0 at the top) of a pinhole camera.
vec3 primaryRay(vec2 film, vec2 size) {
  vec3 forward = normalize(LOOKAT - EYE);
  vec3 right = normalize(cross(forward, UP));
  vec3 up = cross(right, forward);
  float tanHalf = tan(radians(FOV_Y) * 0.5);
  vec2 ndc = vec2(film.x / size.x * 2.0 - 1.0, 1.0 - film.y / size.y * 2.0);
  return normalize(forward + (ndc.x * tanHalf * size.x / size.y) * right + (ndc.y * tanHalf) * up);
}

// Nearest t > 0 along unit d, or -1.
float hitSphere(vec3 o, vec3 d) {
  vec3 oc = o - SPHERE_CENTER;
  float b = dot(oc, d);
  float c = dot(oc, oc) - SPHERE_RADIUS * SPHERE_RADIUS;
  float disc = b * b - c;
  if (disc < 0.0) return -1.0;
  float s = sqrt(disc);
  return -b - s > 0.0 ? -b - s : -b + s;  // the far root when o is inside; negative if behind
}

float hitPlane(vec3 o, vec3 d) { return (PLANE_Y - o.y) / d.y; }  // <= 0 or inf or NaN: a miss

// Floor-based checker: parity of floor(u sq) + floor(v sq), u, v the offsets along the tangent
// and binormal in tex_scale units (docs/textures.md; with whole squares per tile the tile term
// is already in the floors).
vec3 planeAlbedo(vec3 p) {
  vec2 cell = floor(p.xz * (CHECKER_SQUARES / TEX_SCALE));
  return mod(cell.x + cell.y, 2.0) < 0.5 ? CHECKER_COLOR1 : CHECKER_COLOR2;
}

// Phong: ambient k_a albedo, plus diffuse albedo N.L and specular k_s (R.V)^shininess from the
// light when nothing lies between.
vec3 shade(vec3 p, vec3 n, vec3 toEye, vec3 albedo, float ks, float shininess) {
  vec3 color = AMBIENT_LIGHT * KA * albedo;
  vec3 toLight = LIGHT_POSITION - p;
  float dist = length(toLight);
  vec3 l = toLight / dist;
  float nDotL = dot(n, l);
  if (nDotL <= 0.0) return color;
  vec3 o = p + SHADOW_OFFSET * n;
  float ts = hitSphere(o, l), tp = hitPlane(o, l);
  if ((ts > 0.0 && ts < dist) || (tp > 0.0 && tp < dist)) return color;
  float rDotV = max(dot(reflect(-l, n), toEye), 0.0);
  return color + LIGHT_COLOR * (albedo * nDotL + ks * pow(rDotV, shininess));
}

vec3 radiance(vec2 film, vec2 size) {
  vec3 d = primaryRay(film, size);
  float ts = hitSphere(EYE, d), tp = hitPlane(EYE, d);
  if (ts > 0.0 && !(tp > 0.0 && tp < ts)) {
    vec3 n = (EYE + ts * d - SPHERE_CENTER) / SPHERE_RADIUS;
    return shade(SPHERE_CENTER + SPHERE_RADIUS * n, n, -d, sphereAlbedo(n), SPHERE_KS, SPHERE_SHININESS);
  }
  if (tp > 0.0) {
    vec3 p = EYE + tp * d;
    return shade(p, vec3(0.0, 1.0, 0.0), -d, planeAlbedo(p), PLANE_KS, PLANE_SHININESS);
  }
  return BACKGROUND;
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(outputImage);
  if (any(greaterThanEqual(pixel, size))) return;
  const int n = SAMPLES_PER_SIDE;
  vec3 sum = vec3(0.0);
  for (int sy = 0; sy < n; ++sy)
    for (int sx = 0; sx < n; ++sx)
      sum += radiance(vec2(pixel) + (vec2(sx, sy) + 0.5) / float(n), vec2(size));
  imageStore(outputImage, pixel, vec4(sum / float(n * n), 1.0));
}
