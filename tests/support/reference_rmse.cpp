#include "support/reference_rmse.h"

#include "image_metrics.h"

double rmseAgainstReference(const float* rgba, const ReferenceImage& ref, const std::vector<bool>* mask) {
  return rootMeanSquareError(rgbaFloatImage(rgba, ref.width, ref.height),
                             rgbaFloatImage(referenceToRgba(ref).data(), ref.width, ref.height), mask);
}
