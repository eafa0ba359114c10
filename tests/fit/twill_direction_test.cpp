// The direction of a weave's lines on the bias (core/fit/twill_direction.h), on drawn stripes.
#include <gtest/gtest.h>

#include <cmath>

#include "twill_direction.h"

namespace woven {
namespace {

// Stripes of 9 pixels whose crests run at `lineDegrees` from x toward y (down), with threads along
// both axes (3 and 4 pixels) stronger than them, as a twill's lines beside its threads.
Image stripes(double lineDegrees) {
    Image image;
    image.width = image.height = 128;
    const double a = (lineDegrees + 90.0) * M_PI / 180.0;  // the stripes' wave vector
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x) {
            const double v = 0.5 + 0.1 * std::sin(2.0 * M_PI * (std::cos(a) * x + std::sin(a) * y) / 9.0) +
                             0.2 * std::sin(2.0 * M_PI * x / 3.0) + 0.2 * std::sin(2.0 * M_PI * y / 4.0);
            image.pixels.push_back(glm::vec3(float(v)));
        }
    return image;
}

TEST(TwillDirection, LinesOfDrawnStripes) {
    for (const double degrees : {-60.0, -25.0, 30.0, 64.0}) EXPECT_NEAR(twillLineDegrees(stripes(degrees)), degrees, 1.5) << degrees;
}

}  // namespace
}  // namespace woven
