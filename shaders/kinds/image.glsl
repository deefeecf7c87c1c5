// image: a picture file at its own size, bilinear at the hit (point) or averaged over the
// footprint in its own mip chain (box; or by another method, IMAGE_FILTER: image_filters.glsl).
// Oracle: sampleImageReference (host/reference/reference_render.h).
#ifndef RAYTEX_KIND_IMAGE_GLSL
#define RAYTEX_KIND_IMAGE_GLSL

// The lookups of element `index` of BINDING_IMAGES. Lavapipe cannot index a sampler array with
// a variable, so IMAGE_SWITCH picks the element by constant indices, its cases past IMAGE_COUNT
// compiled out (one image: no switch), and applies LOOKUP(images[i]) to it. The only place that
// names `images`: the filters are written once for every image.
#define IMAGE_CASE(i, LOOKUP) \
  case i:                     \
    if (uint(i) < IMAGE_COUNT) return LOOKUP(images[i]); \
    break;
#define IMAGE_SWITCH(LOOKUP)                                                                          \
  if (IMAGE_COUNT <= 1u) return LOOKUP(images[0]);                                                    \
  switch (int(index)) {                                                                               \
    IMAGE_CASE(0, LOOKUP) IMAGE_CASE(1, LOOKUP) IMAGE_CASE(2, LOOKUP) IMAGE_CASE(3, LOOKUP)           \
    IMAGE_CASE(4, LOOKUP) IMAGE_CASE(5, LOOKUP) IMAGE_CASE(6, LOOKUP) IMAGE_CASE(7, LOOKUP)           \
    IMAGE_CASE(8, LOOKUP) IMAGE_CASE(9, LOOKUP) IMAGE_CASE(10, LOOKUP) IMAGE_CASE(11, LOOKUP)         \
    IMAGE_CASE(12, LOOKUP) IMAGE_CASE(13, LOOKUP) IMAGE_CASE(14, LOOKUP) IMAGE_CASE(15, LOOKUP)       \
    default:                                                                                          \
      break;                                                                                          \
  }                                                                                                   \
  return vec4(0.0);

// At st (REPEAT), mip level lod, filtered by the sampler.
#define IMAGE_LOD_LOOKUP(image) textureLod(image, st, lod)
vec4 sampleImage(uint index, vec2 st, float lod) { IMAGE_SWITCH(IMAGE_LOD_LOOKUP) }

#ifdef RAYTEX_FILTER_BOX
// Texel `texel` of mip level `level` (texelFetch: no filtering, no wrap).
#define IMAGE_TEXEL_LOOKUP(image) texelFetch(image, texel, level)
vec4 fetchImage(uint index, ivec2 texel, int level) { IMAGE_SWITCH(IMAGE_TEXEL_LOOKUP) }
#endif

// An image texture as the host packed it (Material.imageIndex, imageSize): its element of
// BINDING_IMAGES, its size in texels and mip levels, and which axes do not wrap.
struct ImageInfo {
  uint index;
  vec2 size;
  float levels;
  bool clampS;  // wrap = clamp
  bool clampT;  // wrap = clamp, or a sphere (its poles do not wrap into each other)
};

ImageInfo imageInfo(Material m, TexCoord tc) {
  ImageInfo im;
  im.index = m.imageIndex & 0xFFu;
  im.levels = float((m.imageIndex >> 8) & 0xFFu);
  im.size = vec2(float(m.imageSize & 0xFFFFu), float(m.imageSize >> 16));
  im.clampS = (m.imageIndex & IMAGE_WRAP_CLAMP) != 0u;
  im.clampT = im.clampS || tc.clampV;
  return im;
}

// The lookup coordinate: tc.image, column and row with row 0 the image's top, oriented by the
// mapping (docs/textures.md, "Image orientation"). wrap = clamp takes the unwrapped lookup,
// imageTile + image, clamped to [0, 1]: the image once, its edge texels extended beyond (the
// host packs a clamped image's offset whole, not reduced: packPlane).
vec2 imageCoord(ImageInfo im, TexCoord tc) {
  return im.clampS ? clamp(tc.imageTile + tc.image, 0.0, 1.0) : tc.image;
}

