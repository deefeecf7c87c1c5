// The scene built into the kernel (SPEC_BAKED): its spheres, planes, lights and materials as
// specialisation constants, laid out word for word as in their uniform blocks (BAKED_*_WORD).
// A kernel specialised to a scene's values, not only its counts, folds them into its code:
// the default scene's kernel went from 286 to 189 x86 instructions per pixel
// (bench/instructions.sh), and its material is picked with selects among constants instead of
// gathered per lane. Included by trace.comp.glsl after common.h.

// Word 10 t + d is constant_id SPEC_BAKED_WORDS + 10 t + d, named bakedWord<t>_<d>.
#define BAKED_WORD(t, d) layout(constant_id = SPEC_BAKED_WORDS + 10 * t + d) const uint bakedWord##t##_##d = 0u;
#define BAKED_WORDS_10(t)                                                                 \
  BAKED_WORD(t, 0) BAKED_WORD(t, 1) BAKED_WORD(t, 2) BAKED_WORD(t, 3) BAKED_WORD(t, 4)    \
  BAKED_WORD(t, 5) BAKED_WORD(t, 6) BAKED_WORD(t, 7) BAKED_WORD(t, 8) BAKED_WORD(t, 9)
#define BAKED_LIST_10(t)                                                                  \
  bakedWord##t##_0, bakedWord##t##_1, bakedWord##t##_2, bakedWord##t##_3, bakedWord##t##_4, \
  bakedWord##t##_5, bakedWord##t##_6, bakedWord##t##_7, bakedWord##t##_8, bakedWord##t##_9

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

// (Not const: GLSL allows no const array initialised from specialisation constants. After
// specialisation the driver sees constants stored to a private array and read at constant
// indices, and folds them.)
uint bakedWords[BAKED_WORD_COUNT] = uint[BAKED_WORD_COUNT](
    BAKED_LIST_10(0),
    BAKED_LIST_10(1),
    BAKED_LIST_10(2),
    BAKED_LIST_10(3),
    BAKED_LIST_10(4),
    BAKED_LIST_10(5),
    BAKED_LIST_10(6),
    BAKED_LIST_10(7),
    BAKED_LIST_10(8),
    BAKED_LIST_10(9),
    BAKED_LIST_10(10),
    BAKED_LIST_10(11),
    BAKED_LIST_10(12),
    BAKED_LIST_10(13),
    BAKED_LIST_10(14),
    BAKED_LIST_10(15),
    BAKED_LIST_10(16),
    BAKED_LIST_10(17),
    BAKED_LIST_10(18),
    BAKED_LIST_10(19),
    BAKED_LIST_10(20),
    BAKED_LIST_10(21),
    BAKED_LIST_10(22),
    BAKED_LIST_10(23),
    BAKED_LIST_10(24),
    BAKED_LIST_10(25),
    BAKED_LIST_10(26),
    BAKED_LIST_10(27),
    BAKED_LIST_10(28),
    BAKED_LIST_10(29),
    BAKED_LIST_10(30),
    BAKED_LIST_10(31),
    BAKED_LIST_10(32),
    BAKED_LIST_10(33),
    BAKED_LIST_10(34),
    BAKED_LIST_10(35),
    BAKED_LIST_10(36),
    BAKED_LIST_10(37),
    BAKED_LIST_10(38));

float bakedFloat(uint i) { return uintBitsToFloat(bakedWords[i]); }
vec4 bakedVec4(uint i) {
  return vec4(bakedFloat(i), bakedFloat(i + 1u), bakedFloat(i + 2u), bakedFloat(i + 3u));
}

// Item k (a constant after unrolling; clamped so that the unbaked kernel's loops stay in range).
Sphere bakedSphere(uint k) {
  uint w = BAKED_SPHERE_WORD + min(k, MAX_BAKED_SPHERES - 1u) * 8u;
  return Sphere(bakedVec4(w), bakedWords[w + 4u], 0u, 0u, 0u);
}
Plane bakedPlane(uint k) {
  uint w = BAKED_PLANE_WORD + min(k, MAX_BAKED_PLANES - 1u) * 24u;
  return Plane(bakedVec4(w), bakedVec4(w + 4u), bakedVec4(w + 8u), bakedVec4(w + 12u), bakedVec4(w + 16u),
               bakedWords[w + 20u], 0u, 0u, 0u);
}
Light bakedLight(uint k) {
  uint w = BAKED_LIGHT_WORD + min(k, MAX_BAKED_LIGHTS - 1u) * 8u;
  return Light(bakedVec4(w), bakedVec4(w + 4u));
}
Material bakedMaterial(uint k) {
  uint w = BAKED_MATERIAL_WORD + min(k, MAX_BAKED_MATERIALS - 1u) * 28u;
  return Material(bakedVec4(w), bakedVec4(w + 4u), bakedVec4(w + 8u), bakedVec4(w + 12u), bakedVec4(w + 16u),
                  bakedVec4(w + 20u), bakedWords[w + 24u], bakedWords[w + 25u], bakedWords[w + 26u], 0u);
}
