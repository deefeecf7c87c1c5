// The scene built into the kernel (SPEC_BAKED): its spheres, planes, lights and materials as
// specialisation constants, each item laid out word for word as its uniform block's struct
// (common.h, BAKED_*_WORD and BAKED_*_STRIDE). A kernel specialised to a scene's values, not
// only its counts, folds them into its code, and picks its material with selects among
// constants instead of gathering it per lane (docs/performance.md, "Where the kernel's time
// goes"). Included by trace.comp.glsl after common.h.
//
// The items are built from the constants by name, not read from an array: lavapipe processes
// an array initialised from them (uint[](...)) in every variant, baked or not, and that
// triples its pipeline creation (docs/performance.md, "Specialised against unspecialised
// pipelines").

// Word 10 t + d is constant_id SPEC_BAKED_WORDS + 10 t + d, named bakedWord<t>_<d>.
#define BAKED_WORD(t, d) layout(constant_id = SPEC_BAKED_WORDS + 10 * t + d) const uint bakedWord##t##_##d = 0u;
#define BAKED_WORDS_10(t)                                                                 \
  BAKED_WORD(t, 0) BAKED_WORD(t, 1) BAKED_WORD(t, 2) BAKED_WORD(t, 3) BAKED_WORD(t, 4)    \
  BAKED_WORD(t, 5) BAKED_WORD(t, 6) BAKED_WORD(t, 7) BAKED_WORD(t, 8) BAKED_WORD(t, 9)

BAKED_WORDS_10(0)
BAKED_WORDS_10(1)
BAKED_WORDS_10(2)
BAKED_WORDS_10(3)
BAKED_WORDS_10(4)
BAKED_WORDS_10(5)
BAKED_WORDS_10(6)
BAKED_WORDS_10(7)
BAKED_WORDS_10(8)
BAKED_WORDS_10(9)
BAKED_WORDS_10(10)
BAKED_WORDS_10(11)
BAKED_WORDS_10(12)
BAKED_WORDS_10(13)
BAKED_WORDS_10(14)
BAKED_WORDS_10(15)
BAKED_WORDS_10(16)
BAKED_WORDS_10(17)
BAKED_WORDS_10(18)
BAKED_WORDS_10(19)
BAKED_WORDS_10(20)
BAKED_WORDS_10(21)
BAKED_WORDS_10(22)
BAKED_WORDS_10(23)
BAKED_WORDS_10(24)
BAKED_WORDS_10(25)
BAKED_WORDS_10(26)
BAKED_WORDS_10(27)
BAKED_WORDS_10(28)
BAKED_WORDS_10(29)
BAKED_WORDS_10(30)
BAKED_WORDS_10(31)
BAKED_WORDS_10(32)
BAKED_WORDS_10(33)
BAKED_WORDS_10(34)
BAKED_WORDS_10(35)
BAKED_WORDS_10(36)
BAKED_WORDS_10(37)
BAKED_WORDS_10(38)
BAKED_WORDS_10(39)
BAKED_WORDS_10(40)
BAKED_WORDS_10(41)
BAKED_WORDS_10(42)
BAKED_WORDS_10(43)
BAKED_WORDS_10(44)
BAKED_WORDS_10(45)
BAKED_WORDS_10(46)
BAKED_WORDS_10(47)
BAKED_WORDS_10(48)
BAKED_WORDS_10(49)
BAKED_WORDS_10(50)
BAKED_WORDS_10(51)