// st kept half a texel of a level `texels` in size inside the image along the axes that do
// not wrap (the sampler REPEATs): CLAMP_TO_EDGE, and no blend of the sphere's two poles.
vec2 clampToImage(ImageInfo im, vec2 st, vec2 texels) {
  vec2 inset = mix(vec2(-1.0e30), 0.5 / texels, bvec2(im.clampS, im.clampT));
  return clamp(st, inset, 1.0 - inset);
}

vec3 imagePoint(Material m, TexCoord tc) {
  ImageInfo im = imageInfo(m, tc);
  return sampleImage(im.index, clampToImage(im, imageCoord(im, tc), im.size), 0.0).rgb;
}

#ifdef RAYTEX_FILTER_BOX
// FILTER_BOX's default (IMAGE_FILTER_ANISOTROPIC; docs/textures.md, "Image filtering"): trilinear lookups in the image's mip chain
// (linear-light box averages built on the host) over the sample's footprint, the Jacobian
// J = [dst/dx dst/dy] in texels. J's ellipse is split along its major axis into probes, each
// at the level of the longer of the minor axis and the probe spacing (anisotropic filtering
// in the shader: lavapipe's sampler anisotropy returns wrong texels in this compute kernel).
// The derivatives are analytic, so the sphere's u seam gets no wrong level (no line of average
// colour; docs/textures.md, "Filtering image textures").
// At most IMAGE_MAX_PROBES probes on planes (beyond that the footprint is blurred along its
// minor axis, as hardware anisotropic filtering does); on spheres IMAGE_SPHERE_PROBES, since
// the map's anisotropy grows as 1/sin(colatitude) near the poles (33 at 1.7 degrees).
const float IMAGE_MAX_PROBES = 8.0;
const float IMAGE_SPHERE_PROBES = 32.0;
// The level is log2(width) - log2(3)/2: a mip texel (box of 2^l texels) under bilinear
// filtering (tent of half-width 2^l) has variance 4^l/4, a box of the footprint's width w
// has w^2/12; the bias makes the two equal (and with probes, the whole filter's variance
// along the major axis equals the footprint's box).
const float IMAGE_LOD_BIAS = -0.79248125;

// The footprint's Jacobian in level-0 texels: the steps of the lookup coordinate for one sample
// step in x and in y. Near a sphere's poles du grows without bound, but no footprint covers more
// than every u.
void imageSteps(ImageInfo im, TexCoord tc, Footprint fp, out vec2 dx, out vec2 dy) {
  vec2 dstdx = fp.dimagedx, dstdy = fp.dimagedy;
  if (tc.clampV) {
    dstdx.x = clamp(dstdx.x, -1.0, 1.0);
    dstdy.x = clamp(dstdy.x, -1.0, 1.0);
  }
  dx = dstdx * im.size;
  dy = dstdy * im.size;
}

