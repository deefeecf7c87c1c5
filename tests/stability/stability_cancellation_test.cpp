// Stability: cancellation in the ray-sphere discriminant. A small sphere
// far away (r/D down to 1e-4), where the naive b^2 - 4ac test gets many rays wrong.
#include "reference.h"
#include "reference_render.h"
#include "texture.h"
#include "texture_kinds.h"

#include "support/stability_fixture.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace {

// --- 5. small far sphere -----------------------------------------------------

// r = 0.1 at D = 1, 10, 100, 1000 (r/D = 1e-1 .. 1e-4), the field of view scaled so the
// disc is ~24 px wide (443 pixels, 86 of them within 5 % of r of the silhouette). The
// naive b^2 - 4ac test gets many such rays wrong at a relative error of 1e-4; the kernel's
// form must get none wrong. Pixels whose ray passes within kMargin = 1e-5 r
// of the silhouette are skipped: the kernel's float error in the ray's distance from the
// centre is ~2e-7 r at D = 1000 (direction error ~6e-8 of its 1e-4 lateral part times D,
// and ulp(D)^2 / r^2 from the cancellation along the ray). Measured: none skipped, none
// wrong; the closest checked ray passed 1.8e-4 r from the silhouette.
TEST_F(StabilityTest, SmallFarSphereHasNoWrongPixels) {
  const int w = 96, h = 72;
  const double kMargin = 1e-5;
  for (double distance : {1.0, 10.0, 100.0, 1000.0}) {
    SCOPED_TRACE("D = " + fmtG(distance));
    const double r = 0.1;
    Scene scene = smallSphereScene(r, distance);
    std::vector<float> coords = render(scene, w, h, OUTPUT_COORDS);
    std::vector<ReferenceHit> ref = referenceHits(scene, w, h);
    int wrong = 0, skipped = 0, hits = 0, nearEdge = 0;
    double closest = 1e30;  // how close to the silhouette the checked rays came
    for (size_t i = 0; i < ref.size(); ++i) {
      hits += ref[i].kind == HIT_SPHERE;
      if (ref[i].edgeMargin < kMargin) {
        ++skipped;
        continue;
      }
      closest = std::min(closest, ref[i].edgeMargin);
      nearEdge += ref[i].edgeMargin < 0.05;
      if (gpuKind(coords, i) != ref[i].kind) ++wrong;
    }
    std::cout << "[small far sphere] r/D " << fmtG(r / distance) << ": " << hits << " disc pixels, " << wrong
              << " wrong, " << skipped << " skipped (margin < " << kMargin << "), " << nearEdge
              << " within 5 % of r of the silhouette, closest " << fmtG(closest) << "\n";
    RecordProperty("skipped_r_over_D" + fmtG(r / distance), skipped);
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(hits, 300);
    EXPECT_LE(skipped, hits / 100);
  }
}

}  // namespace
