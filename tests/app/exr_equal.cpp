// exr_equal A.exr B.exr: exits 0 when two frames hold the same radiance, sample counts,
// sample sums and render passes' sums bit for bit; otherwise says how they differ and exits 1. For the shell tests.
#include <cmath>
#include <iostream>

#include "frame_io.h"
#include "image_io.h"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: exr_equal A.exr B.exr\n";
        return 2;
    }
    try {
        const woven::ExrImage a = woven::readExr(argv[1]), b = woven::readExr(argv[2]);
        if (a.image.width != b.image.width || a.image.height != b.image.height) {
            std::cerr << "sizes differ: " << a.image.width << "x" << a.image.height << " and " << b.image.width << "x"
                      << b.image.height << "\n";
            return 1;
        }
        size_t differing = 0;
        double maxDifference = 0.0;
        for (size_t i = 0; i < a.image.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c)
                if (a.image.pixels[i][c] != b.image.pixels[i][c]) {
                    ++differing;
                    maxDifference = std::max(maxDifference, double(std::abs(a.image.pixels[i][c] - b.image.pixels[i][c])));
                }
        const bool same =
            differing == 0 && a.sampleCount == b.sampleCount && a.sampleSums == b.sampleSums && a.passSums == b.passSums;
        if (!same)
            std::cerr << argv[1] << " and " << argv[2] << " differ: " << differing << " channel values (largest difference "
                      << maxDifference << ")" << (a.sampleCount == b.sampleCount ? "" : ", sample counts")
                      << (a.sampleSums == b.sampleSums ? "" : ", sample sums")
                      << (a.passSums == b.passSums ? "" : ", render passes' sums") << "\n";
        return same ? 0 : 1;
    } catch (const std::exception& e) {
        std::cerr << "exr_equal: " << e.what() << "\n";
        return 2;
    }
}
