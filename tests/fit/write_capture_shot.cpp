// Writes a capture-rig shot (capture_rig.h) for a test outside C++, the window's Fit section
// (tests/preview/window_fit_xvfb.py): a 3/1 twill of 8 ends and 6 picks per cm in DIR/twill.json,
// its photo and swatch beside it. Prints the shot's path and the cloth's thread counts as JSON.
#include <cstdio>

#include "capture_rig.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s DIR\n", argv[0]);
        return 2;
    }
    woven::test::RigPhoto photo;
    photo.truth.pattern = {1, 3, 1};
    photo.truth.repeat = {800.0f, 600.0f};  // per metre: one UV unit of the swatch is a metre
    photo.truth.weft_color = {0.70f, 0.62f, 0.45f};
    photo.truth.warp_color = {0.10f, 0.16f, 0.42f};
    photo.spp = 16;
    const std::string shot = woven::test::writeCaptureShot(argv[1], "twill", photo);
    std::printf("{\"shot\": \"%s\", \"threads_per_cm\": [8, 6]}\n", shot.c_str());
    return 0;
}
