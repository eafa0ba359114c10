#pragma once
// Whether a shot can be fitted at all: its camera sees its target, and light reaches what it
// sees. A target hidden behind another surface, or one that no light reaches (a lamp of
// intensity 0), makes renders that no material changes, and a fit of them would write some
// material as if it had found one.
#include <atomic>

#include "shot.h"
#include "shot_render.h"

namespace woven {

// Below this share of the frame the target is not taken as seen, or as lit.
constexpr double kLeastTargetShare = 0.01;

// Throws FitError naming the shot's file where the part of the target that the camera sees lit
// fills less than kLeastTargetShare of the frame, saying whether it is hidden or unlit. Two or
// three renders of one sample a pixel (a grey woven target, whose yarns pass light so that a
// backlit shot counts, against a black one; then a white unlit one), which no deadline cuts short.
// Judges nothing where `cancel` cut them.
void checkTargetSeenAndLit(const Shot& shot, FitRenderSettings settings, const std::atomic<bool>& cancel);

}  // namespace woven