vec3 imageAnisotropic(Material m, TexCoord tc, Footprint fp) {
  ImageInfo im = imageInfo(m, tc);
  vec2 st = imageCoord(im, tc);
  vec2 size = im.size;
  float maxLevel = im.levels - 1.0;
  float k = 1.0;         // probes
  vec2 step = vec2(0.0);  // st from one probe to the next
  float width2;           // squared width of each probe's footprint, in level-0 texels
  if (tc.clampV && tc.solid.x == 0.5 && tc.solid.z == 0.5) {
    // The exact pole of a sphere (n.x = n.z = 0, where the mapping sets u = 0.5): the
    // mapping's derivatives are 0/0 (they come out 0), but the footprint is a disc around the
    // pole: every u, and v within half a sample step of it, |dn| / 2pi (solid = (n + 1) / 2,
    // so dn = 2 ds). Probes all around the circle, in the middle of that band and as wide as
    // it: an equirectangular image's rows near a pole all picture the pole's surroundings and
    // change slowly along u.
    float band = min(max(length(fp.dsdx), length(fp.dsdy)) / float(TEXTURE_PI), 1.0);
    st.y = st.y < 0.5 ? 0.5 * band : 1.0 - 0.5 * band;
    k = IMAGE_SPHERE_PROBES;
    step = vec2(1.0 / k, 0.0);
    width2 = band * band * size.y * size.y;
  } else {
    vec2 dx, dy;
    imageSteps(im, tc, fp, dx, dy);
    // Principal axes of the footprint: the eigenvalues of J J^T, J = [dx dy], are the squared
    // semi-axes of its ellipse (the lengths of dx and dy overstate the minor axis when they
    // are skewed, as on the sphere away from the equator).
    float a = dx.x * dx.x + dy.x * dy.x, b = dx.x * dx.y + dy.x * dy.y, c = dx.y * dx.y + dy.y * dy.y;
    if (!(a + c < 1.0e30)) {  // non-finite or huge (a differential ray parallel to the surface)
      if (tc.clampV) st.y = 0.5;
#ifdef RAYTEX_AOV
      keepLodPass(maxLevel);
#endif
      return sampleImage(im.index, clampToImage(im, st, max(floor(size * exp2(-maxLevel)), 1.0)), maxLevel).rgb;
    }
    float dev = sqrt(0.25 * (a - c) * (a - c) + b * b);
    float major2 = 0.5 * (a + c) + dev, minor2 = max(0.5 * (a + c) - dev, 0.0);
    // Probes only where the footprint is longer than a texel: under magnification one
    // bilinear lookup at level 0 is exactly the point kernel's.
    if (major2 > 1.0) k = clamp(ceil(sqrt(major2 / max(minor2, 1.0e-30))), 1.0, tc.clampV ? IMAGE_SPHERE_PROBES : IMAGE_MAX_PROBES);
    width2 = max(minor2, major2 / (k * k));
    // The major axis: an eigenvector of J J^T, in the form without cancellation.
    vec2 axis = a >= c ? vec2(0.5 * (a - c) + dev, b) : vec2(b, 0.5 * (c - a) + dev);
    axis = dot(axis, axis) > 0.0 ? normalize(axis) : vec2(1.0, 0.0);
    step = axis * sqrt(major2) / (size * k);
  }
  float lod = clamp(0.5 * log2(max(width2, 1.0e-30)) + IMAGE_LOD_BIAS, 0.0, maxLevel);
#ifdef RAYTEX_AOV
  keepLodPass(lod);
#endif
  // Along the axes that do not wrap st stays half a texel of the coarser of the two levels
  // blended inside the image, so no level blends the two poles' rows or wraps a clamped edge.
  vec2 texels = vec2(max(ivec2(size) >> int(ceil(lod)), ivec2(1)));
  vec3 sum = vec3(0.0);
  for (float i = 0.5 - 0.5 * k; i < 0.5 * k; i += 1.0)
    sum += sampleImage(im.index, clampToImage(im, st + i * step, texels), lod).rgb;
  return sum / k;
}

#include "image_filters.glsl"

// The box kernel's image lookup: the method IMAGE_FILTER selects (a constant: the others
// compile out).
vec3 imageBox(Material m, TexCoord tc, Footprint fp) {
  if (IMAGE_FILTER == IMAGE_FILTER_BILINEAR) return imagePoint(m, tc);
  if (IMAGE_FILTER == IMAGE_FILTER_TRILINEAR) return imageTrilinear(m, tc, fp);
  if (IMAGE_FILTER == IMAGE_FILTER_EWA) return imageEwa(m, tc, fp);
  if (IMAGE_FILTER == IMAGE_FILTER_STOCHASTIC) return imageStochastic(m, tc, fp);
  return imageAnisotropic(m, tc, fp);
}
#endif  // RAYTEX_FILTER_BOX

#endif  // RAYTEX_KIND_IMAGE_GLSL
