// The box kernel's other image filter methods (IMAGE_FILTER; docs/textures.md, "Image filter
// methods"), for comparison with the default anisotropic probes (image.glsl): one trilinear
// lookup at the level of the footprint's major axis, as a GPU sampler without anisotropy does;
// an elliptical weighted average (EWA, Heckbert 1989, in the form pbrt-v4 uses: a Gaussian over
// the texels inside the footprint's ellipse at the two levels around its minor axis, anisotropy
// limited to EWA_MAX_ANISOTROPY), with at most EWA_MAX_TEXELS texels a level; and stochastic
// filtering (Pharr et al., "Filtering after Shading with Stochastic Texture Filtering", 2024):
// one texel per sample, drawn with the probability of its weight in the footprint's box filter
// over level 0's bilinear reconstruction, so that the pixel's samples average the filter.
// Bilinear without mip levels is imagePoint.
//
// Needs (from image.glsl): ImageInfo, imageInfo, imageCoord, imageSteps, clampToImage,
// sampleImage, fetchImage, IMAGE_FILTER; imageSeed, set per sample by the kernel.
#ifndef RAYTEX_KIND_IMAGE_FILTERS_GLSL
#define RAYTEX_KIND_IMAGE_FILTERS_GLSL

// The seed of the sample being shaded (IMAGE_FILTER_STOCHASTIC: set by albedoAt from its film
// position, so each pixel and sample draws its own texel; read only then).
uint imageSeed;

// One trilinear lookup, at the level where the longer of the two sample steps spans one texel.
vec3 imageTrilinear(Material m, TexCoord tc, Footprint fp) {
  ImageInfo im = imageInfo(m, tc);
  vec2 dx, dy;
  imageSteps(im, tc, fp, dx, dy);
  float width2 = max(dot(dx, dx), dot(dy, dy));
  float maxLevel = im.levels - 1.0;
  float lod = width2 < 1.0e30 ? clamp(0.5 * log2(max(width2, 1.0e-30)), 0.0, maxLevel) : maxLevel;
  vec2 texels = vec2(max(ivec2(im.size) >> int(ceil(lod)), ivec2(1)));
  return sampleImage(im.index, clampToImage(im, imageCoord(im, tc), texels), lod).rgb;
}

// Texel `texel` of level `level` (`size` texels), wrapped or clamped as the image's axes are.
vec4 fetchWrapped(ImageInfo im, ivec2 texel, int level, ivec2 size) {
  ivec2 wrapped = ((texel % size) + size) % size;
  ivec2 clamped = clamp(texel, ivec2(0), size - 1);
  return fetchImage(im.index, ivec2(im.clampS ? clamped.x : wrapped.x, im.clampT ? clamped.y : wrapped.y), level);
}

// Integer hash (a xorshift-multiply mix) and uniform numbers in [0, 1) drawn from imageSeed.
uint imageHash(uint x) {
  x ^= x >> 16u;
  x *= 0x7feb352du;
  x ^= x >> 15u;
  x *= 0x846ca68bu;
  return x ^ (x >> 16u);
}
float imageRandom() {
  imageSeed = imageHash(imageSeed);
  return float(imageSeed >> 8u) * (1.0 / 16777216.0);
}

// One texel: a point drawn uniformly in the footprint's parallelogram, then one of its four
// bilinear neighbours at level 0 with its bilinear weight as the probability.
vec3 imageStochastic(Material m, TexCoord tc, Footprint fp) {
  ImageInfo im = imageInfo(m, tc);
  vec2 dx, dy;
  imageSteps(im, tc, fp, dx, dy);
  if (!(dot(dx, dx) + dot(dy, dy) < 1.0e12)) dx = dy = vec2(0.0);  // no finite footprint
  vec2 offset = (imageRandom() - 0.5) * dx + (imageRandom() - 0.5) * dy;
  vec2 p = imageCoord(im, tc) * im.size + offset - 0.5;
  p = mix(p - im.size * floor(p / im.size), clamp(p, vec2(-1.0), im.size), bvec2(im.clampS, im.clampT));
  vec2 base = floor(p);
  vec2 pick = step(vec2(imageRandom(), imageRandom()), p - base);
  return fetchWrapped(im, ivec2(base + pick), 0, ivec2(im.size)).rgb;
}

// EWA's anisotropy limit (the minor axis is lengthened to 1/8 of the major) and its Gaussian's
// falloff: weight exp(-alpha r^2) - exp(-alpha) at r^2 of the ellipse's own radius.
const float EWA_MAX_ANISOTROPY = 8.0;
const float EWA_ALPHA = 2.0;

