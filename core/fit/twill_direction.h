#pragma once
// Which way a photo's weave runs on the bias: the direction of its twill (or satin) lines, as a
// person judges it by eye, for comparing a fitted render with its photo (woven fit --report).
// The lines are perpendicular to the spectrum's strongest peak off the thread directions.
#include "image.h"

namespace woven {

// Peaks closer than this to either image axis are the threads', not the lines'.
constexpr double kOffAxisDegrees = 8.0;

// The angle of the lines, degrees in (-90, 90] from the image's x axis toward its y axis (down),
// from the strongest local peak of the luminance spectrum more than kOffAxisDegrees from both
// axes and at least 3 cycles across the image; NaN where there is none.
double twillLineDegrees(const Image& image);

}  // namespace woven
