// Yardstick 1, the write-only floor: stores one constant colour per pixel (the course scene's
// background, so the image equals raytex's render of the scene with its objects removed). The
// cost of launching 8x8 workgroups over the image and writing an rgba32f pixel: no kernel that
// writes the image can be faster. Compiled at build time (CMakeLists.txt, add_spirv).
#version 460

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0, rgba32f) uniform writeonly image2D outputImage;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(outputImage)))) return;
  imageStore(outputImage, pixel, vec4(0.05, 0.05, 0.08, 1.0));
}
