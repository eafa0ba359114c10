#include "drawdown_image.h"

#include <stdexcept>
#include <string>

namespace woven {

Image drawdownImage(const WeavePattern& weave, const std::vector<glm::vec3>& warpColors,
                    const std::vector<glm::vec3>& weftColors, int columns, int rows, int cellPixels) {
    if (columns < 1 || rows < 1 || cellPixels < 1) throw std::invalid_argument("drawdown image: sizes must be positive");
    if (warpColors.empty() || weftColors.empty()) throw std::invalid_argument("drawdown image: no thread colours");
    const size_t pixels = size_t(columns) * size_t(rows) * size_t(cellPixels) * size_t(cellPixels);
    if (pixels > kMaxDrawdownPixels)
        throw std::invalid_argument("drawdown image: " + std::to_string(pixels) + " pixels is more than the limit of " +
                                    std::to_string(kMaxDrawdownPixels));
    Image image;
    image.width = columns * cellPixels;
    image.height = rows * cellPixels;
    image.pixels.resize(pixels);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const int U = x / cellPixels, V = y / cellPixels;
            image.at(x, y) = weave.top(U, V) == YarnType::Warp ? warpColors[size_t(U) % warpColors.size()]
                                                                : weftColors[size_t(V) % weftColors.size()];
        }
    return image;
}

}  // namespace woven