// The footprint's ellipse at one level: the lookup point in that level's texel indices, the
// quadratic form A s^2 + B s t + C t^2 < 1 (with a texel's reconstruction filter added), and the
// box of texels it covers, in rows `width` wide, `count` texels (at most EWA_MAX_TEXELS).
struct EwaLevel {
  int level;
  ivec2 size;
  vec2 p;
  float a, b, c;
  ivec2 low;
  int width, count;
};

EwaLevel ewaLevel(ImageInfo im, vec2 st, vec2 major, vec2 minor, int level) {
  EwaLevel e;
  e.level = level;
  e.size = max(ivec2(im.size) >> level, ivec2(1));
  e.p = st * vec2(e.size) - 0.5;
  float scale = exp2(-float(level));
  vec2 d0 = major * scale, d1 = minor * scale;
  float a = d0.y * d0.y + d1.y * d1.y + 1.0, b = -2.0 * (d0.x * d0.y + d1.x * d1.y), c = d0.x * d0.x + d1.x * d1.x + 1.0;
  float f = a * c - 0.25 * b * b;
  e.a = a / f;
  e.b = b / f;
  e.c = c / f;
  float det = 4.0 * e.a * e.c - e.b * e.b;
  vec2 reach = min(sqrt(4.0 * vec2(e.c, e.a) / det), vec2(1.0e6));
  e.low = ivec2(ceil(e.p - reach));
  ivec2 high = ivec2(floor(e.p + reach));
  e.width = high.x - e.low.x + 1;
  e.count = e.width * (high.y - e.low.y + 1);
  return e;
}

// The Gaussian-weighted texels of one or two levels (fraction `blend` of the second), in one
// loop: lavapipe makes as many passes as the busiest lane of the SIMD group.
vec3 ewaSum(ImageInfo im, EwaLevel l0, EwaLevel l1, float blend) {
  int n0 = min(l0.count, int(EWA_MAX_TEXELS)), n1 = blend > 0.0 ? min(l1.count, int(EWA_MAX_TEXELS)) : 0;
  vec4 sum0 = vec4(0.0), sum1 = vec4(0.0);  // weighted colours, weights in w
  for (int i = 0; i < n0 + n1; ++i) {
    bool first = i < n0;
    EwaLevel e = first ? l0 : l1;
    int k = first ? i : i - n0;
    ivec2 texel = e.low + ivec2(k % e.width, k / e.width);
    vec2 d = vec2(texel) - e.p;
    float r2 = e.a * d.x * d.x + e.b * d.x * d.y + e.c * d.y * d.y;
    float w = r2 < 1.0 ? exp(-EWA_ALPHA * r2) - exp(-EWA_ALPHA) : 0.0;
    vec4 term = vec4(fetchWrapped(im, texel, e.level, e.size).rgb * w, w);
    if (first) sum0 += term;
    else sum1 += term;
  }
  vec3 c0 = sum0.w > 0.0 ? sum0.rgb / sum0.w : fetchWrapped(im, ivec2(round(l0.p)), l0.level, l0.size).rgb;
  vec3 c1 = sum1.w > 0.0 ? sum1.rgb / sum1.w : c0;
  return mix(c0, c1, blend);
}

vec3 imageEwa(Material m, TexCoord tc, Footprint fp) {
  ImageInfo im = imageInfo(m, tc);
  vec2 major, minor;
  imageSteps(im, tc, fp, major, minor);
  if (dot(minor, minor) > dot(major, major)) {
    vec2 t = major;
    major = minor;
    minor = t;
  }
  float majorLength = length(major), minorLength = length(minor);
  if (!(majorLength < 1.0e12) || minorLength == 0.0) return imagePoint(m, tc);
  if (minorLength * EWA_MAX_ANISOTROPY < majorLength) {
    minor *= majorLength / (minorLength * EWA_MAX_ANISOTROPY);
    minorLength = majorLength / EWA_MAX_ANISOTROPY;
  }
  // The level where the minor axis spans one texel, then coarser while the ellipse covers more
  // than EWA_MAX_TEXELS (one level alone then).
  int maxLevel = int(im.levels) - 1;
  float lod = max(log2(minorLength), 0.0);
  int level = min(int(floor(lod)), maxLevel);
  float blend = level < maxLevel ? lod - float(level) : 0.0;
  vec2 st = imageCoord(im, tc);
  EwaLevel l0 = ewaLevel(im, st, major, minor, level);
  int raise = min(int(ceil(0.5 * log2(float(l0.count) / float(EWA_MAX_TEXELS)))), maxLevel - level);
  if (raise > 0) {
    l0 = ewaLevel(im, st, major, minor, level + raise);
    blend = 0.0;
  }
  EwaLevel l1 = ewaLevel(im, st, major, minor, min(l0.level + 1, maxLevel));
  return ewaSum(im, l0, l1, blend);
}

#endif  // RAYTEX_KIND_IMAGE_FILTERS_GLSL