// Words d..d+3 of ten t as a vec4, and words 8, 9 of ten t with words 0, 1 of ten u.
#define BAKED_VEC4(t, d0, d1, d2, d3)                                                                      \
  vec4(uintBitsToFloat(bakedWord##t##_##d0), uintBitsToFloat(bakedWord##t##_##d1),                      \
       uintBitsToFloat(bakedWord##t##_##d2), uintBitsToFloat(bakedWord##t##_##d3))
#define BAKED_VEC4_ACROSS(t, u)                                                                            \
  vec4(uintBitsToFloat(bakedWord##t##_8), uintBitsToFloat(bakedWord##t##_9),                             \
       uintBitsToFloat(bakedWord##u##_0), uintBitsToFloat(bakedWord##u##_1))

// The items, by the tens their words start at (BAKED_*_WORD / 10 + k * BAKED_*_STRIDE / 10).
// Sphere: centerRadius, texRotation, solidOffset, material, uOffset, vOffset, clampV. Plane:
// normalDistance, tangentScale, binormal, uvOffset, solidOffset, texRotation, imageRight,
// imageDown, material. Light: position, color. Material: ambient, diffuse, specular, color1,
// color2, params, textureKind, octaves, imageIndex, imageSize.
#define BAKED_SPHERE(t, u)                                                                                 \
  Sphere(BAKED_VEC4(t, 0, 1, 2, 3), BAKED_VEC4(t, 4, 5, 6, 7), BAKED_VEC4_ACROSS(t, u), bakedWord##u##_2,  \
         uintBitsToFloat(bakedWord##u##_3), uintBitsToFloat(bakedWord##u##_4), bakedWord##u##_5)
#define BAKED_PLANE(t, u, v, w)                                                                            \
  Plane(BAKED_VEC4(t, 0, 1, 2, 3), BAKED_VEC4(t, 4, 5, 6, 7), BAKED_VEC4_ACROSS(t, u),                    \
        BAKED_VEC4(u, 2, 3, 4, 5), BAKED_VEC4(u, 6, 7, 8, 9), BAKED_VEC4(v, 0, 1, 2, 3),                  \
        BAKED_VEC4(v, 4, 5, 6, 7), BAKED_VEC4_ACROSS(v, w), bakedWord##w##_2, 0u, 0u, 0u)
#define BAKED_LIGHT(t) Light(BAKED_VEC4(t, 0, 1, 2, 3), BAKED_VEC4(t, 4, 5, 6, 7))
#define BAKED_MATERIAL(t, u, v)                                                                            \
  Material(BAKED_VEC4(t, 0, 1, 2, 3), BAKED_VEC4(t, 4, 5, 6, 7), BAKED_VEC4_ACROSS(t, u),                 \
           BAKED_VEC4(u, 2, 3, 4, 5), BAKED_VEC4(u, 6, 7, 8, 9), BAKED_VEC4(v, 0, 1, 2, 3),               \
           bakedWord##v##_4, bakedWord##v##_5, bakedWord##v##_6, bakedWord##v##_7)

// Slot k of each kind (k is a constant once the driver unrolls the caller's loop; slots past
// MAX_BAKED_* give the last one).
Sphere bakedSphere(uint k) {
  return k == 0u ? BAKED_SPHERE(0, 1) : k == 1u ? BAKED_SPHERE(2, 3) : k == 2u ? BAKED_SPHERE(4, 5) : BAKED_SPHERE(6, 7);
}
Plane bakedPlane(uint k) {
  return k == 0u ? BAKED_PLANE(8, 9, 10, 11) : k == 1u ? BAKED_PLANE(12, 13, 14, 15)
       : k == 2u ? BAKED_PLANE(16, 17, 18, 19) : BAKED_PLANE(20, 21, 22, 23);
}
Light bakedLight(uint k) {
  return k == 0u ? BAKED_LIGHT(24) : k == 1u ? BAKED_LIGHT(25) : k == 2u ? BAKED_LIGHT(26) : BAKED_LIGHT(27);
}
Material bakedMaterial(uint k) {
  return k == 0u ? BAKED_MATERIAL(28, 29, 30) : k == 1u ? BAKED_MATERIAL(31, 32, 33)
       : k == 2u ? BAKED_MATERIAL(34, 35, 36) : k == 3u ? BAKED_MATERIAL(37, 38, 39)
       : k == 4u ? BAKED_MATERIAL(40, 41, 42) : k == 5u ? BAKED_MATERIAL(43, 44, 45)
       : k == 6u ? BAKED_MATERIAL(46, 47, 48) : BAKED_MATERIAL(49, 50, 51);
}
